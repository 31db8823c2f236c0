# Helpers for the project's GoogleTest executables.

# rt_add_gtest(<target> PREFIX <ctest name prefix> LABELS <labels...>)
# Registers the tests of an existing GoogleTest executable with CTest as <prefix><Suite>.<Test>,
# discovered when ctest runs (so a starter tree whose stubs crash still builds and lists them).
function(rt_add_gtest target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "PREFIX" "LABELS")
  # A test's own code does little work itself: the framework, the student files and the CGAL
  # reference it calls are libraries at -O3 (cmake/off_hot_path.cmake).
  rt_off_hot_path(${target})
  gtest_discover_tests(${target}
    TEST_PREFIX "${arg_PREFIX}"
    PROPERTIES TIMEOUT 300
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    NO_PRETTY_VALUES  # names come from the name generators (Graded/Image.../<scene>)
    DISCOVERY_MODE PRE_TEST)
  # CMake 3.25's gtest_discover_tests splits list-valued PROPERTIES (LABELS "a;b" keeps only
  # "a"), so labels are set by a script ctest runs after discovery, from the <target>_TESTS list.
  set(script ${CMAKE_CURRENT_BINARY_DIR}/${target}_labels.cmake)
  file(WRITE ${script}
    "if(${target}_TESTS)\n"
    "  set_tests_properties(\${${target}_TESTS} PROPERTIES LABELS \"${arg_LABELS}\")\n"
    "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${script})
endfunction()

# rt_skip_pattern(<test> <regex>): <test> (a script test) says it cannot run with output
# matching <regex>: xvfb-run, a browser or WebGL2 missing. A skip is for a starter tree only, on
# a student's machine that may lack them; in the instructor tree scripts/install-deps.sh installs
# everything, so a test that skips there has not run, and it fails instead. (GoogleTest's skips:
# RT_SKIP_IN_STARTER_TREE, framework/testing/skip.h.)
function(rt_skip_pattern test regex)
  if(RT_INSTRUCTOR)
    set_property(TEST ${test} APPEND PROPERTY FAIL_REGULAR_EXPRESSION "${regex}")
  else()
    set_property(TEST ${test} PROPERTY SKIP_REGULAR_EXPRESSION "${regex}")
  endif()
endfunction()

# rt_graded_binary(<target> <out>): <out> is ON when grading.json in the calling folder lists
# <target> among its unit_tests' binaries (rt-grade builds and runs exactly those judges).
function(rt_graded_binary target out)
  set(graded OFF)
  set(spec ${CMAKE_CURRENT_SOURCE_DIR}/grading.json)
  if(EXISTS ${spec})
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${spec})
    file(READ ${spec} json)
    string(JSON count ERROR_VARIABLE problem LENGTH "${json}" unit_tests)
    if(problem)
      message(FATAL_ERROR "${spec}: ${problem}")
    endif()
    if(count GREATER 0)
      math(EXPR last "${count} - 1")
      foreach(i RANGE ${last})
        string(JSON binary GET "${json}" unit_tests ${i} binary)
        if(binary STREQUAL target)
          set(graded ON)
        endif()
      endforeach()
    endif()
  endif()
  set(${out} ${graded} PARENT_SCOPE)
endfunction()

