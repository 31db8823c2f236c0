// How the build rt-grade came from compiles, passed on to the builds rt-grade makes itself
// (the grading workspace), so they share its compiler cache (cmake/compiler_cache.cmake).
#pragma once

#include <string>

namespace rt::grader {

struct BuildSettings {
    bool werror = false;     // RT_WERROR: the workspace's objects hash like this build's
    std::string ccache_dir;  // RT_CCACHE_DIR, or "" when this build compiles without ccache
};
const BuildSettings& this_build();

}  // namespace rt::grader
