// Stage 09 conformance: the GPU port renders the scenes of stages 02-06 as the CPU renderer does.
// Both compute in float (the release preset's Real), but not the same instructions: llvmpipe
// vectorises sqrt, pow, atan and may order sums differently, and a ray grazing a silhouette can
// flip. So an image passes when at most 0.5 % of its pixels differ by more than 2 steps of 8-bit
// sRGB in some channel (images of 64 pixels across: llvmpipe runs a few million rays a second).
#include <cmath>
#include <string>

#include "image/compare.h"
#include "render/accelerate.h"
#include "render/gpu_render.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

struct Case {
    const char* scene;  // relative to stages/
    const char* mode;   // "" the scene's own, else a debug mode the GPU port has
};

const Case kCases[] = {
    {"02-intersections/scenes/spheres_normals.json", ""},
    {"02-intersections/scenes/triangles_normals.json", ""},
    {"02-intersections/scenes/boxes_primitive_ids.json", "normals"},
    {"02-intersections/scenes/plane_depth.json", ""},
    {"02-intersections/scenes/orthographic_mixed.json", ""},
    {"02-intersections/scenes/mesh_normals.json", "directions"},
    {"03-blinn-phong/scenes/direct_light.json", ""},
    {"03-blinn-phong/scenes/attenuation.json", ""},
    {"03-blinn-phong/scenes/specular_only.json", ""},
    {"04-shadows/scenes/shadows.json", ""},
    {"04-shadows/scenes/glass_shadows.json", ""},
    {"04-shadows/scenes/cornell_box.json", ""},
    {"05-recursion/scenes/whitted.json", ""},
    {"05-recursion/scenes/refraction.json", ""},
    {"05-recursion/scenes/mirror_box.json", ""},
    {"05-recursion/scenes/transparent_cube.json", ""},
    {"06-bvh/scenes/mesh_garden.json", ""},
};

class Conformance : public ::rt::testing::StageTest, public ::testing::WithParamInterface<Case> {};

RenderMode mode_named(const std::string& name, RenderMode fallback) {
    if (name == "normals") return RenderMode::Normals;
    if (name == "directions") return RenderMode::Directions;
    if (name == "depth") return RenderMode::Depth;
    return fallback;
}

TEST_P(Conformance, GpuMatchesCpu) {
    const Case& c = GetParam();
    Scene scene = load_scene(::rt::testing::source_dir() / "stages" / c.scene);
    const int width = 64;
    scene.image.height =
        std::max(1, int(std::lround(64.0 * scene.image.height / scene.image.width)));
    scene.image.width = width;
    build_acceleration(scene);
    const RenderMode mode = mode_named(c.mode, scene.mode);
    const Image cpu = render(scene, mode);
    const Image gpu = render_gpu(scene, mode);
    CompareOptions options;
    options.tolerance = 2;
    options.max_failing_percent = 0.5;
    const CompareResult r = compare_images(to_image8(gpu), to_image8(cpu), options);
    EXPECT_TRUE(r.passed) << c.scene << " (" << to_string(mode)
                          << ", GPU against CPU): " << r.summary();
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) {
    std::string name = info.param.scene;
    name = name.substr(name.rfind('/') + 1);
    name = name.substr(0, name.find('.'));
    return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, Conformance, ::testing::ValuesIn(kCases), case_name);

// The two headless contexts run the student's shaders to the same image.
RT_TEST_SUITE(GpuContexts);

TEST_F(GpuContexts, EglAndOsMesaRenderTheSameImage) {
    Scene scene = load_scene(::rt::testing::source_dir() / "stages/04-shadows/scenes/shadows.json");
    scene.image.width = 32, scene.image.height = 24;
    build_acceleration(scene);
    GpuRenderOptions osmesa;
    osmesa.context = GlKind::OsMesa;
    const Image a = render_gpu(scene, RenderMode::Shaded);
    const Image b = render_gpu(scene, RenderMode::Shaded, osmesa);
    EXPECT_EQ(a.pixels, b.pixels);
}

}  // namespace
}  // namespace rt
