# The viewer under Xvfb (framework/view/): runs a scripted session, then checks what its comment
# lines promise:
#   # expect NAME = FLAGS...       DIR/NAME.png equals `rt render SCENE FLAGS` (tolerance 0)
#   # expect-differs A B MIN       DIR/A.png and DIR/B.png differ in at least MIN pixels
#   # expect-same A B              DIR/A.png and DIR/B.png are the same image (tolerance 0)
#   # expect-files NAME...         the session wrote DIR/NAME.png
#   # expect-output TEXT           the session printed TEXT
#   # expect-scene FILE NAME       `rt render DIR/FILE` (a scene the session wrote) matches
#                                  DIR/NAME.png under the grader's metric
#   cmake -DRT=<rt> -DSCENE=<scene.json> -DSCRIPT=<session.txt> -DOUT=<dir> -P check_view.cmake
include(${CMAKE_CURRENT_LIST_DIR}/xvfb.cmake)
rt_xvfb_ready(${OUT})
execute_process(
  COMMAND ${XVFB_RUN} -a -s "-screen 0 1920x1080x24"
          ${RT} view ${SCENE} --script ${SCRIPT} --out ${OUT}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 900)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rt view --script failed (${rc}):\n${out}\n${err}")
endif()

# Runs `rt compare --tolerance 0 A B`; sets <failing> to its failing pixel count.
function(compare a b failing)
  execute_process(COMMAND ${RT} compare --tolerance 0 ${OUT}/${a}.png ${OUT}/${b}.png
                  OUTPUT_VARIABLE line ERROR_VARIABLE err)
  if(NOT line MATCHES ": (match|MISMATCH): ([0-9]+) failing pixels")
    message(FATAL_ERROR "rt compare ${a} ${b}: ${line}${err}")
  endif()
  set(${failing} ${CMAKE_MATCH_2} PARENT_SCOPE)
  string(STRIP "${line}" line)
  message(STATUS "${line}")
endfunction()

file(STRINGS ${SCRIPT} lines REGEX "^# expect")
set(checks 0)
foreach(line ${lines})
  math(EXPR checks "${checks} + 1")
  if(line MATCHES "^# expect ([^ ]+) =(.*)$")
    set(name ${CMAKE_MATCH_1})
    separate_arguments(flags UNIX_COMMAND "${CMAKE_MATCH_2}")
    execute_process(COMMAND ${RT} render ${SCENE} -q -o ${OUT}/cli-${name}.png ${flags}
                    RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "rt render ${flags} failed: ${err}")
    endif()
    compare(${name} cli-${name} failing)
    if(NOT failing EQUAL 0)
      message(FATAL_ERROR "${name} differs from rt render ${flags} in ${failing} pixels: the "
                          "viewer's setting must render what the flag renders")
    endif()
  elseif(line MATCHES "^# expect-differs ([^ ]+) ([^ ]+) ([0-9]+)$")
    compare(${CMAKE_MATCH_1} ${CMAKE_MATCH_2} failing)
    if(failing LESS ${CMAKE_MATCH_3})
      message(FATAL_ERROR "${CMAKE_MATCH_1} and ${CMAKE_MATCH_2} differ in ${failing} pixels, "
                          "fewer than ${CMAKE_MATCH_3}")
    endif()
  elseif(line MATCHES "^# expect-same ([^ ]+) ([^ ]+)$")
    compare(${CMAKE_MATCH_1} ${CMAKE_MATCH_2} failing)
    if(NOT failing EQUAL 0)
      message(FATAL_ERROR "${CMAKE_MATCH_1} and ${CMAKE_MATCH_2} differ in ${failing} pixels")
    endif()
  elseif(line MATCHES "^# expect-scene ([^ ]+) ([^ ]+)$")
    set(file ${CMAKE_MATCH_1})
    set(name ${CMAKE_MATCH_2})
    execute_process(COMMAND ${RT} render ${OUT}/${file} -q -o ${OUT}/cli-${file}.png
                    RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "rt render ${OUT}/${file} (written by the session) failed: ${err}")
    endif()
    execute_process(COMMAND ${RT} compare ${OUT}/${name}.png ${OUT}/cli-${file}.png
                    OUTPUT_VARIABLE cmp ERROR_VARIABLE err)
    if(NOT cmp MATCHES ": match: ")
      message(FATAL_ERROR "${file} does not render the view ${name} shows: ${cmp}${err}")
    endif()
    message(STATUS "${file}: ${cmp}")
  elseif(line MATCHES "^# expect-output (.*)$")
    string(FIND "${out}" "${CMAKE_MATCH_1}" at)
    if(at LESS 0)
      message(FATAL_ERROR "the session did not print \"${CMAKE_MATCH_1}\"")
    endif()
  elseif(line MATCHES "^# expect-files (.*)$")
    separate_arguments(names UNIX_COMMAND "${CMAKE_MATCH_1}")
    foreach(name ${names})
      if(NOT EXISTS ${OUT}/${name}.png)
        message(FATAL_ERROR "the session did not write ${OUT}/${name}.png")
      endif()
    endforeach()
  else()
    message(FATAL_ERROR "${SCRIPT}: cannot read the check \"${line}\"")
  endif()
endforeach()
if(checks EQUAL 0)
  message(FATAL_ERROR "${SCRIPT} has no # expect lines")
endif()
message(STATUS "viewer: ${checks} checks passed; screenshots in ${OUT}")
