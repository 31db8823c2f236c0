// `rt render --gpu --debug-pixel X,Y` (render/gpu/gpu_debug_pixel.h): the shader's own notes of one
// pixel, and a student's rt_debug(value) with its file and line. Framework tests: they pass
// whatever the student's GLSL computes, or skip where they need it to be right.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "render/accelerate.h"
#include "render/gpu/gpu_debug_pixel.h"
#include "render/gpu/gpu_render.h"
#include "render/prepare.h"
#include "render/ray_tree.h"
#include "scene/scene_loader.h"
#include "student_copy.h"
#include "testing/skip.h"
#include "testing/stage_test.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

using namespace gpu_test;

PreparedScene whitted() {
    return prepare_scene(
        load_scene(::rt::testing::source_dir() / "stages/05-recursion/scenes/whitted.json"));
}

// The notes of one kind, in order.
std::vector<GpuDebugRecord> notes(const GpuPixelProbe& probe, int kind) {
    std::vector<GpuDebugRecord> out;
    for (const GpuDebugRecord& r : probe.records)
        if (r.kind == kind) out.push_back(r);
    return out;
}

int count_rays(const RayNode& node) {
    int n = 1;
    for (const RayNode& child : node.children) n += count_rays(child);
    return n;
}

// Probing a pixel changes no pixel of the image.
TEST(GpuDebugPixel, LeavesTheImageAsItWas) {
    const PreparedScene scene = whitted();
    GpuRenderer renderer;
    const Image plain = renderer.render(scene, RenderMode::Shaded);
    GpuPixelProbe probe;
    probe.x = 100;
    probe.y = 80;
    const Image probed = renderer.render(scene, RenderMode::Shaded, nullptr, &probe);
    EXPECT_EQ(probed.pixels, plain.pixels);
    EXPECT_GT(probe.made, 0);
}

// A glass sphere's pixel: the same rays as the CPU's tree (stage 05's debugger), the same first
// hit, and the pixel's colour. Needs a right stage 09 (and stage 05) to compare.
TEST(GpuDebugPixel, FollowsTheCpuRayTree) {
    const PreparedScene scene = whitted();
    const GpuPixelProbe probe = debug_pixel_gpu(scene, RenderMode::Shaded, 100, 80);
    const std::vector<GpuDebugRecord> pixel = notes(probe, gpu::kDebugPixel);
    ASSERT_EQ(pixel.size(), 1u) << gpu_pixel_text(scene, probe);
    if (pixel[0].value.w == -2)
        RT_SKIP_IN_STARTER_TREE() << "a stub was reached: the course tree runs this test";
    const PixelTree tree = debug_pixel(scene, 100, 80);
    EXPECT_EQ(int(notes(probe, gpu::kDebugRay).size()), count_rays(tree.root))
        << gpu_pixel_text(scene, probe);
    const std::vector<GpuDebugRecord> hits = notes(probe, gpu::kDebugHit);
    ASSERT_FALSE(hits.empty());
    ASSERT_TRUE(tree.root.hit);
    EXPECT_EQ((int(hits[0].value.y) << 28) | int(hits[0].value.z), tree.root.hit_record.primitive);
    EXPECT_NEAR(hits[0].value.x, tree.root.hit_record.t, 1e-3 * tree.root.hit_record.t);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(pixel[0].value[c], tree.color[c], 1e-3);
    const std::string text = gpu_pixel_text(scene, probe);
    EXPECT_NE(text.find("camera ray (depth 0) from (0, 1.4, 7)"), std::string::npos) << text;
    EXPECT_NE(text.find("    refraction ray (depth 1)"), std::string::npos) << text;
}

// rt_debug in the first function every pixel calls (before its stub in a starter tree): each
// value with the student's file, line and that line's text; past the buffer's room, a count.
TEST(GpuDebugPixel, StudentValuesNameTheirFileAndLine) {
    StudentCopy copy("debug-pixel");
    std::string camera = read(copy.dir() / "camera.glsl");
    const std::string head = "Ray perspective_ray(vec2 pixel) {\n";
    const std::size_t at = camera.find(head);
    ASSERT_NE(at, std::string::npos);
    camera.insert(at + head.size(),
                  "    rt_debug(pixel); rt_debug(-70000); rt_debug(pixel.x > 2.0);\n"
                  "    for (int i = 0; i < 600; ++i) rt_debug(float(i));\n");
    write(copy.dir() / "camera.glsl", camera);
    const int line = int(std::count(camera.begin(), camera.begin() + long(at), '\n')) + 2;
    GpuRenderOptions options;
    options.student_dir = copy.dir();
    PreparedScene scene = whitted();
    scene.image.width = 40;
    scene.image.height = 30;
    const GpuPixelProbe probe = debug_pixel_gpu(scene, RenderMode::Shaded, 7, 3, options);
    const std::string text = gpu_pixel_text(scene, probe);
    const std::string where = "rt_debug at " + (copy.dir() / "camera.glsl").string() + ":" +
                              std::to_string(line) + " `rt_debug(pixel); rt_debug(-70000); ";
    EXPECT_NE(text.find(where), std::string::npos) << text.substr(0, 2000);
    EXPECT_NE(text.find("`: (7.5, 3.5)\n"), std::string::npos) << text.substr(0, 2000);
    EXPECT_NE(text.find("`: -70000\n"), std::string::npos) << text.substr(0, 2000);
    EXPECT_NE(text.find("`: true\n"), std::string::npos) << text.substr(0, 2000);
    EXPECT_GT(probe.made, gpu::kDebugCapacity);
    EXPECT_NE(text.find("more notes were made; the first 512 are shown"), std::string::npos);
}

}  // namespace
}  // namespace rt
