# Runs `softtune simulate` (server/cli/cmd_simulate.cpp) as a user would: a preset's probes land on the
# request, snapshots come with --frames at the stride asked, and bad flags exit 2 naming the field.
# Usage: cmake -DSOFTTUNE=path/to/softtune -DPRESETS=path/to/presets -DWORK=scratch/dir -P cmd_simulate_test.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)

# The 1-D oscillator preset (2 Hz, zeta 0.5 at 60 fps): core integrators only. Exact mode lands on the request;
# the standard soft constraint (implicit Euler, omega h = 0.21) runs a few per cent slow.
expect_run(0 simulate --preset oscillator --presets ${PRESETS})
string(JSON name GET "${out}" name)
string(JSON stages GET "${out}" stages)
if(NOT name STREQUAL "oscillator" OR stages MATCHES "box2d" OR NOT stages MATCHES "core_integrator")
  message(FATAL_ERROR "oscillator preset: name ${name}, stages ${stages}")
endif()
string(JSON soft GET "${out}" probes 0 id)
string(JSON soft_error GET "${out}" probes 0 error frequency)
string(JSON exact_error GET "${out}" probes 1 error frequency)
string(JSON exact_zeta_error GET "${out}" probes 1 error damping_ratio)
if(NOT soft STREQUAL "soft")
  message(FATAL_ERROR "first probe is '${soft}', wanted soft")
endif()
expect_between("soft error.frequency" "${soft_error}" -0.1 -0.01)
expect_between("soft_exact error.frequency" "${exact_error}" -1e-6 1e-6)
expect_between("soft_exact error.damping_ratio" "${exact_zeta_error}" -1e-6 1e-6)

string(JSON has_snapshots ERROR_VARIABLE none GET "${out}" snapshots)
if(NOT none)
  message(FATAL_ERROR "snapshots without --frames")
endif()

# Snapshots every 30th frame of the mouse preset (3 s at 60 fps, 180 frames): frames 0, 30, ..., 180.
expect_run(0 simulate --preset mouse --presets ${PRESETS} --frames --frame-stride 30)
string(JSON snapshots LENGTH "${out}" snapshots)
if(NOT snapshots EQUAL 7)
  message(FATAL_ERROR "mouse --frames --frame-stride 30: ${snapshots} snapshots, wanted 7")
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

expect_problem(--preset simulate --presets ${PRESETS})  # neither --preset nor --request
expect_problem(--frame-stride simulate --preset oscillator --presets ${PRESETS} --frame-stride often)
file(WRITE ${WORK}/list.json "[1, 2]")
expect_problem(--request simulate --request ${WORK}/list.json --presets ${PRESETS})

# --engine (issue 32): the default engine named runs the scene and the answer says which engine ran; an
# unknown engine or a malformed --engine-settings exits 2 naming it.
expect_run(0 simulate --preset buddhas --presets ${PRESETS} --engine box2d_v2_4)
string(JSON engine GET "${out}" engine name)
string(JSON version GET "${out}" engine version)
string(JSON stages GET "${out}" stages)
if(NOT engine STREQUAL "box2d_v2_4" OR version STREQUAL "" OR NOT stages MATCHES "box2d_step")
  message(FATAL_ERROR "--engine box2d_v2_4: engine ${engine}, version '${version}', stages ${stages}")
endif()
expect_problem(engine simulate --preset buddhas --presets ${PRESETS} --engine havok)
expect_problem(--engine-settings simulate --preset buddhas --presets ${PRESETS} --engine-settings iterations)
expect_problem(engine_settings.iterations simulate --preset buddhas --presets ${PRESETS} --engine-settings iterations=4)
