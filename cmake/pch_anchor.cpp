// The empty translation unit a shared precompiled header compiles with (cmake/TestCompile.cmake,
// cmake/ServerCompile.cmake).
