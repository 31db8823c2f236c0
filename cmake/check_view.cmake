# The viewer under Xvfb (framework/view/): a scripted session opens the window, waits for the
# refined frame, toggles settings and clicks a pixel; its renders must equal `rt render` with the
# same flags (the grader's metric, tolerance 0), the click must draw the ray tree.
#   cmake -DRT=<rt> -DSCENE=<scene.json> -DSCRIPT=<session.txt> -DOUT=<dir> -P check_view.cmake
find_program(XVFB_RUN xvfb-run)
if(NOT XVFB_RUN)
  message("SKIPPED: xvfb-run is missing; scripts/install-deps.sh installs it (package xvfb)")
  return()
endif()
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(
  COMMAND ${XVFB_RUN} -a -s "-screen 0 1600x1000x24"
          ${RT} view ${SCENE} --script ${SCRIPT} --out ${OUT}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 900)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rt view --script failed (${rc}):\n${out}\n${err}")
endif()
foreach(name 01-first-refined 02-shadows-off 03-ray-tree 04-normals 05-orbit-zoom 06-difference
             screenshot-001 render-default display-ray-tree)
  if(NOT EXISTS ${OUT}/${name}.png)
    message(FATAL_ERROR "the session did not write ${OUT}/${name}.png")
  endif()
endforeach()

function(cli_render name)
  execute_process(COMMAND ${RT} render ${SCENE} -q -o ${OUT}/cli-${name}.png ${ARGN}
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "rt render ${ARGN} failed: ${err}")
  endif()
endfunction()

# Runs `rt compare --tolerance 0 A B`; sets <failing> to its failing pixel count.
function(compare a b failing)
  execute_process(COMMAND ${RT} compare --tolerance 0 ${OUT}/${a}.png ${OUT}/${b}.png
                  OUTPUT_VARIABLE line ERROR_VARIABLE err)
  if(NOT line MATCHES ": (match|MISMATCH): ([0-9]+) failing pixels")
    message(FATAL_ERROR "rt compare ${a} ${b}: ${line}${err}")
  endif()
  set(${failing} ${CMAKE_MATCH_2} PARENT_SCOPE)
  message(STATUS "${line}")
endfunction()

function(expect_same a b)
  compare(${a} ${b} failing)
  if(NOT failing EQUAL 0)
    message(FATAL_ERROR "${a} differs from ${b} in ${failing} pixels: the viewer's toggle must "
                        "render what rt render renders with the same flag")
  endif()
endfunction()

cli_render(default)
cli_render(shadows-off --shadows off)
cli_render(shadows-off-depth1 --shadows off --max-depth 1)
cli_render(normals --mode normals)
expect_same(render-default cli-default)
expect_same(render-shadows-off cli-shadows-off)
expect_same(render-shadows-off-depth1 cli-shadows-off-depth1)
expect_same(render-normals cli-normals)
# The toggles changed the image at all.
compare(render-default render-shadows-off shadow_pixels)
if(shadow_pixels LESS 100)
  message(FATAL_ERROR "shadows off changed only ${shadow_pixels} pixels")
endif()
# The click drew the ray tree over the render.
compare(display-ray-tree render-shadows-off overlay_pixels)
if(overlay_pixels LESS 20)
  message(FATAL_ERROR "the click drew only ${overlay_pixels} overlay pixels")
endif()
message(STATUS "viewer: shadows off changed ${shadow_pixels} pixels, the ray tree drew "
               "${overlay_pixels}; screenshots in ${OUT}")
