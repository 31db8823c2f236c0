// Stage 09 conformance: the GPU port renders every scene of stages 01-08 as the CPU renderer does.
// Both compute in float (the release preset's Real), but not the same instructions: llvmpipe
// vectorises sqrt, pow, atan and may order sums differently, and a ray grazing a silhouette can
// flip. So an image passes when at most 0.5 % of its pixels differ by more than 2 steps of 8-bit
// sRGB in some channel (images of 64 pixels across: llvmpipe runs a few million rays a second).
// The scenes are listed from the tree, so a scene added to stages 01-08 is checked too; one the
// GPU port could not draw in its own mode would be listed in kGpuLimits with the reason, checked
// to fail with that reason, and compared in a mode the port has instead.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "image/compare.h"
#include "image/image.h"
#include "render/accelerate.h"
#include "render/gpu/gpu_render.h"
#include "render/prepare.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "testing/stage_test.h"
#include "testing/temp_dir.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

// Scenes whose own mode has no GPU port: the reason render_gpu gives, and the mode compared.
struct Limit {
    const char* reason;
    RenderMode instead;
};
const std::map<std::string, Limit> kGpuLimits = {};  // none today: every mode has a port

// Every scene file of stages 01-08, relative to stages/, in order.
std::vector<std::string> all_scenes() {
    std::vector<std::string> scenes;
    for (const fs::directory_entry& stage :
         fs::directory_iterator(::rt::testing::source_dir() / "stages")) {
        const std::string name = stage.path().filename().string();
        if (name < "01" || name >= "09" || !fs::is_directory(stage.path() / "scenes")) continue;
        for (const fs::directory_entry& f : fs::directory_iterator(stage.path() / "scenes"))
            if (f.path().extension() == ".json")
                scenes.push_back(name + "/scenes/" + f.path().filename().string());
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

class Conformance : public ::rt::testing::StageTest,
                    public ::testing::WithParamInterface<std::string> {};

PreparedScene small_scene(const std::string& relative) {
    Scene scene = load_scene(::rt::testing::source_dir() / "stages" / relative);
    const int height = std::max(1, int(std::lround(64.0 * scene.image.height / scene.image.width)));
    return prepare_scene(std::move(scene), {.width = 64, .height = height});
}

// How to render the scene of a failure at its own size: a scene file of the tree with `rt render`;
// a scene made by a test (made_scene below) has its text in this file.
std::string how_to_see_whole(const PreparedScene& scene, RenderMode mode,
                             const GpuRenderOptions& options) {
    const fs::path file = fs::path(scene.source).lexically_relative(::rt::testing::source_dir());
    if (file.empty() || *file.begin() == "..")
        return "the scene is made by the test: its text is in "
               "stages/09-gpu/tests/conformance_test.cpp";
    return "the scene whole: build/bin/rt render " + file.string() + " --mode " + to_string(mode) +
           " --gpu" + (options.uber ? " --uber" : "") +
           " -o gpu.png, then without --gpu for the CPU's";
}

// The GPU image of `scene` in `mode` against the CPU's, under the metric above. A failure keeps
// both images and their difference, and says how to see the scene whole.
void expect_gpu_matches_cpu(const PreparedScene& scene, RenderMode mode, const std::string& what,
                            const GpuRenderOptions& options = {}) {
    const Image8 cpu = to_image8(render(scene, mode));
    const Image8 gpu = to_image8(render_gpu(scene, mode, options));
    CompareOptions compare;
    compare.tolerance = 2;
    compare.max_failing_percent = 0.5;
    const CompareResult r = compare_images(gpu, cpu, compare);
    if (r.passed) return;
    const std::string name = fs::path(scene.source).stem().string() + (options.uber ? "-uber" : "");
    std::vector<::rt::testing::KeptImage> kept = {{"GPU (yours)", name + ".gpu.png", &gpu},
                                                  {"CPU", name + ".cpu.png", &cpu}};
    if (r.size_matches) kept.push_back({"difference", name + ".diff.png", &r.heat_map});
    ADD_FAILURE() << what << " (" << to_string(mode) << ", GPU against CPU): " << r.summary()
                  << ::rt::testing::keep_failure_images("09-gpu", kept) << "\n  "
                  << how_to_see_whole(scene, mode, options);
}

TEST_P(Conformance, GpuMatchesCpu) {
    const std::string& file = GetParam();
    const PreparedScene scene = small_scene(file);
    RenderMode mode = scene.mode;
    if (const auto limit = kGpuLimits.find(file); limit != kGpuLimits.end()) {
        try {
            render_gpu(scene, mode);
            ADD_FAILURE() << file << ": listed as a GPU limit (" << limit->second.reason
                          << "), yet the GPU rendered it: remove it from kGpuLimits";
        } catch (const GpuError& e) {
            EXPECT_NE(std::string(e.what()).find(limit->second.reason), std::string::npos)
                << e.what();
        }
        mode = limit->second.instead;
        std::printf("%s: mode %s not on the GPU (%s); compared in mode %s instead\n", file.c_str(),
                    to_string(scene.mode), limit->second.reason, to_string(mode));
    }
    expect_gpu_matches_cpu(scene, mode, file);
}

// Instances on the GPU (render/gpu/flatten_instances.h): a box turned by 30 degrees is drawn as
// its 12 triangles in world space, and must look as the CPU's two-level traversal sees it.
class GpuInstances : public ::rt::testing::StageTest {};  // a stub fails it, as every stage test

TEST_F(GpuInstances, TurnedBoxMatchesTheCpu) {
    Scene scene =
        load_scene(::rt::testing::source_dir() / "framework/tests/scenes/rotated_box.json");
    ASSERT_EQ(scene.instances.size(), 1u);
    const PreparedScene prepared = prepare_scene(std::move(scene));
    for (RenderMode mode : {RenderMode::Normals, RenderMode::Depth, RenderMode::Shaded})
        expect_gpu_matches_cpu(prepared, mode, "rotated_box.json (an instance)");
}

// The uber shader (every HAS_ defined, what the scene has decided at run time) on scenes that
// lack some features: it must not use what is not there (a BVH, shadows, vertex normals).
class UberConformance : public Conformance {};

TEST_P(UberConformance, GpuMatchesCpu) {
    const PreparedScene scene = small_scene(GetParam());
    GpuRenderOptions uber;
    uber.uber = true;
    expect_gpu_matches_cpu(scene, scene.mode, GetParam() + " with --uber", uber);
}

std::string case_name(const ::testing::TestParamInfo<std::string>& info) {
    return fs::path(info.param).stem().string();
}

INSTANTIATE_TEST_SUITE_P(Scenes, Conformance, ::testing::ValuesIn(all_scenes()), case_name);
INSTANTIATE_TEST_SUITE_P(Scenes, UberConformance,
                         ::testing::Values("07-textures/scenes/textured_whitted.json"), case_name);
// The same uber shader on more scenes. Not graded (grading.json): llvmpipe takes about 7 s of CPU
// to compile it, again in every test process of a grading (the sandbox keeps no shader cache).
INSTANTIATE_TEST_SUITE_P(Ungraded, UberConformance,
                         ::testing::Values("05-recursion/scenes/whitted.json",
                                           "06-bvh/scenes/mesh_garden.json",
                                           "08-environment/scenes/glass.json"),
                         case_name);

// A scene made for one test: its text, and the files it names, written by `write_files` into a
// folder of its own (removed once the scene is loaded).
PreparedScene made_scene(const std::string& name, const std::string& text,
                         const std::function<void(const fs::path& dir)>& write_files = {}) {
    const ::rt::testing::TempDir dir("stage09-" + name);
    if (write_files) write_files(dir.path());
    return prepare_scene(parse_scene(text, name + ".json", dir.path()));
}

// Blinn-Phong's clamp, which no scene reaches (N.V > 0 and N.L > 0 give N.H > 0): vertex
// normals leaning 80 degrees away from a viewer 60 degrees off the quad's axis, lit from the
// front, so N.L > 0 and N.H < 0.
RT_TEST_SUITE(GpuShade, "direct-light-and-shadows");

TEST_F(GpuShade, SpecularClampedWhereTheHalfVectorLeansAway) {
    const PreparedScene scene = made_scene("lean", R"({
  "camera": {"eye": [-3.4641, 0, 2], "look_at": [0, 0, 0], "fov": 40},
  "image": {"width": 64, "height": 64},
  "render": {"mode": "shaded", "shadows": false},
  "ambient_light": [0.1, 0.1, 0.1],
  "materials": [{"name": "shiny", "ambient": [1, 1, 1], "diffuse": [0.5, 0.5, 0.5],
                 "specular": [1, 1, 1], "shininess": 3}],
  "surfaces": [{"type": "mesh", "file": "lean.obj", "material": "shiny"}],
  "lights": [{"type": "directional", "direction": [0, -0.6, -0.8], "intensity": [1, 1, 1]}]
})",
                                           [](const fs::path& dir) {
                                               std::ofstream(dir / "lean.obj")
                                                   << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                                      "vn 0.98481 0 0.17365\n"
                                                      "f 1//1 2//1 3//1\nf 1//1 3//1 4//1\n";
                                           });
    expect_gpu_matches_cpu(scene, RenderMode::Shaded,
                           "vertex normals leaning away from the viewer, lit from the front "
                           "(N.L > 0, N.H < 0): the specular term is k_s max(0, N.H)^n_s; clamp "
                           "N.H at 0 before pow(), whose negative base is undefined in GLSL");
}

