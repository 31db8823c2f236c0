# Web.TogglesMatchCpu (docs/viewer.md#lecture-demos-in-a-browser): the switches of rt export-web's
# panel change the image as the same switches of rt view do. Each scene's page is opened in
# headless Chromium (SwiftShader's WebGL2) by tools/web/render_pages.js from a static web server
# (--http; Web.ExportMatchesCpu opens its pages from file://), which clicks each switch
# (checkbox #toggle-NAME), writes the frame it draws and clicks it back (which must draw the first
# frame again). Each such frame must match `rt render` with the same switch (--off TERM, --shadows,
# --fresnel: what rt view's panel changes, render/prepare.h's switch_off_terms) under stage 09's
# conformance metric (tolerance 2, at most 0.5% of pixels failing), and must differ from the first
# frame (a switch that changes nothing is a broken switch). `moves` and `ortho` move the camera with
# the mouse (orbit, pan, zoom; and P for orthographic), and the frame must match `rt render` of the
# scene with the camera the page's W shows for the scene file (R must bring the first frame back);
# `reference` checks the CPU render button's difference (near black) and the frame time. A console
# error, an uncaught exception or a WebGL error fails it; a browser without WebGL2 skips it with
# one line.
#   cmake -DRT=<rt> -DSOURCE=<tree> -DOUT=<dir> -P check_web_toggles.cmake
cmake_minimum_required(VERSION 3.25)  # IN_LIST
# Each case: scene|action|rt render's options for the same switch ("camera": the page's camera;
# "": nothing to render).
set(CASES
  "05-recursion/scenes/whitted.json|specular|--off specular"
  "05-recursion/scenes/whitted.json|shadows|--shadows off"
  "05-recursion/scenes/whitted.json|diffuse|--off diffuse"
  "05-recursion/scenes/whitted.json|reflection|--off reflection"
  "05-recursion/scenes/whitted.json|refraction|--off refraction"
  "05-recursion/scenes/whitted.json|fresnel|--fresnel on"
  "05-recursion/scenes/whitted.json|mode-depth|--mode depth"
  "04-shadows/scenes/cornell_box.json|reference|"
  "04-shadows/scenes/cornell_box.json|ambient|--off ambient"
  "04-shadows/scenes/cornell_box.json|emissive|--off emissive"
  "04-shadows/scenes/cornell_box.json|shadows|--shadows off"
  "04-shadows/scenes/cornell_box.json|moves|camera"
  "04-shadows/scenes/cornell_box.json|ortho|camera"
  "08-environment/scenes/sky.json|environment|--off environment")

include(${CMAKE_CURRENT_LIST_DIR}/find_web_browser.cmake)
web_check_start(${OUT}/pages ${OUT}/frames)

function(run_rt what)
  execute_process(COMMAND ${RT} ${ARGN} RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}): ${err}")
  endif()
endfunction()

# Each scene's page once, with the switches to click; each switch's CPU render.
set(names "")
foreach(case ${CASES})
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 scene)
  list(GET parts 1 switch)
  list(LENGTH parts n)
  set(options "")
  if(n GREATER 2)
    list(GET parts 2 options)
  endif()
  get_filename_component(name ${scene} NAME_WE)
  if(NOT name IN_LIST names)
    list(APPEND names ${name})
    run_rt("rt export-web ${scene}" export-web ${SOURCE}/stages/${scene}
           -o ${OUT}/pages/${name}.html)
  endif()
  list(APPEND switches_${name} ${switch})
  if(options STREQUAL "" OR options STREQUAL "camera")
    continue()
  endif()
  separate_arguments(options UNIX_COMMAND "${options}")
  run_rt("rt render ${scene} ${options}" render ${SOURCE}/stages/${scene}
         -o ${OUT}/frames/${name}.${switch}_cpu.png -q ${options})
endforeach()

set(pages "")
foreach(name ${names})
  list(JOIN switches_${name} "," list)
  list(APPEND pages "${OUT}/pages/${name}.html@${list}")
endforeach()
render_pages(--http ${OUT}/frames ${pages})
if(NOT render_pages_rc EQUAL 0)
  message(FATAL_ERROR "a page failed in Chromium (above)")
endif()

# The scene file with the camera the page's W showed (no file of it refers to another).
function(render_with_page_camera scene name action)
  file(READ ${SOURCE}/stages/${scene} text)
  file(READ ${OUT}/frames/${name}.${action}.camera.json camera)
  string(REGEX REPLACE "^\"camera\": " "" camera "${camera}")
  string(JSON text SET "${text}" camera "${camera}")
  file(WRITE ${OUT}/${name}.${action}.json "${text}")
  run_rt("rt render ${name} with the page's camera" render ${OUT}/${name}.${action}.json
         -o ${OUT}/frames/${name}.${action}_cpu.png -q)
endfunction()

# The metric of stages/09-gpu/tests/conformance_test.cpp; and the switch must change the frame.
set(failed "")
foreach(case ${CASES})
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 scene)
  list(GET parts 1 switch)
  list(LENGTH parts n)
  get_filename_component(name ${scene} NAME_WE)
  set(options "")
  if(n GREATER 2)
    list(GET parts 2 options)
  endif()
  if(options STREQUAL "")
    continue()  # checked in the page
  endif()
  if(options STREQUAL "camera")
    render_with_page_camera(${scene} ${name} ${switch})
  endif()
  set(frame ${OUT}/frames/${name}.${switch}.png)
  execute_process(COMMAND ${RT} compare ${frame} ${OUT}/frames/${name}.${switch}_cpu.png
                          --tolerance 2 --max-failing-percent 0.5
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(STRIP "${out}${err}" line)
  string(REPLACE "${OUT}/frames/" "" line "${line}")
  message(STATUS "${line}")
  if(NOT rc EQUAL 0)
    list(APPEND failed "${name}.${switch} (differs from rt render's)")
  endif()
  execute_process(COMMAND ${RT} compare ${frame} ${OUT}/frames/${name}.png --tolerance 2
                  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(rc EQUAL 0)
    list(APPEND failed "${name}.${switch} (it did not change the frame)")
  endif()
endforeach()
if(failed)
  message(FATAL_ERROR "switched in the page: ${failed}")
endif()
list(LENGTH CASES count)
message(STATUS "${count} actions in the page: each frame matches rt render's")
