# Every C++ file of the course tree is in .clang-format's form (CI runs this as Format.ClangFormat).
#   cmake -DSOURCE=<tree> [-DCLANG_FORMAT=clang-format] -P check_format.cmake
# Fix: clang-format -i FILE (or every file: git ls-files '*.cpp' '*.h' | xargs clang-format -i).
if(NOT CLANG_FORMAT)
  find_program(CLANG_FORMAT clang-format REQUIRED)
endif()
file(GLOB_RECURSE files RELATIVE ${SOURCE}
     ${SOURCE}/framework/*.cpp ${SOURCE}/framework/*.h ${SOURCE}/stages/*.cpp ${SOURCE}/stages/*.h
     ${SOURCE}/grader/*.cpp ${SOURCE}/grader/*.h ${SOURCE}/tools/*.cpp ${SOURCE}/tools/*.h
     ${SOURCE}/scripts/*.cpp)
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${files}
                WORKING_DIRECTORY ${SOURCE} RESULT_VARIABLE status ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  string(REGEX MATCHALL "[^\n]*: error: code should be clang-formatted[^\n]*" lines "${errors}")
  list(JOIN lines "\n" text)
  message(FATAL_ERROR "${text}\nnot in clang-format's form: run clang-format -i on the files above")
endif()
list(LENGTH files count)
message(STATUS "clang-format: ${count} files in form")
