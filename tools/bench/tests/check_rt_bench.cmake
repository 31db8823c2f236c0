# The BVH benchmark's command line (label bench). Never looks at a timing figure: only at exit
# codes and at what the report must contain.
#   cmake -DRT_BENCH=<rt-bench> -DMODE=<run|inject> -DEXPECT_RATIOS=<ON|OFF> -DOUT=<dir>
#         -P check_rt_bench.cmake
# run:    a tiny benchmark, without a subcommand and as `rt-bench bvh`, must exit 0 and print the
#         correctness table, the throughput table (brute force included), the CSV and, when
#         Embree is built in, the ratios line; `rt-bench accuracy` must still be there.
# inject: with the BVH made to answer wrongly on every 7th hit (hidden --inject-error), the run
#         must fail with exit code 2, say which back-ends disagree, and time nothing.
set(small --procedural icosphere --triangles 500 --width 64 --height 48 --repeat 1 --threads 2)

function(run_bench expect_rc)
  execute_process(COMMAND ${RT_BENCH} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc STREQUAL "${expect_rc}")
    message(FATAL_ERROR "rt-bench ${ARGN}: expected exit code ${expect_rc}, got '${rc}'\n"
                        "stdout:\n${out}\nstderr:\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

function(expect text pattern)
  if(NOT text MATCHES "${pattern}")
    message(FATAL_ERROR "expected the output to match '${pattern}', got:\n${text}")
  endif()
endfunction()

function(expect_not text pattern)
  if(text MATCHES "${pattern}")
    message(FATAL_ERROR "expected the output not to match '${pattern}', got:\n${text}")
  endif()
endfunction()

file(MAKE_DIRECTORY ${OUT})
if(MODE STREQUAL "run")
  foreach(subcommand "" "bvh")
    set(csv ${OUT}/bench${subcommand}.csv)
    file(REMOVE ${csv})
    run_bench(0 ${subcommand} ${small} --csv ${csv})
    expect("${out}" "machine: [0-9]+ cores")
    expect("${out}" "mesh: procedural icosphere[^\n]*, [0-9,]+ triangles")
    expect("${out}" "correctness check")
    expect("${out}" "brute-force vs bvh +primary")
    expect("${out}" "back-end +threads +build ms +primary +shadow +diffuse +cpu share")
    expect("${out}" "\n  brute-force +1 ")
    expect("${out}" "\n  bvh +1 +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9]+%\n")
    expect("${out}" "\n  bvh +2 ")
    if(EXPECT_RATIOS)
      expect("${out}" "bvh vs embree +primary")
      expect("${out}" "\n  embree +2 +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9]+%\n")
      expect("${out}" "\nratios bvh/embree, 2 threads: primary [0-9.]+x, shadow [0-9.]+x, diffuse [0-9.]+x throughput; build time [0-9.]+x")
    else()
      expect("${out}" "embree: not built in")
      expect_not("${out}" "ratios bvh/embree")
    endif()
    if(NOT EXISTS ${csv})
      message(FATAL_ERROR "--csv ${csv}: no file written")
    endif()
    file(READ ${csv} csv_text)
    expect("${csv_text}" "^mesh,triangles,backend,threads,measure,rays,best_seconds,mrays_per_s")
    expect("${csv_text}" ",bvh,2,diffuse,[0-9]+,[0-9.]+,[0-9.]+,[0-9.]+,")
  endforeach()
  run_bench(0 accuracy --help)
  expect("${out}" "--cases")
elseif(MODE STREQUAL "inject")
  run_bench(2 ${small} --inject-error 7)
  expect("${err}" "rt-bench: error: [^\n]*disagree on [0-9]+ of [0-9]+ [a-z]+ rays")
  expect("${out}" "TOO MANY")
  expect_not("${out}" "Mrays/s")
  expect_not("${out}" "ratios bvh/embree")
else()
  message(FATAL_ERROR "MODE must be run or inject")
endif()
message(STATUS "rt-bench ${MODE}: as expected")
