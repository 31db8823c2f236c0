// The OpenGL contexts the GPU stage renders through (EGL, OSMesa / llvmpipe).
#include <gtest/gtest.h>

#include "gpu/gl/gl_context.h"

namespace rt {
namespace {

// The one context interface of the GPU stage (gpu/gl/gl_context.h): both headless kinds give a
// current 4.3+ context with the 16 storage blocks the scene needs.
TEST(GlContext, EglAndOsMesaHaveComputeAndTheLimitsTheShaderNeeds) {
    for (GlKind kind : {GlKind::Egl, GlKind::OsMesa}) {
        std::string error;
        const auto context = GlContext::create(kind, error);
        ASSERT_TRUE(context) << to_string(kind) << ": " << error;
        const GlLimits& l = context->limits();
        EXPECT_GE(l.major * 10 + l.minor, 43) << l.version;
        EXPECT_GE(l.compute_storage_blocks, 16) << context->describe();
        EXPECT_GE(l.group_invocations, 64) << "trace.comp's work group is 8x8";
        EXPECT_NE(context->describe().find(to_string(kind)), std::string::npos);
    }
}

TEST(GlContext, KindsParseByName) {
    EXPECT_EQ(parse_gl_kind("egl"), GlKind::Egl);
    EXPECT_EQ(parse_gl_kind("osmesa"), GlKind::OsMesa);
    EXPECT_EQ(parse_gl_kind("window"), GlKind::Window);
    EXPECT_EQ(parse_gl_kind("vulkan"), std::nullopt);
}

}  // namespace
}  // namespace rt
