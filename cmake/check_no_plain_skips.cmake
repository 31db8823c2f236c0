# Format.NoPlainSkips: no test calls GTEST_SKIP() itself. A skip is for a starter tree only, and
# RT_SKIP_IN_STARTER_TREE() (framework/testing/skip.h) makes it a failure in the instructor tree;
# a plain GTEST_SKIP() would let a test that never ran pass CI unseen.
#   cmake -DSOURCE=<tree> -P check_no_plain_skips.cmake
file(GLOB_RECURSE sources ${SOURCE}/framework/*.cpp ${SOURCE}/framework/*.h ${SOURCE}/stages/*.cpp
     ${SOURCE}/stages/*.h ${SOURCE}/grader/*.cpp ${SOURCE}/grader/*.h ${SOURCE}/tools/*.cpp
     ${SOURCE}/tools/*.h)
list(FILTER sources EXCLUDE REGEX "/framework/testing/skip\\.h$|/node_modules/")
set(found "")
foreach(source ${sources})
  file(STRINGS ${source} lines REGEX "GTEST_SKIP")
  foreach(line ${lines})
    string(STRIP "${line}" line)
    string(APPEND found "\n  ${source}: ${line}")
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "GTEST_SKIP() used directly; use RT_SKIP_IN_STARTER_TREE() "
                      "(framework/testing/skip.h), which fails in the instructor tree:${found}")
endif()
list(LENGTH sources count)
message(STATUS "${count} files: every skip goes through RT_SKIP_IN_STARTER_TREE()")
