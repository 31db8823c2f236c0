// The headless OpenGL context the GPU stage will render through (OSMesa / llvmpipe).
#include <gtest/gtest.h>

#include "gl/headless_context.h"

namespace rt {
namespace {

TEST(GlContext, HeadlessCoreContextCanBeQueried) {
    const GlInfo info = query_headless_gl();
    ASSERT_TRUE(info.ok) << info.error;
    EXPECT_GE(info.major * 10 + info.minor, 43) << "compute shaders need GL 4.3: " << info.version;
    EXPECT_FALSE(info.renderer.empty());
    EXPECT_NE(info.glsl_version.find('4'), std::string::npos) << info.glsl_version;
}

}  // namespace
}  // namespace rt
