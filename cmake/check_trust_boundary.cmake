# The trust boundary in the tree (framework/README.md): only framework/render, framework/apps,
# framework/testing and framework/remote (the judge's proxies and the worker that makes the
# calls) may include the stage API (the declarations of the student functions), so no other
# folder can call student code. The grader links only the other folders (rt_core).
#   cmake -DFRAMEWORK=<framework dir> -P check_trust_boundary.cmake
file(GLOB_RECURSE sources RELATIVE ${FRAMEWORK} ${FRAMEWORK}/*.cpp ${FRAMEWORK}/*.h)
set(violations "")
foreach(source ${sources})
  if(source MATCHES "^(render|apps|testing|stage_api|tests|remote)/")
    continue()
  endif()
  file(STRINGS ${FRAMEWORK}/${source} lines REGEX "#include \"stage_api/")
  if(lines)
    list(APPEND violations "framework/${source}: ${lines}")
  endif()
endforeach()
if(violations)
  list(JOIN violations "\n" text)
  message(FATAL_ERROR "student code reachable from trusted folders (move the caller to "
                      "framework/render/):\n${text}")
endif()
list(LENGTH sources count)
message(STATUS "trust boundary: ${count} framework files checked")
