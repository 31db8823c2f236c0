# Renders SCENE with 1, 2 and 5 threads and requires byte-identical PNG files.
# Usage: cmake -DRT=<rt> -DSCENE=<scene.json> -DOUT=<dir> -P check_thread_determinism.cmake
file(MAKE_DIRECTORY ${OUT})
foreach(threads 1 2 5)
  execute_process(COMMAND ${RT} render ${SCENE} -o ${OUT}/t${threads}.png --threads ${threads} -q
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "rt render --threads ${threads} failed (${rc})")
  endif()
endforeach()
file(SHA256 ${OUT}/t1.png h1)
foreach(threads 2 5)
  file(SHA256 ${OUT}/t${threads}.png h)
  if(NOT h STREQUAL h1)
    message(FATAL_ERROR "--threads ${threads} gave a different image than --threads 1")
  endif()
endforeach()
message(STATUS "identical for 1, 2 and 5 threads: ${h1}")
