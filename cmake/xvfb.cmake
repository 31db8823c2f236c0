# For the check scripts that need an X server (include(), then rt_xvfb_ready(<out dir>)): sets
# XVFB_RUN and makes an empty <out dir>, or says SKIPPED (the tests' SKIP_REGULAR_EXPRESSION) and
# ends the calling script (a macro, so its return() leaves the caller).
macro(rt_xvfb_ready out)
  find_program(XVFB_RUN xvfb-run)
  if(NOT XVFB_RUN)
    message("SKIPPED: xvfb-run is missing; scripts/install-deps.sh installs it (package xvfb)")
    return()
  endif()
  file(REMOVE_RECURSE ${out})
  file(MAKE_DIRECTORY ${out})
endmacro()
