# What the CLI scripts (cmd_*_test.cmake) share: run `softtune ARGS...` and check its exit code, and read the
# field of the problem it printed on stderr. Include it after setting SOFTTUNE.

# Runs softtune with ARGN; fails unless it exits with `expected_code`. Sets `out` and `err` in the caller.
function(expect_run expected_code)
  execute_process(COMMAND ${SOFTTUNE} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL expected_code)
    message(FATAL_ERROR "softtune ${ARGN}: exit ${code}, wanted ${expected_code}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# Runs softtune with ARGN; fails unless it exits 2 with a problem on stderr naming `field`.
function(expect_problem field)
  expect_run(2 ${ARGN})
  string(JSON named ERROR_VARIABLE bad GET "${err}" field)
  if(bad OR NOT named STREQUAL field)
    message(FATAL_ERROR "softtune ${ARGN}: problem names '${named}', wanted '${field}':\n${err}")
  endif()
endfunction()

# Fails unless `value` is a number in [lo, hi] (if() compares numbers as doubles).
function(expect_between what value lo hi)
  if(NOT value MATCHES "^-?[0-9.]+([eE][+-]?[0-9]+)?$" OR value LESS lo OR value GREATER hi)
    message(FATAL_ERROR "${what} = '${value}', wanted a number in [${lo}, ${hi}]")
  endif()
endfunction()
