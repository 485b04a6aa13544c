# Every ctest test gets exactly one label, from the rules below, so a test added anywhere under tests/
# is labelled without an edit to its CMakeLists.txt:
#   unit         in-process tests of one area and the source-tree checks (scripts/test.sh --quick runs these)
#   integration  the CLI as users call it, a server over real HTTP, the render processes, whole presets
#   browser      the page in headless Chromium
#   real-engine  a real engine (linked, or WebAssembly under node) run from softtune's answer
#   memcheck     valgrind memcheck runs of the Box2D-facing tests
# A test takes the first rule whose pattern matches its name (a gtest case: its executable's name), else its
# directory's default (tests/engines and below: real-engine; everything else: unit). A new test whose
# default is wrong gets a pattern here, not a LABELS property of its own.
#
# How, since ctest reads a directory's TEST_INCLUDE_FILES (where gtest_discover_tests puts its cases)
# before that directory's add_test lines: softtune_test_labels(DIR) appends to each directory one include
# file that labels its gtest executables' cases (the `<target>_TESTS` lists the discovered files set), and
# softtune_test_labels_plain() writes one more include, read after every test directory, that labels the
# add_test tests by name (ctest's set_tests_properties finds a test defined in any directory read before).

set(SOFTTUNE_TEST_LABEL_RULES
  "^memcheck_"                      memcheck
  "^web\\.e2e$"                     browser
  "^(engines\\.|mujoco_js_)"        real-engine
  "^(cli[._]|cmd_|preset_check$|preset_ci_doc_test$)" integration
  "^(http_integration_tests|security_tests|preview_service_test|scene_frames_test)$" integration
  "^(renderer_test|raster_process_test|frame_pipeline_test|clip_test)$" integration
  "^(scene_modes_tests|scene_stability_tests)$" integration
  "^(engines_tests)$"               unit
)

# The longest tests, as ctest names them (a gtest case: Suite.Case), with a COST so that `ctest -j` starts
# them first on a fresh build, where ctest has no timings of its own yet (Testing/Temporary/CTestCostData.txt)
# and would start them in declaration order: one started last is the whole stage's tail. The cost is the
# seconds measured in the ASan+UBSan suite, where the order matters most.
set(SOFTTUNE_TEST_COST_RULES
  "^ModalRange\\.BridgeDeck"       275
)

# softtune_test_label(OUT NAME DIR): the label of the test or gtest executable NAME defined in DIR.
function(softtune_test_label out name dir)
  set(rules ${SOFTTUNE_TEST_LABEL_RULES})
  while(rules)
    list(POP_FRONT rules pattern label)
    if(name MATCHES "${pattern}")
      set(${out} ${label} PARENT_SCOPE)
      return()
    endif()
  endwhile()
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${dir})
  if(rel MATCHES "^tests/engines(/|$)")
    set(${out} real-engine PARENT_SCOPE)
  else()
    set(${out} unit PARENT_SCOPE)
  endif()
endfunction()

# softtune_test_labels(DIR): labels the gtest cases of DIR and below; collects their add_test names.
function(softtune_test_labels dir)
  get_property(bin DIRECTORY ${dir} PROPERTY BINARY_DIR)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  set(script "")
  # Inside each executable's branch: the COST of its cases that a cost rule names.
  set(cost_script "")
  set(rules ${SOFTTUNE_TEST_COST_RULES})
  while(rules)
    list(POP_FRONT rules pattern cost)
    string(APPEND cost_script "  foreach(c IN LISTS @TARGET@_TESTS)\n    if(c MATCHES [=[${pattern}]=])\n"
                              "      set_tests_properties(\${c} PROPERTIES COST ${cost})\n    endif()\n  endforeach()\n")
  endwhile()
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    if(type STREQUAL "EXECUTABLE")
      softtune_test_label(label ${t} ${dir})
      string(REPLACE "@TARGET@" "${t}" target_cost_script "${cost_script}")
      string(APPEND script "if(DEFINED ${t}_TESTS)\n  set_tests_properties(\${${t}_TESTS} PROPERTIES LABELS ${label})\n"
                           "${target_cost_script}"
                           "else()\n  set_tests_properties(${t}_NOT_BUILT PROPERTIES LABELS ${label})\nendif()\n")
    endif()
  endforeach()
  get_property(tests DIRECTORY ${dir} PROPERTY TESTS)
  foreach(t IN LISTS tests)
    softtune_test_label(label ${t} ${dir})
    set_property(GLOBAL APPEND PROPERTY SOFTTUNE_PLAIN_TEST_LABELS "${t}" ${label})
  endforeach()
  if(script)
    file(WRITE ${bin}/softtune_labels.cmake "${script}")
    set_property(DIRECTORY ${dir} APPEND PROPERTY TEST_INCLUDE_FILES ${bin}/softtune_labels.cmake)
  endif()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(d IN LISTS subdirs)
    softtune_test_labels(${d})
  endforeach()
endfunction()

# softtune_test_labels_plain(): called from a directory that ctest reads after every test directory.
function(softtune_test_labels_plain)
  get_property(pairs GLOBAL PROPERTY SOFTTUNE_PLAIN_TEST_LABELS)
  set(script "")
  while(pairs)
    list(POP_FRONT pairs name label)
    string(APPEND script "set_tests_properties([=[${name}]=] PROPERTIES LABELS ${label})\n")
    set(rules ${SOFTTUNE_TEST_COST_RULES})
    while(rules)
      list(POP_FRONT rules pattern cost)
      if(name MATCHES "${pattern}")
        string(APPEND script "set_tests_properties([=[${name}]=] PROPERTIES COST ${cost})\n")
        break()
      endif()
    endwhile()
  endwhile()
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/softtune_plain_labels.cmake "${script}")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${CMAKE_CURRENT_BINARY_DIR}/softtune_plain_labels.cmake)
endfunction()
