#include "workspace/build_settings.h"

namespace rt::grader {

const BuildSettings& this_build() {
    static const BuildSettings settings{RT_BUILD_WERROR != 0, RT_BUILD_CCACHE_DIR};
    return settings;
}

}  // namespace rt::grader
