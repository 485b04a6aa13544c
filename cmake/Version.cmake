# The version, once: project(softtune VERSION ...) in CMakeLists.txt. softtune_version is a header-only
# target whose generated softtune/version.h holds it for `softtune --version` and GET /api/v1/health; the
# Debian package (cmake/Package.cmake) is named with the same number.
configure_file(${CMAKE_CURRENT_LIST_DIR}/version.h.in ${CMAKE_BINARY_DIR}/generated/softtune/version.h @ONLY)
add_library(softtune_version INTERFACE)
target_include_directories(softtune_version INTERFACE ${CMAKE_BINARY_DIR}/generated)
