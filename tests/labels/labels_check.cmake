# ctest tests.labels: every test in the build (BUILD_DIR) carries exactly one of the five labels
# (cmake/TestLabels.cmake), so `ctest -L unit` (scripts/test.sh --quick) and the others select every test once.
cmake_minimum_required(VERSION 3.25)

# tests_of(OUT ARGS...): the names `ctest -N ARGS` lists.
function(tests_of out)
  execute_process(COMMAND ${CMAKE_CTEST_COMMAND} -N ${ARGN} WORKING_DIRECTORY ${BUILD_DIR}
                  OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "ctest -N ${ARGN} failed (${rc})")
  endif()
  string(REGEX MATCHALL "Test +#[0-9]+: [^\n]+" lines "${text}")
  list(TRANSFORM lines REPLACE "^Test +#[0-9]+: " "")
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

tests_of(all)
list(LENGTH all total)
if(total LESS 2)
  message(FATAL_ERROR "only ${total} tests listed")
endif()
set(labelled "")
foreach(label unit integration browser real-engine memcheck)
  tests_of(some -L "^${label}$")
  list(LENGTH some n)
  message(STATUS "${label}: ${n}")
  list(APPEND labelled ${some})
endforeach()
# Every test in some list, and the lists' lengths add up to the total: so each test is in exactly one.
list(LENGTH labelled sum)
set(unlabelled ${all})
list(REMOVE_ITEM unlabelled ${labelled})
if(unlabelled)
  list(JOIN unlabelled "\n  " text)
  message(FATAL_ERROR "tests with none of the five labels:\n  ${text}")
endif()
if(NOT sum EQUAL total)
  message(FATAL_ERROR "${total} tests but ${sum} labels: a test carries two of the five")
endif()