// A point light between a floor and a ceiling: the ceiling lies beyond the light, seen from the
// floor, and must cast no shadow on it.
TEST_F(GpuShade, PointLightShadowRayStopsAtTheLight) {
    const PreparedScene scene = made_scene("beyond", R"({
  "camera": {"eye": [0, 1.5, 4], "look_at": [0, 0, 0], "fov": 60},
  "image": {"width": 48, "height": 36},
  "render": {"mode": "shaded", "max_depth": 0, "shadows": true},
  "ambient_light": [0.1, 0.1, 0.1],
  "materials": [{"name": "chalk", "ambient": [0.5, 0.5, 0.5], "diffuse": [0.8, 0.8, 0.8]}],
  "surfaces": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "chalk"},
               {"type": "box", "min": [-6, 3, -6], "max": [6, 3.2, 6], "material": "chalk"}],
  "lights": [{"type": "point", "position": [0, 2, 0], "intensity": [8, 8, 8]}]
})");
    expect_gpu_matches_cpu(scene, RenderMode::Shaded,
                           "a point light under a ceiling, seen from the floor: the shadow ray "
                           "of a point light ends at the light (its t_range stops at the "
                           "distance to the light), so the ceiling beyond the light casts no "
                           "shadow");
}

// Fresnel's weights alone: a glass ball in front of a bright wall, on a dark background. The
// wall seen through the ball gets the refraction's weight 1 - R; the reflection sees the dark.
RT_TEST_SUITE(GpuRecursion, "reflection-and-refraction");

