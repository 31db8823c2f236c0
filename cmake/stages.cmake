# Helpers shared by the stage folders.

# rt_stage_tests(<NN> <target> SOURCES <files...> [LABELS <extra labels...>] [LIBRARIES <libs...>])
# A GoogleTest executable for stage NN. Its tests appear in CTest as StageNN.<Suite>.<Test>,
# labelled stageNN (plus any extra labels), and are discovered when ctest runs, so a starter
# tree whose stubs crash or hang still builds.
function(rt_stage_tests number target)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "SOURCES;LABELS;LIBRARIES")
  add_executable(${target} ${arg_SOURCES})
  target_link_libraries(${target} PRIVATE rt_testing GTest::gtest_main ${arg_LIBRARIES})
  target_compile_definitions(${target} PRIVATE RT_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(${target}
    TEST_PREFIX "Stage${number}."
    PROPERTIES LABELS "stage${number};${arg_LABELS}" TIMEOUT 300
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    DISCOVERY_MODE PRE_TEST)
endfunction()
