# How the test executables compile: at -O1, with one precompiled header they all share.
#
# Why: in a fresh build the test sources took over half of the compile time, and what they spent it on was
# gtest's, nlohmann-json's and Eigen's headers and -O3 optimising gtest and JSON template code, not their
# own logic. Measured on six tests/core files (user CPU, gcc 12): -O3 41.7 s, -O1 27.3 s, -O1 with the
# shared header 19.9 s, plus 6.8 s once for the header itself. The code under test (core, scene, the
# server libraries) keeps the build type's optimisation; only the test files' own code runs at -O1.
#
# softtune_test_compile(DIR) gives every executable defined in DIR and below both, reusing the header that
# softtune_test_pch compiles once (REUSE_FROM: same compiler, same flags; no header in it depends on a
# target's own definitions), and compiles it in unity batches (cmake/UnityBuild.cmake).

include(${CMAKE_CURRENT_LIST_DIR}/UnityBuild.cmake)

set(SOFTTUNE_TEST_OPTIMISATION -O1)

add_library(softtune_test_pch OBJECT ${CMAKE_CURRENT_LIST_DIR}/pch_anchor.cpp)
target_link_libraries(softtune_test_pch PRIVATE GTest::gtest nlohmann_json::nlohmann_json Eigen3::Eigen)
target_compile_options(softtune_test_pch PRIVATE ${SOFTTUNE_TEST_OPTIMISATION})
target_precompile_headers(softtune_test_pch PRIVATE <gtest/gtest.h> <nlohmann/json.hpp> <Eigen/Dense>)

function(softtune_test_compile dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    if(type STREQUAL "EXECUTABLE")
      target_compile_options(${t} PRIVATE ${SOFTTUNE_TEST_OPTIMISATION})
      target_precompile_headers(${t} REUSE_FROM softtune_test_pch)
      softtune_unity(${t})
      # The shared header's include paths: a test that does not link Eigen itself still finds what it holds.
      target_link_libraries(${t} PRIVATE GTest::gtest nlohmann_json::nlohmann_json Eigen3::Eigen)
    endif()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(d IN LISTS subdirs)
    softtune_test_compile(${d})
  endforeach()
endfunction()