TEST_F(GpuRecursion, SchlickWeightsAsOnTheCpu) {
    const PreparedScene scene = made_scene("schlick", R"({
  "camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0], "fov": 40},
  "image": {"width": 48, "height": 48},
  "render": {"mode": "shaded", "max_depth": 3, "shadows": false, "fresnel": true},
  "background": [0.02, 0.02, 0.02],
  "ambient_light": [0.2, 0.2, 0.2],
  "materials": [
    {"name": "glass", "diffuse": [0, 0, 0], "transmissive": [0.9, 0.9, 0.9], "ior": 1.5},
    {"name": "wall", "ambient": [1, 0.9, 0.6], "diffuse": [0.8, 0.7, 0.5]}
  ],
  "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass"},
               {"type": "box", "min": [-3, -3, -3], "max": [3, 3, -2.8], "material": "wall"}],
  "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": [0.8, 0.8, 0.8]}]
})");
    expect_gpu_matches_cpu(scene, RenderMode::Shaded,
                           "a glass ball (ior 1.5) before a bright wall, Fresnel on: Schlick's "
                           "R = R0 + (1 - R0)(1 - cos)^5 with R0 = ((n1 - n2) / (n1 + n2))^2, "
                           "squared, so never negative; the reflection gets R, the refraction "
                           "1 - R");
}

// Three quads one behind the other in one mesh, listed near to far: the nearest hit through the
// tree is the near quad's, whatever the order the leaves and their primitives are tested in.
RT_TEST_SUITE(GpuBvh, "bvh-traversal");

TEST_F(GpuBvh, NearestHitOfQuadsOneBehindTheOther) {
    const PreparedScene scene = made_scene("layers", R"({
  "camera": {"eye": [0.4, 0.3, 4], "look_at": [0, 0, 0], "fov": 40},
  "image": {"width": 48, "height": 48},
  "render": {"mode": "primitive", "accelerator": "bvh"},
  "materials": [{"name": "chalk", "diffuse": [0.8, 0.8, 0.8]}],
  "surfaces": [{"type": "mesh", "file": "layers.obj", "material": "chalk"}]
})",
                                           [](const fs::path& dir) {
                                               std::ofstream obj(dir / "layers.obj");
                                               for (const char* z : {"0", "-0.5", "-1"})
                                                   obj << "v -1 -1 " << z << "\nv 1 -1 " << z
                                                       << "\nv 1 1 " << z << "\nv -1 1 " << z
                                                       << "\n";
                                               obj << "f 1 2 3\nf 1 3 4\nf 5 6 7\nf 5 7 8\n"
                                                      "f 9 10 11\nf 9 11 12\n";
                                           });
    expect_gpu_matches_cpu(scene, RenderMode::PrimitiveId,
                           "three quads one behind the other, each pixel's primitive: the "
                           "nearest hit through the BVH shrinks t_range.max to each hit it "
                           "finds, so a primitive or subtree tested later counts only when it "
                           "is nearer");
}

