# Runs `softtune stability` (server/cli/cmd_stability.cpp) as a user would on a small custom sweep: every case
# listed and passed (exit 0), --summary leaves the cases out, --format svg draws the maps, bad flags exit 2.
# Usage: cmake -DSOFTTUNE=path/to/softtune -DWORK=scratch/dir -P cmd_stability_test.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)

file(MAKE_DIRECTORY ${WORK})
# 2 methods x 3 frequency ratios x 2 damping ratios x 2 masses x 2 steps = 48 cases, plus one stiffness.
file(WRITE ${WORK}/sweep.json [[{"methods": ["explicit_euler", "soft"], "frequency_ratios": [0.01, 0.3, 2.0],
  "stiffnesses": [1e12], "damping_ratios": [0.0, 1.0], "masses": [1e-6, 1.0], "steps": [1e-3, 0.1],
  "chain": {"mass_ratios": [1, 1000], "iterations": [1, 4], "frequency_ratios": [0.01, 0.1, 1.0]}}]])
expect_run(0 stability --request ${WORK}/sweep.json)
string(JSON passed GET "${out}" summary passed)
string(JSON cases GET "${out}" summary cases)
string(JSON listed LENGTH "${out}" cases)
if(NOT passed STREQUAL "ON" OR NOT cases EQUAL listed OR cases LESS 48)
  message(FATAL_ERROR "sweep: passed ${passed}, ${cases} cases, ${listed} listed")
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

expect_run(0 stability --help)
expect_problem(--format stability --request ${WORK}/sweep.json --format csv)
expect_problem(--frobnicate stability --frobnicate)
expect_problem(--request stability --request ${WORK}/absent.json)
file(WRITE ${WORK}/bad.json [[{"masses": [0]}]])
expect_problem(masses[0] stability --request ${WORK}/bad.json)