# rt_stage_tests(<NN> <target> SOURCES <files...> [SCENE_IMAGES] [LABELS <extra labels...>]
#                [LIBRARIES <libs...>])
# A GoogleTest executable for stage NN: CTest names StageNN.<Suite>.<Test>, label stageNN plus
# any extra labels. SCENE_IMAGES adds the image tests of the stage's graded scenes
# (framework/testing/scene_image_test.cpp), for the folder this is called from.
function(rt_stage_tests number target)
  cmake_parse_arguments(PARSE_ARGV 2 arg "SCENE_IMAGES" "" "SOURCES;LABELS;LIBRARIES")
  # The tests compile once, into objects that two programs link: <target>, the tests with the
  # student code (a student's own tree), and <target>_judge, the same tests with every call of
  # student code sent to rt-worker (the grading judge: framework/remote/remote_call.h). The GPU
  # renderer runs the student's GLSL, so only <target> links it; a judge sends its calls too.
  set(object_libraries ${arg_LIBRARIES})
  list(REMOVE_ITEM object_libraries rt_gpu_render)
  add_library(${target}_objects OBJECT ${arg_SOURCES})
  target_link_libraries(${target}_objects PUBLIC rt_test_support ${object_libraries})
  if(arg_SCENE_IMAGES)
    get_filename_component(stage_folder ${CMAKE_CURRENT_SOURCE_DIR} NAME)
    set(stage_source ${CMAKE_CURRENT_BINARY_DIR}/${target}_image_stage.cpp)
    file(CONFIGURE OUTPUT ${stage_source} CONTENT
      "// Written by rt_stage_tests: the stage whose graded scenes scene_image_test.cpp runs.\n\
namespace rt::testing {\n\
extern const char* const kImageTestStage;\n\
const char* const kImageTestStage = \"${stage_folder}\";\n\
}  // namespace rt::testing\n")
    target_sources(${target}_objects PRIVATE ${stage_source})
    target_link_libraries(${target}_objects PUBLIC nlohmann_json::nlohmann_json)
    set(image_objects $<TARGET_OBJECTS:rt_scene_images>)
  endif()
  rt_off_hot_path(${target}_objects)
  add_executable(${target} ${image_objects})
  target_link_libraries(${target} PRIVATE ${target}_objects rt_test_support rt_render
    ${arg_LIBRARIES} GTest::gtest_main)
  # Its functions' names in the dynamic symbol table (-rdynamic): a test stopped at its CPU limit
  # names the functions it was in (testing/test_watch.h).
  set_target_properties(${target} PROPERTIES ENABLE_EXPORTS ON)
  rt_add_gtest(${target} PREFIX "Stage${number}." LABELS stage${number} ${arg_LABELS})
  # `cmake --build --preset release --target stageNN`: what a student working on stage NN needs
  # (its test binaries and rt), not every other stage's tests, the grader or the benchmarks.
  if(NOT TARGET stage${number})
    add_custom_target(stage${number})
    add_dependencies(stage${number} rt)
  endif()
  add_dependencies(stage${number} ${target})
  # The judge is for rt-grade, which builds it by name: a student's build leaves it out.
  add_executable(${target}_judge ${image_objects})
  target_link_libraries(${target}_judge PRIVATE ${target}_objects rt_test_support rt_judge
    GTest::gtest_main)
  rt_off_hot_path(${target}_judge)
  # Only a binary that the stage's grading.json names is ever run as a judge; the others (the
  # optional GPU parts' binaries) leave theirs out of the build and of the Remote tests.
  rt_graded_binary(${target} graded)
  if(NOT RT_INSTRUCTOR OR NOT graded)
    set_target_properties(${target}_judge PROPERTIES EXCLUDE_FROM_ALL ON)
    return()
  endif()
  add_dependencies(stage${number} ${target}_judge rt-worker)  # its Remote test is -L stageNN too
  # Every graded test of the binary through the split, with the reference solution in rt-worker
  # (the image tests are not graded as unit tests: rt-grade renders the scenes itself).
  add_test(NAME Remote.${target}
    COMMAND ${target}_judge --gtest_brief=1 --gtest_filter=-Graded/Image.*)
  set_tests_properties(Remote.${target} PROPERTIES LABELS "remote;stage${number}"
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    ENVIRONMENT RT_REMOTE_WORKER=$<TARGET_FILE:rt-worker>)
  add_test(NAME Remote.${target}.HoldsNoStudentCode
    COMMAND bash ${PROJECT_SOURCE_DIR}/cmake/check_judge_links.sh $<TARGET_FILE:${target}_judge>
            $<TARGET_FILE:rt_judge> $<TARGET_FILE:rt_stages> $<TARGET_FILE:rt_render>
            $<TARGET_FILE:rt_gpu_render>)
  set_tests_properties(Remote.${target}.HoldsNoStudentCode PROPERTIES LABELS "remote;framework")
endfunction()
