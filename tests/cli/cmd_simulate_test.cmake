# Runs `softtune simulate` (server/cli/cmd_simulate.cpp) as a user would: a preset's probes land on the
# request, snapshots come with --frames at the stride asked, and bad flags exit 2 naming the field.
# Usage: cmake -DSOFTTUNE=path/to/softtune -DPRESETS=path/to/presets -DWORK=scratch/dir -P cmd_simulate_test.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)

# The 1-D oscillator preset: core integrators only, the measured frequency within 3 % of the request.
expect_run(0 simulate --preset oscillator --presets ${PRESETS})
string(JSON name GET "${out}" name)
string(JSON stages GET "${out}" stages)
if(NOT name STREQUAL "oscillator" OR stages MATCHES "box2d" OR NOT stages MATCHES "core_integrator")
  message(FATAL_ERROR "oscillator preset: name ${name}, stages ${stages}")
endif()
string(JSON probes LENGTH "${out}" probes)
math(EXPR last "${probes} - 1")
foreach(i RANGE ${last})
  string(JSON error GET "${out}" probes ${i} error frequency)
  expect_between("probes.${i}.error.frequency" "${error}" -0.03 0.03)
endforeach()

# Snapshots every 30th frame of the mouse preset (180 frames): frames 0, 30, ..., 180.
expect_run(0 simulate --preset mouse --presets ${PRESETS} --frames --frame-stride 30)
string(JSON snapshots LENGTH "${out}" snapshots)
if(NOT snapshots EQUAL 7)
  message(FATAL_ERROR "mouse --frames --frame-stride 30: ${snapshots} snapshots, wanted 7")
endif()
expect_run(0 simulate --preset mouse --presets ${PRESETS})
string(JSON has_snapshots ERROR_VARIABLE none GET "${out}" snapshots)
if(NOT none)
  message(FATAL_ERROR "snapshots without --frames")
endif()

# A full scene from a file gives the same run as its preset.
file(MAKE_DIRECTORY ${WORK})
file(READ ${PRESETS}/oscillator.json scene)
file(WRITE ${WORK}/scene.json "${scene}")
expect_run(0 simulate --request ${WORK}/scene.json --presets ${PRESETS})
string(JSON name GET "${out}" name)
if(NOT name STREQUAL "oscillator")
  message(FATAL_ERROR "--request scene.json ran '${name}'")
endif()

expect_run(0 simulate --help)
expect_problem(--preset simulate --presets ${PRESETS})  # neither --preset nor --request
expect_problem(frame_stride simulate --preset oscillator --presets ${PRESETS} --frame-stride 0)
expect_problem(--frame-stride simulate --preset oscillator --presets ${PRESETS} --frame-stride often)
expect_problem(mass_model simulate --preset oscillator --presets ${PRESETS} --mass-model heavy)
expect_problem(--frobnicate simulate --preset oscillator --frobnicate 3)
file(WRITE ${WORK}/list.json "[1, 2]")
expect_problem(--request simulate --request ${WORK}/list.json --presets ${PRESETS})
expect_run(2 simulate --preset nosuch --presets ${PRESETS})
