# Runs `rt render` on every malformed scene in DIR: each must exit with code 1 (not a crash) and
# print exactly one line of the form "<file>:<line>:<col>: error: ..." (and "error:" only once).
# Usage: cmake -DRT=<rt> -DDIR=<bad_scenes> -DOUT=<dir> -P check_bad_scenes.cmake
include(${CMAKE_CURRENT_LIST_DIR}/render_one_line_error.cmake)
file(GLOB scenes ${DIR}/*.json)
list(LENGTH scenes count)
require_cases(${count} 15 "malformed scenes in ${DIR}")
set(failures "")
foreach(scene ${scenes})
  render_one_line_error(${scene} err problem)
  get_filename_component(name ${scene} NAME)
  if(NOT problem STREQUAL "")
    string(APPEND failures "\n  ${name}: ${problem}")
  elseif(NOT err MATCHES "^[^\n]*${name}:[0-9]+:[0-9]+: error: ")
    string(APPEND failures "\n  ${name}: not of the form file:line:col: error: ...: ${err}")
  elseif(err MATCHES "error: .*error: ")  # a reader's own message embedded whole
    string(APPEND failures "\n  ${name}: says error twice: ${err}")
  else()
    message(STATUS "${err}")
  endif()
endforeach()
report_cases("${failures}" "malformed scenes"
  "${count} malformed scenes, each a one-line file:line:col error with exit code 1")
