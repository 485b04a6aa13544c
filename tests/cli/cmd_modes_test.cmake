# Runs `softtune modes` as a user would: the per-spring vehicle's heave on the docs' closed form, exit 2 and a
# problem naming the flag's field on bad input.
# Usage: cmake -DSOFTTUNE=path/to/softtune -DPRESETS=presets -P cmd_modes_test.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)

expect_run(0 modes --preset vehicle_per_spring --presets ${PRESETS})
string(JSON name GET "${out}" modes 1 name)
string(JSON f GET "${out}" modes 1 continuous frequency_hz)
# f sqrt(2 m_eff / M), m_eff = 1 / (1/120 + 1/15 + 1.1^2 / 92.5) = 11.35 kg: 1.305 Hz (docs/scenes.md).
if(NOT name STREQUAL "chassis heave" OR f LESS 1.300 OR f GREATER 1.310)
  message(FATAL_ERROR "modes 1 is '${name}' at ${f} Hz; wanted chassis heave at 1.305 Hz")
endif()

expect_run(0 modes --help)
expect_run(2 modes --preset vehicle_per_spring --presets ${PRESETS} --at 100)
string(JSON field GET "${err}" field)
if(NOT field STREQUAL "at_s")
  message(FATAL_ERROR "problem names '${field}', wanted at_s:\n${err}")
endif()
expect_run(2 modes --preset oscillator --presets ${PRESETS})
string(JSON field GET "${err}" field)
if(NOT field STREQUAL "bodies")
  message(FATAL_ERROR "problem names '${field}', wanted bodies:\n${err}")
endif()
