# A compiler cache shared by the builds of one CI run (or of one student's machine): the main
# build, the grader's workspace (grader/workspace/), the starter tree and its workspace
# (grader/tests/check_starter_tree.sh) compile the same framework and tests from copies of the
# same files in different folders. ccache's base_dir turns each tree's absolute paths into paths
# relative to the build folder, so a copy laid out as SOURCE/ and SOURCE/build (every tree here
# is) hashes like the original, and -fmacro-prefix-map makes __FILE__ the same in every copy
# (and the stub messages' paths short). The cache starts empty in a clean build folder: it never
# carries results from one checkout to another unless RT_CCACHE_DIR says so.
#
# Only trusted builds use it. The students' files (rt_stages) compile without it: the grader
# replays their compile commands in its sandbox, which must neither see nor write the cache.
find_program(RT_CCACHE_PROGRAM ccache)
find_program(RT_ENV_PROGRAM env)
if(RT_CCACHE_PROGRAM AND RT_ENV_PROGRAM AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(rt_ccache_default ON)
else()
  set(rt_ccache_default OFF)
endif()
option(RT_CCACHE "Compile through ccache, shared by the nested builds of the grader and CI"
       ${rt_ccache_default})
set(RT_CCACHE_DIR "${CMAKE_BINARY_DIR}/ccache" CACHE PATH
    "The compiler cache folder (nested builds are given the outer build's)")

# The deepest folder holding both the sources and the build folder.
function(rt_common_parent out a b)
  cmake_path(GET a ROOT_PATH root)
  set(common "${a}")
  while(NOT common STREQUAL root)
    cmake_path(IS_PREFIX common "${b}" NORMALIZE inside)
    if(inside)
      break()
    endif()
    cmake_path(GET common PARENT_PATH common)
  endwhile()
  set(${out} "${common}" PARENT_SCOPE)
endfunction()

# __FILE__ relative to the tree in every build (ccache or not), so a stub names
# "stages/01-camera-rays/camera_rays.cpp" wherever the tree lives.
add_compile_options("-fmacro-prefix-map=${PROJECT_SOURCE_DIR}/=")

if(RT_CCACHE)
  if(NOT RT_CCACHE_PROGRAM)
    message(FATAL_ERROR "RT_CCACHE is ON but ccache is not installed: run scripts/install-deps.sh "
                        "or configure with -DRT_CCACHE=OFF")
  endif()
  rt_common_parent(rt_ccache_base "${PROJECT_SOURCE_DIR}" "${PROJECT_BINARY_DIR}")
  # pcg_extras.hpp expands __DATE__ and __TIME__ (for a seed this project never uses).
  # time_macros lets the direct mode cache such files; SOURCE_DATE_EPOCH (honoured by GCC, as in
  # reproducible builds) fixes the expanded values, so the preprocessed mode, the only one that
  # can match a unity batch of another tree (their text holds absolute paths), matches too.
  set(CMAKE_CXX_COMPILER_LAUNCHER
      ${RT_ENV_PROGRAM} "CCACHE_DIR=${RT_CCACHE_DIR}" "CCACHE_BASEDIR=${rt_ccache_base}"
      CCACHE_SLOPPINESS=time_macros SOURCE_DATE_EPOCH=0 ${RT_CCACHE_PROGRAM})
  set(CMAKE_C_COMPILER_LAUNCHER ${CMAKE_CXX_COMPILER_LAUNCHER})
endif()
