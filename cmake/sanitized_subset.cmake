# The sanitizers' slice that every CI run checks (label sanitize): the code that talks to C
# libraries, compiled with AddressSanitizer and UndefinedBehaviorSanitizer inside the release
# build. That code is the GL contexts and the GPU renderer (EGL, OSMesa, GL buffers and
# read-backs), OpenImageIO's module and the tests that drive them: stage 09's GPU tests and
# Framework.OiioTextures.*. Everything else these programs link (the CPU renderer, the reference
# solutions, the scene loader) is the release build's own objects, not instrumented: ASan's
# allocator still sees every allocation and free of the process, and the debug preset
# (`ctest --preset debug`, build-debug/) instruments the whole tree for the developer.
#
# A nested sanitized build of the same programs compiled the whole framework a second time: 574 s
# of compile steps in a CI run (2026-12-07), most of it code this slice never meant to check.

set(RT_SANITIZE_FLAGS -fsanitize=address,undefined -fno-omit-frame-pointer)
# What the sanitized tests run with (cmake/sanitizers/lsan.supp says why each is needed):
# undefined behaviour ends the test, the third-party leaks are suppressed, and the dynamic TLS
# interceptor of GCC 12's runtime is off.
set(RT_SANITIZE_ENVIRONMENT
  "ASAN_OPTIONS=intercept_tls_get_addr=0"
  "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/cmake/sanitizers/lsan.supp:print_suppressions=0"
  "UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1")

# The sources of `target`, as absolute paths (a generator expression, such as $<TARGET_OBJECTS>,
# as it is).
function(rt_absolute_sources out target)
  get_target_property(dir ${target} SOURCE_DIR)
  get_target_property(sources ${target} SOURCES)
  set(result "")
  foreach(source ${sources})
    if(NOT source MATCHES "^\\$<" AND NOT IS_ABSOLUTE "${source}")
      set(source "${dir}/${source}")
    endif()
    list(APPEND result "${source}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

# rt_sanitized_twin(<name> <MODULE|EXECUTABLE> FROM <targets> LINK <libraries>): a module or a
# program made of every source of the FROM targets, compiled with the sanitizers at -O0 (as in the
# debug preset; GCC 12 at -O1 warns of std::regex falsely) and line tables, with the
# FROM targets' include folders and definitions, and linked with what they link (the FROM targets
# themselves excepted) and LINK. The files of a FROM target built without unity batches (the GL
# contexts: their headers clash) compile alone here too; the others in batches.
function(rt_sanitized_twin name kind)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "FROM;LINK")
  if(kind STREQUAL "MODULE")
    add_library(${name} MODULE)
  else()
    add_executable(${name})
  endif()
  set(libraries ${arg_LINK})
  foreach(target ${arg_FROM})
    rt_absolute_sources(sources ${target})
    target_sources(${name} PRIVATE ${sources})
    get_target_property(unity ${target} UNITY_BUILD)
    if(NOT unity)
      set_source_files_properties(${sources} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endif()
    target_include_directories(${name} PRIVATE $<TARGET_PROPERTY:${target},INCLUDE_DIRECTORIES>)
    target_compile_definitions(${name} PRIVATE $<TARGET_PROPERTY:${target},COMPILE_DEFINITIONS>)
    get_target_property(linked ${target} LINK_LIBRARIES)
    if(linked)
      list(APPEND libraries ${linked})
    endif()
  endforeach()
  list(REMOVE_ITEM libraries ${arg_FROM})
  target_link_libraries(${name} PRIVATE ${libraries})
  target_compile_options(${name} PRIVATE ${RT_SANITIZE_FLAGS} -O0 -g1)
  target_link_options(${name} PRIVATE ${RT_SANITIZE_FLAGS})
endfunction()

# rt_sanitized_tests(<program> FILTER <gtest filter> PREFIX <prefix>): the program's tests that the
# filter selects, each a ctest test labelled sanitize with RT_SANITIZE_ENVIRONMENT and ENVIRONMENT.
function(rt_sanitized_tests program)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "FILTER;PREFIX" "ENVIRONMENT")
  gtest_discover_tests(${program}
    TEST_PREFIX "${arg_PREFIX}"
    TEST_FILTER "${arg_FILTER}"
    PROPERTIES TIMEOUT 300
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    NO_PRETTY_VALUES
    DISCOVERY_MODE PRE_TEST)
  # List-valued properties go through a script, as in rt_add_gtest (cmake/testing.cmake).
  set(environment ${RT_SANITIZE_ENVIRONMENT} ${arg_ENVIRONMENT})
  set(script ${CMAKE_CURRENT_BINARY_DIR}/${program}_properties.cmake)
  file(WRITE ${script}
    "if(${program}_TESTS)\n"
    "  set_tests_properties(\${${program}_TESTS} PROPERTIES LABELS sanitize\n"
    "                       ENVIRONMENT \"${environment}\")\n"
    "endif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${script})
endfunction()

# OpenImageIO's module, sanitized, loaded in place of the release one (RT_OIIO_PLUGIN).
rt_sanitized_twin(rt_oiio_sanitized MODULE FROM rt_oiio)
set_target_properties(rt_oiio_sanitized PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/lib)
set(oiio_module
  ${CMAKE_BINARY_DIR}/lib/${CMAKE_SHARED_MODULE_PREFIX}rt_oiio_sanitized${CMAKE_SHARED_MODULE_SUFFIX})

rt_sanitized_twin(oiio_texture_tests_sanitized EXECUTABLE FROM oiio_texture_tests)
add_dependencies(oiio_texture_tests_sanitized rt_oiio_sanitized)
rt_sanitized_tests(oiio_texture_tests_sanitized PREFIX "Sanitized.Framework." FILTER "OiioTextures.*"
  ENVIRONMENT "RT_OIIO_PLUGIN=${oiio_module}")

# Stage 09's tests with the GL contexts and the GPU renderer (rt_stage_tests' stage09_tests).
rt_sanitized_twin(stage09_tests_sanitized EXECUTABLE
  FROM stage09_tests_objects rt_gpu_render rt_gl
  LINK rt_test_support rt_render GTest::gtest_main)
set_target_properties(stage09_tests_sanitized PROPERTIES ENABLE_EXPORTS ON)
set(conformance "Scenes/Conformance.GpuMatchesCpu")
rt_sanitized_tests(stage09_tests_sanitized PREFIX "Sanitized.Stage09."
  FILTER "GpuContexts.*:GpuIntersect.*:${conformance}/whitted:${conformance}/mesh_garden:${conformance}/textured_whitted:${conformance}/sky:Scenes/Shadertoy.ExportCompilesAndMatchesCpu/refraction")
