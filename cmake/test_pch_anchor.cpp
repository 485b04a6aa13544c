// The translation unit that compiles the tests' shared precompiled header (cmake/TestCompile.cmake).
