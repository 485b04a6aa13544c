# Runs `softtune verify` (server/cli/cmd_verify.cpp) as a user would: without --engines no engine runs; with
# --engines box2d_v2_4 the real Box2D 2.4.1 moves as its model predicts; bad flags exit 2 naming the field.
# Usage: cmake -DSOFTTUNE=path/to/softtune -DWORK=scratch/dir -P cmd_verify_test.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)

expect_run(0 verify --frequency 3 --damping-ratio 0.15 --mass 2.5)
string(JSON engines LENGTH "${out}" engines)
string(JSON available LENGTH "${out}" available_engines)
if(NOT engines EQUAL 0 OR available LESS 1)
  message(FATAL_ERROR "verify without --engines ran ${engines} engines (of ${available}):\n${out}")
endif()

# 3 Hz at 60 fps is well resolved: Box2D's measured frequency is its model's within 1 %.
expect_run(0 verify --engines box2d_v2_4 --frequency 3 --damping-ratio 0.15 --mass 2.5 --mode exact --duration 4)
string(JSON type TYPE "${out}" engines box2d_v2_4)
if(NOT type STREQUAL "OBJECT")
  message(FATAL_ERROR "no box2d_v2_4 answer:\n${out}")
endif()
string(JSON off GET "${out}" engines box2d_v2_4 measured_vs_predicted frequency)
expect_between("box2d_v2_4 measured_vs_predicted.frequency" "${off}" -0.01 0.01)

# The same request from a file.
file(MAKE_DIRECTORY ${WORK})
file(WRITE ${WORK}/verify.json [[{"frequency_hz": 3, "damping_ratio": 0.15, "effective_mass": 2.5, "engines": []}]])
expect_run(0 verify --request ${WORK}/verify.json)

expect_problem(--duration verify --engines box2d_v2_4 --frequency 3 --mass 1 --oscillation some --duration long)
expect_problem(--request verify --request ${WORK}/verify.json --mass 2)
expect_problem(engines.0 verify --engines havok --frequency 3 --oscillation some --mass 1)
