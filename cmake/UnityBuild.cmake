# Unity builds for the server's libraries and the test executables: their sources each include the same
# heavy headers (nlohmann-json, gtest, Eigen, the app's types) and instantiate and optimise the same
# templates again; compiled eight to a translation unit, that work is done once per eight. Measured on
# softtune_app alone (gcc 12, Release, 26 sources): 110 s of CPU one by one, 47 s in unity batches of 8.
#
# The rule this asks of those folders' sources: no two files of one target give a different meaning to
# the same name in the same namespace, even inside `namespace {}` (the compiler says so at once when they
# do). core/, scene/, engines/ and render/ stay one file per translation unit: their engine models and
# drawing code reuse short internal names by design, and they are a small part of the build.
#
# -DSOFTTUNE_UNITY_BUILD=OFF compiles file by file (quicker when editing one file over and over).
option(SOFTTUNE_UNITY_BUILD "Compile the server libraries and the tests in unity batches" ON)
set(SOFTTUNE_UNITY_BATCH 8)

function(softtune_unity)
  if(NOT SOFTTUNE_UNITY_BUILD)
    return()
  endif()
  foreach(t IN LISTS ARGN)
    set_target_properties(${t} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${SOFTTUNE_UNITY_BATCH})
  endforeach()
endfunction()
