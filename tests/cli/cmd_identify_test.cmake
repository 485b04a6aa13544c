# Runs `softtune identify` as a user would: a CSV recording of a known oscillator (4.3 Hz, zeta 0.61, written
# by the closed form), against the request it was tuned for, from a file and from stdin; and a bad row.
# Usage: cmake -DSOFTTUNE=path/to/softtune -DDATA=tests/cli/data -P cmd_identify_test.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)

expect_run(0 identify --csv ${DATA}/recording_4p3hz.csv --frequency 5 --damping-ratio 0.5 --mass 2 --engine godot)
string(JSON f GET "${out}" frequency_hz)
string(JSON z GET "${out}" damping_ratio)
string(JSON verdict GET "${out}" verdict)
string(JSON next GET "${out}" correction next frequency_hz)
if(f LESS 4.29999 OR f GREATER 4.30001 OR z LESS 0.60999 OR z GREATER 0.61001 OR NOT verdict STREQUAL "ok")
  message(FATAL_ERROR "identified ${f} Hz, zeta ${z}, verdict ${verdict}; wanted 4.3 Hz, 0.61, ok")
endif()
# f' = 5 x 5 / 4.3
if(next LESS 5.8139 OR next GREATER 5.8140)
  message(FATAL_ERROR "correction ${next} Hz, wanted 5.81395")
endif()

# The correction's verdict; and 4.3 Hz / 0.61 where 5 Hz / 0.2 was asked, typed with no damping: the engine
# damps by itself, so the correction types a negative ratio unless the engine refuses one.
string(JSON stance GET "${out}" correction verdict)
if(NOT stance STREQUAL "converging")
  message(FATAL_ERROR "correction verdict ${stance}, wanted converging")
endif()
expect_run(0 identify --csv ${DATA}/recording_4p3hz.csv --frequency 5 --damping-ratio 0.2 --mass 2 --typed-frequency 5 --typed-damping 0)
string(JSON z GET "${out}" correction next damping_ratio)
if(NOT z LESS 0)
  message(FATAL_ERROR "next damping ratio ${z}, wanted a negative one")
endif()
expect_run(0 identify --csv ${DATA}/recording_4p3hz.csv --frequency 5 --damping-ratio 0.2 --mass 2 --typed-frequency 5 --typed-damping 0 --no-negative-damping)
string(JSON z GET "${out}" correction next damping_ratio)
if(NOT z EQUAL 0)
  message(FATAL_ERROR "next damping ratio ${z} with --no-negative-damping, wanted 0")
endif()

execute_process(COMMAND ${SOFTTUNE} identify --csv - INPUT_FILE ${DATA}/recording_4p3hz.csv RESULT_VARIABLE code OUTPUT_VARIABLE out)
string(JSON f GET "${out}" frequency_hz)
if(NOT code EQUAL 0 OR f LESS 4.29999 OR f GREATER 4.30001)
  message(FATAL_ERROR "from stdin: exit ${code}, ${f} Hz")
endif()

expect_run(0 identify --help)
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/identify_bad.csv "time,x\n0,1\n0.1,oops\n")
expect_run(2 identify --csv ${CMAKE_CURRENT_BINARY_DIR}/identify_bad.csv)
string(JSON field GET "${err}" field)
if(NOT field STREQUAL "csv.rows.1.x")
  message(FATAL_ERROR "problem names '${field}', wanted csv.rows.1.x:\n${err}")
endif()
expect_run(2 identify --frequency 5)
