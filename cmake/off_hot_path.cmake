# rt_off_hot_path(<targets...>): code that is not on a hot path compiles at -O1 in Release:
# command lines, GL set-up and shader text, the grader, and the tests' own code
# (rt_add_gtest). -O1 takes about 40 % less compile time than -O3 (framework_tests' largest
# batch: 18.8 s of CPU at -O3, 11.1 s at -O1), and every CI run compiles this code in the build,
# the grader's workspace, the starter tree and the calibration build. Results do not change:
# with -ffp-contract=off and without -ffast-math, the optimisation level never changes a
# floating-point result. What computes pixels or is timed keeps -O3: rt_core, rt_render, the
# GPU renderer's read-back, the student files (rt_stages), the viewer (its preview and
# accumulation run every frame), the CGAL reference and the benchmarks.
function(rt_off_hot_path)
  foreach(target ${ARGN})
    target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O1>)
  endforeach()
endfunction()
