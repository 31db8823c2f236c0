# Web.ExportMatchesCpu and Web.SampledExportMatchesCpu (docs/viewer.md#lecture-demos-in-a-browser):
# every scene of the stages STAGES matches (a glob of stage numbers; default 0[1-8]) through
# `rt export-web`, each page opened in headless Chromium (SwiftShader's WebGL2) by
# tools/web/render_pages.js, which writes the first frame the page read back with readPixels; that
# frame must match `rt render` by `rt compare` under stage 09's conformance metric (tolerance 2, at
# most 0.5% of pixels failing: stages/09-gpu/tests/conformance_test.cpp), or for stage 10's Monte
# Carlo scenes under stage 10's block metric (means of 8x8 blocks, tolerance 6, at most 1.5%:
# stages/10-sampling/grading.json; the GPU's random numbers are not the CPU's). The scenes the
# export refuses must be exactly EXPECTED_REFUSALS, each with a one-line error naming the scene.
# WIDER_SCENES allow more failing pixels, each for the reason given beside it.
# SIZE (WIDTHxHEIGHT) renders both at that size instead of the scene's.
#   cmake -DRT=<rt> -DSOURCE=<tree> -DOUT=<dir> [-DSTAGES=<glob>] [-DSIZE=<w>x<h>] [-DNODE=<node>]
#         -P check_web_export.cmake
cmake_minimum_required(VERSION 3.25)  # IN_LIST
if(NOT STAGES)
  set(STAGES "0[1-8]")
endif()
# Fog has no GPU port (instances are drawn from a world-space copy: render/gpu/flatten_instances.h).
set(KNOWN_REFUSALS "10-sampling/fog")
# Grazing rays on the rims of the mirror and glass spheres reflect the brick texture, where
# SwiftShader's rounding (not llvmpipe's, for which stage 09 keeps 0.5%) moves a few texels.
set(WIDER_SCENES "textured_whitted=1.0")

include(${CMAKE_CURRENT_LIST_DIR}/find_web_browser.cmake)
web_check_start(${OUT}/pages ${OUT}/frames)

# Export and render on the CPU every scene; a refusal is one line naming the scene.
file(GLOB scenes ${SOURCE}/stages/${STAGES}-*/scenes/*.json)
set(EXPECTED_REFUSALS "")
foreach(known ${KNOWN_REFUSALS})  # those of the stages this run covers
  string(REPLACE "/" "/scenes/" known_file "${known}")
  if("${SOURCE}/stages/${known_file}.json" IN_LIST scenes)
    list(APPEND EXPECTED_REFUSALS ${known})
  endif()
endforeach()
set(block_metric "")
set(size_options "")
if(SIZE MATCHES "^([0-9]+)x([0-9]+)$")
  set(size_options --width ${CMAKE_MATCH_1} --height ${CMAKE_MATCH_2})
endif()
set(refused "")
set(exported "")
foreach(scene ${scenes})
  get_filename_component(name ${scene} NAME_WE)
  get_filename_component(stage_dir ${scene} DIRECTORY)
  get_filename_component(stage_dir ${stage_dir} DIRECTORY)
  get_filename_component(stage ${stage_dir} NAME)
  execute_process(COMMAND ${RT} export-web ${scene} -o ${OUT}/pages/${name}.html ${size_options}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(STRIP "${err}" err)
    if(NOT err MATCHES "^[^\n]*${name}.json: [^\n]+$")
      message(FATAL_ERROR "rt export-web ${stage}/${name}: the refusal is not one line naming the scene:\n${err}")
    endif()
    list(APPEND refused "${stage}/${name}")
    message(STATUS "refused ${stage}/${name}: ${err}")
    continue()
  endif()
  string(STRIP "${out}" out)
  message(STATUS "${out}")
  execute_process(COMMAND ${RT} render ${scene} -o ${OUT}/frames/${name}_cpu.png ${size_options}
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "rt render ${stage}/${name} failed (${rc}): ${err}")
  endif()
  list(APPEND exported ${name})
  if(stage MATCHES "^1[01]-")  # Monte Carlo: stage 10's block metric
    list(APPEND block_metric ${name})
  endif()
endforeach()
if(NOT refused STREQUAL EXPECTED_REFUSALS)
  message(FATAL_ERROR "rt export-web refused [${refused}]; expected [${EXPECTED_REFUSALS}]")
endif()

# One browser for every page.
list(TRANSFORM exported PREPEND ${OUT}/pages/ OUTPUT_VARIABLE pages)
list(TRANSFORM pages APPEND .html)
render_pages(${OUT}/frames ${pages})
if(NOT render_pages_rc EQUAL 0)
  message(FATAL_ERROR "a page failed in Chromium (above)")
endif()

# The metric of stages/09-gpu/tests/conformance_test.cpp.
set(failed "")
foreach(name ${exported})
  set(percent 0.5)
  foreach(wider ${WIDER_SCENES})
    if(wider MATCHES "^${name}=(.+)$")
      set(percent ${CMAKE_MATCH_1})
    endif()
  endforeach()
  set(metric --tolerance 2 --max-failing-percent ${percent})
  if(name IN_LIST block_metric)
    set(metric --tolerance 6 --max-failing-percent 1.5 --block 8)
  endif()
  execute_process(COMMAND ${RT} compare ${OUT}/frames/${name}.png ${OUT}/frames/${name}_cpu.png
                          ${metric}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(STRIP "${out}${err}" line)
  string(REPLACE "${OUT}/frames/" "" line "${line}")
  message(STATUS "${line}")
  if(NOT rc EQUAL 0)
    list(APPEND failed ${name})
  endif()
endforeach()
if(failed)
  message(FATAL_ERROR "the page's first frame differs from rt render for: ${failed}")
endif()
list(LENGTH exported count)
message(STATUS "${count} pages match rt render; refused as expected: ${refused}")
