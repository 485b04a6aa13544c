# Runs `softtune stability` (server/cli/cmd_stability.cpp) as a user would on a small custom sweep: every case
# listed and its prediction met (exit 0), explicit Euler unstable at f h = 2 and the soft constraint never,
# --summary leaves the cases out, --format svg draws the maps, bad flags exit 2 naming the field.
# Usage: cmake -DSOFTTUNE=path/to/softtune -DWORK=scratch/dir -P cmd_stability_test.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)

file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/sweep.json [[{"methods": ["explicit_euler", "soft"], "frequency_ratios": [0.01, 2.0],
  "damping_ratios": [0.0], "masses": [1.0], "steps": [0.01],
  "chain": {"mass_ratios": [1, 1000], "iterations": [1], "frequency_ratios": [0.01, 1.0]}}]])
expect_run(0 stability --request ${WORK}/sweep.json)
string(JSON passed GET "${out}" summary passed)
string(JSON cases GET "${out}" summary cases)
string(JSON listed LENGTH "${out}" cases)
string(JSON unstable GET "${out}" summary observed_unstable)
string(JSON soft_blowups GET "${out}" summary soft_blowups)
if(NOT passed STREQUAL "ON" OR NOT cases EQUAL listed OR unstable LESS 1 OR NOT soft_blowups EQUAL 0)
  message(FATAL_ERROR "sweep: passed ${passed}, ${cases} cases, ${listed} listed, ${unstable} unstable, "
                      "${soft_blowups} soft blow-ups")
endif()

expect_run(0 stability --request ${WORK}/sweep.json --summary)
string(JSON none ERROR_VARIABLE absent GET "${out}" cases)
string(JSON chain TYPE "${out}" chain)
if(NOT absent OR NOT chain STREQUAL "OBJECT")
  message(FATAL_ERROR "--summary: cases still listed or no chain:\n${out}")
endif()

expect_run(0 stability --request ${WORK}/sweep.json --format svg)
if(NOT out MATCHES "^<svg" OR NOT out MATCHES "Stability map")
  message(FATAL_ERROR "--format svg is no stability map")
endif()

expect_problem(--format stability --request ${WORK}/sweep.json --format csv)
expect_problem(--request stability --request ${WORK}/absent.json)
file(WRITE ${WORK}/bad.json [[{"masses": [0]}]])
expect_problem(masses.0 stability --request ${WORK}/bad.json)