// The environment lookup alone, on a lat-long image whose red is u and whose green is v: a
// wrong longitude or a wrong turn changes every pixel's colour.
RT_TEST_SUITE(GpuEnvironment, "environment-maps");

PreparedScene uv_sky(double rotate_y) {
    return made_scene(rotate_y == 0 ? "uv_sky" : "uv_sky_turned",
                      R"({
  "camera": {"eye": [0, 0, 0], "look_at": [1, 0.3, 0.4], "fov": 90},
  "image": {"width": 48, "height": 32},
  "render": {"mode": "shaded", "max_depth": 0},
  "environment": {"latlong": "uv.png", "rotate_y": )" +
                          std::to_string(rotate_y) + R"(}
})",
                      [](const fs::path& dir) {
                          Image8 uv{64, 32, std::vector<std::uint8_t>(64 * 32 * 3)};
                          for (int y = 0; y < uv.height; ++y)
                              for (int x = 0; x < uv.width; ++x) {
                                  std::uint8_t* p = uv.at(x, y);
                                  p[0] = std::uint8_t(255 * x / (uv.width - 1));
                                  p[1] = std::uint8_t(255 * y / (uv.height - 1));
                                  p[2] = 80;
                              }
                          write_image8(uv, dir / "uv.png");
                      });
}

TEST_F(GpuEnvironment, LatLongLookupSeenFromInside) {
    expect_gpu_matches_cpu(uv_sky(0), RenderMode::Shaded,
                           "a lat-long sky whose red is u and green v, rotate_y 0: the "
                           "longitude seen from inside, u = atan(-d.x, d.z) / (2 pi) + 0.5, and "
                           "the latitude v = acos(d.y) / pi");
}

TEST_F(GpuEnvironment, RotateYTurnsTheSky) {
    expect_gpu_matches_cpu(uv_sky(90), RenderMode::Shaded,
                           "the same sky with rotate_y 90 (if LatLongLookupSeenFromInside "
                           "passes, the lookup is right and the turn is not): the environment "
                           "turns by +rotate_y about +y, so the lookup turns the direction by "
                           "-rotate_y first");
}

// The camera alone, named: the ray through the top row's middle, decoded from the directions
// view (display value 0.5 (d + 1)), makes half the vertical field of view with -w.
RT_TEST_SUITE(GpuCamera, "camera-rays");

TEST_F(GpuCamera, VerticalFieldOfViewAsOnTheCpu) {
    const PreparedScene scene = small_scene("01-camera-rays/scenes/perspective_directions.json");
    const auto degrees = [&](const Image& image) {
        const Color c = image.pixels[std::size_t(image.width / 2)];  // row 0: the top
        const Vec3 d(2 * linear_to_srgb(c.r) - 1, 2 * linear_to_srgb(c.g) - 1,
                     2 * linear_to_srgb(c.b) - 1);
        const Real cosine =
            std::clamp(glm::dot(glm::normalize(d), -scene.camera.w), Real(-1), Real(1));
        return double(glm::degrees(std::acos(cosine)));
    };
    const double gpu = degrees(render_gpu(scene, RenderMode::Directions));
    const double cpu = degrees(render(scene, RenderMode::Directions));
    EXPECT_NEAR(gpu, cpu, 1.0)
        << "the camera ray through the middle of the top row makes " << gpu
        << " degrees with the view direction -w, the CPU's " << cpu
        << ": half the vertical field of view (" << scene.camera.vertical_fov_degrees
        << " degrees), half_height = tan(radians(fov) / 2); GLSL's tan takes radians";
}

// The two headless contexts run the student's shaders to the same image.
RT_TEST_SUITE(GpuContexts, "what-the-tests-check");

TEST_F(GpuContexts, EglAndOsMesaRenderTheSameImage) {
    const PreparedScene scene = prepare_scene(
        load_scene(::rt::testing::source_dir() / "stages/04-shadows/scenes/shadows.json"),
        {.width = 32, .height = 24});
    GpuRenderOptions osmesa;
    osmesa.context = GlKind::OsMesa;
    const Image a = render_gpu(scene, RenderMode::Shaded);
    const Image b = render_gpu(scene, RenderMode::Shaded, osmesa);
    EXPECT_EQ(a.pixels, b.pixels);
}

}  // namespace
}  // namespace rt
