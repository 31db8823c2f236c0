# Shared by check_bad_scenes.cmake and check_bad_objs.cmake (included, needs RT and OUT).
# render_one_line_error(<scene> <err> <problem>): runs `rt render <scene>`, which must exit with
# code 1 (not a crash) and print exactly one line. Sets <err> to what it printed (stripped), and
# <problem> to what was wrong, or to "" when both hold.
function(render_one_line_error scene err_var problem_var)
  execute_process(COMMAND ${RT} render ${scene} -o ${OUT}/bad.png -q
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out TIMEOUT 20)
  string(STRIP "${err}" err)
  set(problem "")
  if(NOT rc EQUAL 1)
    set(problem "exit code '${rc}' (expected 1): ${err}")
  elseif(err MATCHES "\n")
    set(problem "more than one line:\n${err}")
  endif()
  set(${err_var} "${err}" PARENT_SCOPE)
  set(${problem_var} "${problem}" PARENT_SCOPE)
endfunction()

# require_cases(<count> <minimum> <what>): stops unless there are at least <minimum> cases
# ("expected at least <minimum> <what>, found <count>"), then makes OUT.
function(require_cases count minimum what)
  if(count LESS minimum)
    message(FATAL_ERROR "expected at least ${minimum} ${what}, found ${count}")
  endif()
  file(MAKE_DIRECTORY ${OUT})
endfunction()

# report_cases(<failures> <what> <summary>): stops with "<what> not reported cleanly:<failures>"
# when there are failures, else prints <summary>.
function(report_cases failures what summary)
  if(failures)
    message(FATAL_ERROR "${what} not reported cleanly:${failures}")
  endif()
  message(STATUS "${summary}")
endfunction()
