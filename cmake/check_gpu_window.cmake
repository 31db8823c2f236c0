# Stage 09 in a GLFW window under Xvfb: `rt render --gpu --gl window` writes the same PNG, byte for
# byte, as `--gl egl` (the same llvmpipe behind both; the window only brings the context).
# Whatever the shaders compute (a starter tree's stubs give two magenta images), so a framework test.
#   cmake -DRT=<rt> -DSCENE=<scene.json> -DOUT=<dir> -P check_gpu_window.cmake
include(${CMAKE_CURRENT_LIST_DIR}/xvfb.cmake)
rt_xvfb_ready(${OUT})
set(size --width 64 --height 48)
execute_process(
  COMMAND ${XVFB_RUN} -a -s "-screen 0 640x480x24"
          ${RT} render ${SCENE} --gpu --gl window ${size} -o ${OUT}/window.png
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rt render --gpu --gl window failed (${rc}):\n${out}\n${err}")
endif()
if(NOT out MATCHES "gpu: window \\(GLFW\\)" OR NOT out MATCHES "GPU \\(window\\)")
  message(FATAL_ERROR "rt render --gl window did not name the window context:\n${out}")
endif()
execute_process(COMMAND ${RT} render ${SCENE} --gpu --gl egl ${size} -q -o ${OUT}/egl.png
                RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 300)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rt render --gpu --gl egl failed (${rc}):\n${err}")
endif()
file(SHA256 ${OUT}/window.png window)
file(SHA256 ${OUT}/egl.png egl)
if(NOT window STREQUAL egl)
  execute_process(COMMAND ${RT} compare --tolerance 0 ${OUT}/window.png ${OUT}/egl.png
                  OUTPUT_VARIABLE line)
  message(FATAL_ERROR "the window's image differs from EGL's: ${line}")
endif()
string(REGEX MATCH "gpu: window[^\n]*" context "${out}")
message(STATUS "${context}: the same PNG as EGL (${OUT}/window.png)")
