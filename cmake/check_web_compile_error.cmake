# Web.CompileErrorNamesStudentLine (docs/viewer.md#lecture-demos-in-a-browser): a page whose stage 09
# GLSL does not compile says so in one console error naming the student's file and line, as
# rt export-shadertoy's glslang check does. A copy of stages/09-gpu with `return` misspelt on the
# first line of shade.glsl that returns is exported (RT_GPU_STUDENT_DIR) and opened in headless
# Chromium by tools/web/render_pages.js, which must fail the page with "shade.glsl:LINE:" in its
# output. Skipped with one line without node, puppeteer-core or WebGL2.
#   cmake -DRT=<rt> -DSOURCE=<tree> -DOUT=<dir> -P check_web_compile_error.cmake
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/find_web_browser.cmake)
web_check_start()
file(COPY ${SOURCE}/stages/09-gpu/ DESTINATION ${OUT}/student)

# The first line of shade.glsl that returns, misspelt.
file(STRINGS ${OUT}/student/shade.glsl lines)
set(number 0)
set(broken "")
foreach(line IN LISTS lines)
  math(EXPR number "${number} + 1")
  if(broken STREQUAL "" AND line MATCHES "^ +return ")
    set(broken ${number})
  endif()
endforeach()
if(broken STREQUAL "")
  message(FATAL_ERROR "shade.glsl has no line that returns to misspell")
endif()
file(READ ${OUT}/student/shade.glsl text)
string(REGEX REPLACE "\n( +)return " "\n\\1retrun " text "${text}")
file(WRITE ${OUT}/student/shade.glsl "${text}")

set(ENV{RT_GPU_STUDENT_DIR} ${OUT}/student)
execute_process(COMMAND ${RT} export-web ${SOURCE}/stages/05-recursion/scenes/whitted.json
                        -o ${OUT}/whitted.html
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rt export-web failed (${rc}): ${err}")
endif()
render_pages(${OUT}/frames ${OUT}/whitted.html)
if(render_pages_rc EQUAL 0)
  message(FATAL_ERROR "the page with a misspelt return drew")
endif()
if(NOT render_pages_out MATCHES "console: rt export-web: the fragment shader \\(stage 09\\) does not compile: [^\n]*/student/shade\\.glsl:${broken}:")
  message(FATAL_ERROR "the compile error does not name shade.glsl:${broken}")
endif()
message(STATUS "the compile error names shade.glsl:${broken}")
