# ctest `tests.mirror_sources`: every source file with logic has its test file where the tree mirrors it, or
# is on the commented list in tests/untested_sources.txt. Run with -DSOURCE_DIR=<repo root>.
#   core/src/X.cpp               -> tests/core/X_test.cpp        (core/src/engines/X.cpp -> tests/core/engines/)
#   scene/src/X.cpp              -> tests/scene/X_test.cpp
#   render/src/X.cpp             -> tests/render/X_test.cpp
#   engines/E/X.cpp              -> tests/engines/E/X_test.cpp   (engines/X.cpp -> tests/engines/X_test.cpp)
#   server/F/X.cpp               -> tests/F/X_test.cpp           (F: codec, app, http, cli, plot)
#   web/X.js                     -> tests/web/X.test.mjs
# A test may also be a CMake script (X_test.cmake) where the source is a program driven from outside.
file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR}
     ${SOURCE_DIR}/core/src/*.cpp ${SOURCE_DIR}/scene/src/*.cpp ${SOURCE_DIR}/render/src/*.cpp
     ${SOURCE_DIR}/engines/*.cpp ${SOURCE_DIR}/server/*.cpp ${SOURCE_DIR}/web/*.js)
list(FILTER sources EXCLUDE REGEX "^web/vendor/")

file(STRINGS ${SOURCE_DIR}/tests/untested_sources.txt listed REGEX "^[^#]")
set(exempt "")
foreach(line IN LISTS listed)
  string(REGEX REPLACE "[ \t].*$" "" path "${line}")
  if(NOT EXISTS ${SOURCE_DIR}/${path})
    message(SEND_ERROR "tests/untested_sources.txt lists ${path}, which is not there: take it off the list")
  endif()
  list(APPEND exempt ${path})
endforeach()

set(missing "")
foreach(src IN LISTS sources)
  get_filename_component(name ${src} NAME_WE)
  get_filename_component(dir ${src} DIRECTORY)
  if(src MATCHES "^web/")
    set(candidates tests/web/${name}.test.mjs)
  else()
    string(REGEX REPLACE "^(core|scene|render)/src" "tests/\\1" test_dir "${dir}")
    string(REGEX REPLACE "^engines" "tests/engines" test_dir "${test_dir}")
    string(REGEX REPLACE "^server/" "tests/" test_dir "${test_dir}")
    set(candidates ${test_dir}/${name}_test.cpp ${test_dir}/${name}_test.cmake)
  endif()
  set(found FALSE)
  foreach(c IN LISTS candidates)
    if(EXISTS ${SOURCE_DIR}/${c})
      set(found TRUE)
    endif()
  endforeach()
  list(FIND exempt ${src} at)
  if(found AND NOT at EQUAL -1)
    message(SEND_ERROR "${src} has a test file now: take it off tests/untested_sources.txt")
  elseif(NOT found AND at EQUAL -1)
    list(GET candidates 0 wanted)
    list(APPEND missing "${src} (wants ${wanted})")
  endif()
endforeach()

if(missing)
  list(JOIN missing "\n  " text)
  message(FATAL_ERROR "sources without a test file (add it, or list the source with a reason in "
                      "tests/untested_sources.txt):\n  ${text}")
endif()
