// For the GPU tests of stages 10 and 11 (stages/10-sampling/tests/gpu_sampling_test.cpp,
// stages/11-path-tracing/tests/gpu_path_test.cpp): a Monte Carlo scene on the GPU gives the same
// pixels in every run, for any batch size and on either headless context. Header-only: only test
// binaries that link rt_gpu_render include it.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>

#include "core/not_implemented.h"
#include "render/gpu/gpu_render.h"

namespace rt::testing {

// Renders `scene` with the default batch (4 samples a dispatch), with 1, with 7 on OSMesa and
// with the default again, and expects the same pixels each time. Stubs would give the same
// magenta every time: no stub may be reached, so that a starter tree fails too.
inline void expect_gpu_deterministic(const PreparedScene& scene) {
    GpuRenderOptions one, seven;
    one.samples_per_dispatch = 1;
    seven.samples_per_dispatch = 7;
    seven.context = GlKind::OsMesa;
    const std::uint64_t stubs_before = stub_calls_total();
    const Image a = render_gpu(scene, RenderMode::Shaded);
    ASSERT_EQ(stub_calls_total(), stubs_before) << "the shader reached a stub";
    const Image b = render_gpu(scene, RenderMode::Shaded, one);
    const Image c = render_gpu(scene, RenderMode::Shaded, seven);
    const Image d = render_gpu(scene, RenderMode::Shaded);
    EXPECT_EQ(a.pixels, b.pixels) << "1 sample a dispatch";
    EXPECT_EQ(a.pixels, c.pixels) << "7 samples a dispatch, OSMesa";
    EXPECT_EQ(a.pixels, d.pixels) << "a second run";
}

}  // namespace rt::testing
