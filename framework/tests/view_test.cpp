// The viewer's parts that need no window (framework/view/): settings to scenes, camera controls,
// progressive rendering, script checking. View.ScriptedSession runs the window under Xvfb.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <thread>
#include <vector>

#include "camera/camera_moves.h"
#include "core/not_implemented.h"
#include "core/source_dir.h"
#include "render/accelerate.h"
#include "render/gpu/gpu_render.h"
#include "render/prepare.h"
#include "render/ray_tree.h"
#include "render/render.h"
#include "scene/scene_format.h"
#include "scene/scene_loader.h"
#include "view/progressive.h"
#include "view/view_script.h"
#include "view/view_settings.h"

namespace rt::view {
namespace {

namespace fs = std::filesystem;

PreparedScene whitted() {
    return prepare_scene(load_scene(source_dir() / "stages/05-recursion/scenes/whitted.json"));
}

void expect_orthonormal(const Camera& c) {
    EXPECT_NEAR(glm::length(c.u), 1, 1e-5);
    EXPECT_NEAR(glm::length(c.v), 1, 1e-5);
    EXPECT_NEAR(glm::length(c.w), 1, 1e-5);
    EXPECT_NEAR(glm::dot(c.u, c.v), 0, 1e-5);
    EXPECT_NEAR(glm::dot(c.v, c.w), 0, 1e-5);
    EXPECT_NEAR(glm::dot(c.w, c.u), 0, 1e-5);
}

TEST(ViewSettings, TheSceneFilesSettingsGiveTheLoadedSceneBack) {
    const PreparedScene loaded = whitted();
    SceneSource source{Scene(loaded)};
    const PreparedScene made = source.make(source.initial());
    EXPECT_EQ(made.shadows, loaded.shadows);
    EXPECT_EQ(made.max_depth, loaded.max_depth);
    EXPECT_EQ(made.features.describe(), loaded.features.describe());
    EXPECT_EQ(render(made, made.mode).pixels, render(loaded, loaded.mode).pixels);
}

// A lecture shows solved stages: whitted.json's 122 primitives start with stage 06's tree
// (here, in the course tree, it is written); a scene of three spheres starts without one.
TEST(ViewSettings, ABigSceneStartsWithTheTreeASmallOneWithout) {
    SceneSource big{whitted()};
    EXPECT_EQ(big.initial().accelerator, Accelerator::Bvh);
    EXPECT_TRUE(uses_bvh(big.make(big.initial())));
    SceneSource small{load_scene(source_dir() / "stages/03-blinn-phong/scenes/direct_light.json")};
    EXPECT_EQ(small.initial().accelerator, Accelerator::None);
}

void probed_stub() {
    RT_NOT_IMPLEMENTED("stages/06-bvh/README.md#building-the-tree");
}

// The viewer's probe of build_bvh: a stub reached under QuietStubs is counted and reported to
// the probe, and prints nothing; its one message is still printed at its first real use.
TEST(ViewSettings, QuietStubsAreCountedButPrintNothing) {
    const std::uint64_t before = stub_calls_total();
    ::testing::internal::CaptureStderr();
    {
        QuietStubs quiet;
        EXPECT_FALSE(quiet.reached());
        probed_stub();
        EXPECT_TRUE(quiet.reached());
    }
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(stub_calls_total(), before + 1);
    ::testing::internal::CaptureStderr();
    probed_stub();
    EXPECT_NE(::testing::internal::GetCapturedStderr().find("not implemented: probed_stub"),
              std::string::npos);
}

TEST(ViewSettings, ShadowsOffIsWhatTheRendererComputesWithoutShadows) {
    SceneSource source{whitted()};
    ViewSettings settings = source.initial();
    ASSERT_TRUE(settings.shadows) << "whitted.json is expected to ask for shadows";
    ASSERT_EQ(set_by_name(settings, "shadows", "off"), "");
    const PreparedScene made = source.make(settings);
    EXPECT_FALSE(made.features.shadows);  // refresh_features ran: no shadow rays at all
    PreparedScene by_hand = whitted();
    by_hand.shadows = false;
    refresh_features(by_hand);
    EXPECT_EQ(render(made, made.mode).pixels, render(by_hand, by_hand.mode).pixels);
}

// A term or effect off changes the scene the renderer gets, not the picture afterwards: the
// features lose it, and the image is the render of the scene with that coefficient zero.
TEST(ViewSettings, TermsAndEffectsOffAreLeftOutOfTheScene) {
    SceneSource source{whitted()};
    ViewSettings settings = source.initial();
    for (const char* term : {"specular", "reflection", "refraction"})
        ASSERT_EQ(set_by_name(settings, term, "off"), "");
    PreparedScene made = source.make(settings);
    EXPECT_FALSE(made.features.specular);
    EXPECT_FALSE(made.features.reflection);
    EXPECT_FALSE(made.features.refraction);
    made.image = ImageSize{80, 60};
    PreparedScene by_hand = whitted();
    for (Material& m : by_hand.materials) m.specular = m.reflective = m.transmissive = Color(0);
    refresh_features(by_hand);
    by_hand.image = made.image;
    EXPECT_EQ(render(made, made.mode).pixels, render(by_hand, by_hand.mode).pixels);

    SceneSource sky{load_scene(source_dir() / "stages/08-environment/scenes/sky.json")};
    ViewSettings no_sky = sky.initial();
    ASSERT_EQ(set_by_name(no_sky, "environment", "off"), "");
    EXPECT_FALSE(sky.make(no_sky).features.environment);
    EXPECT_TRUE(sky.make(sky.initial()).features.environment);
}

TEST(ViewSettings, BadNamesAndValuesSayWhatIsAccepted) {
    ViewSettings s;
    EXPECT_NE(set_by_name(s, "mode", "shady").find("shaded"), std::string::npos);
    EXPECT_NE(set_by_name(s, "shadows", "maybe").find("on or off"), std::string::npos);
    EXPECT_NE(set_by_name(s, "max-depth", "65").find("0..64"), std::string::npos);
    EXPECT_NE(set_by_name(s, "color", "red").find("settings:"), std::string::npos);
    EXPECT_EQ(set_by_name(s, "filter", "nearest"), "");
    EXPECT_EQ(s.texture_lookup, TextureLookup::Nearest);
}

TEST(ViewCamera, OrbitKeepsTheFrameAndThePivotAndUndoes) {
    const Camera start = whitted().camera;
    Camera c = start;
    const Real distance = 5;
    const Vec3 pivot = c.eye - c.w * distance;
    orbit(c, distance, start.v, 30, 15);
    expect_orthonormal(c);
    EXPECT_NEAR(glm::length(c.eye - pivot), distance, 1e-4);
    EXPECT_NEAR(glm::length(c.eye - c.w * distance - pivot), 0, 1e-4);  // still looks at it
    EXPECT_NEAR(glm::dot(c.u, start.v), 0, 1e-5);                       // no roll
    orbit(c, distance, start.v, 0, -15);
    orbit(c, distance, start.v, -30, 0);
    EXPECT_NEAR(glm::length(c.eye - start.eye), 0, 1e-3);
}

TEST(ViewCamera, OrbitStopsShortOfThePole) {
    Camera c = whitted().camera;
    const Vec3 up = c.v;
    for (int i = 0; i < 20; ++i) orbit(c, 5, up, 0, 20);  // 400 degrees of pitch asked for
    expect_orthonormal(c);
    EXPECT_LT(std::abs(glm::dot(c.w, up)), Real(0.999));
}

TEST(ViewCamera, ZoomMovesTowardThePivotAndPanMovesBoth) {
    Camera c = whitted().camera;
    Real distance = 4;
    const Vec3 pivot = c.eye - c.w * distance;
    zoom(c, distance, Real(0.5));
    EXPECT_NEAR(distance, 2, 1e-6);
    EXPECT_NEAR(glm::length(c.eye - c.w * distance - pivot), 0, 1e-5);
    const Vec3 before = c.eye;
    pan(c, distance, Real(0.25), 0);
    EXPECT_NEAR(glm::dot(c.eye - before, c.v), 0, 1e-6);
    EXPECT_GT(glm::dot(c.eye - before, c.u), 0);
}

TEST(ViewCamera, ProjectionSwitchKeepsThePivotsSizeAndUndoes) {
    Camera c = whitted().camera;
    ASSERT_EQ(c.projection, Projection::Perspective);
    const Real fov = c.vertical_fov_degrees, distance = 5;
    set_projection(c, distance, Projection::Orthographic);
    EXPECT_EQ(c.projection, Projection::Orthographic);
    EXPECT_NEAR(c.view_height, 2 * distance * std::tan(fov * Real(3.14159265358979 / 360)), 1e-4);
    set_projection(c, distance, Projection::Perspective);
    EXPECT_NEAR(c.vertical_fov_degrees, fov, 1e-3);
}

// The viewer's W key: the scene file with the current camera, everything else as it was, in
// rt fmt's form; loading it gives the camera back.
TEST(ViewCamera, WithCameraWritesACameraThatLoadsBack) {
    const fs::path file = source_dir() / "stages/05-recursion/scenes/whitted.json";
    const PreparedScene original = prepare_scene(load_scene(file));
    Camera camera = original.camera;
    orbit(camera, 6, camera.v, 25, 10);
    const std::string text = with_camera(read_scene_text(file), file.string(), camera, 6);
    EXPECT_EQ(canonical_scene_text(text, file.string(), file.parent_path()), text);
    const PreparedScene back = prepare_scene(parse_scene(text, file.string(), file.parent_path()));
    for (const auto& [got, want] :
         {std::pair{back.camera.eye, camera.eye}, std::pair{back.camera.u, camera.u},
          std::pair{back.camera.v, camera.v}, std::pair{back.camera.w, camera.w}})
        EXPECT_NEAR(glm::length(got - want), 0, 1e-4);
    EXPECT_EQ(back.spheres.size(), original.spheres.size());
    EXPECT_EQ(back.materials.size(), original.materials.size());
    EXPECT_EQ(back.lights.size(), original.lights.size());
    set_projection(camera, 6, Projection::Orthographic);
    const PreparedScene ortho = prepare_scene(parse_scene(
        with_camera(text, file.string(), camera, 6), file.string(), file.parent_path()));
    EXPECT_EQ(ortho.camera.projection, Projection::Orthographic);
    EXPECT_NEAR(ortho.camera.view_height, camera.view_height, 1e-4);
    EXPECT_THROW(with_camera("{ not json", "x.json", camera, 6), SceneError);
}

TEST(ViewProgressive, TheRefinedFrameIsTheRenderAndRestartsDropOldWork) {
    const PreparedScene scene = whitted();
    ProgressiveRenderer renderer(2);
    renderer.restart(scene);
    PreparedScene other = scene;
    other.shadows = false;
    refresh_features(other);
    const std::uint64_t generation = renderer.restart(other);
    std::optional<Frame> refined;
    bool seen_new = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!refined && std::chrono::steady_clock::now() < deadline) {
        if (auto frame = renderer.take()) {
            // A pass of the first scene may finish before the restart, never after.
            if (frame->generation != generation) {
                EXPECT_FALSE(seen_new);
            }
            seen_new |= frame->generation == generation;
            EXPECT_EQ(frame->image.width, scene.image.width);  // coarse passes blown up
            if (frame->refined() && frame->generation == generation) refined = std::move(frame);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_TRUE(refined) << "no refined frame within 60 s";
    EXPECT_EQ(refined->image.pixels, render(other, other.mode).pixels);
}

// A Monte Carlo scene (stage 10) refines its samples: 1, 4, then its own 16, the last pass
// being `rt render`'s image bit for bit.
// The passes of a Monte Carlo scene on the CPU or GPU path, up to the refined frame: their
// sample counts must grow to the scene's own.
std::optional<Frame> refine_samples(const PreparedScene& scene, bool gpu, int seconds,
                                    std::vector<int>& samples) {
    ProgressiveRenderer renderer(gpu ? 1 : 2);
    const std::uint64_t generation = renderer.restart(scene, gpu);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (std::chrono::steady_clock::now() < deadline) {
        if (auto frame = renderer.take(); frame && frame->generation == generation) {
            EXPECT_TRUE(frame->error.empty()) << frame->error;
            EXPECT_EQ(frame->gpu, gpu);
            samples.push_back(frame->samples);
            if (frame->refined() || !frame->error.empty()) return frame;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    return std::nullopt;
}

// A Monte Carlo scene at 48 x 32 (no coarse passes) and `spp` samples, on the CPU or the GPU:
// passes of more and more samples, the last one rt render's (--gpu's) image.
void expect_refines(const std::string& scene_file, int spp, bool gpu) {
    PreparedScene scene = prepare_scene(load_scene(source_dir() / scene_file));
    scene.image = ImageSize{48, 32};
    scene.sampling.samples_per_pixel = spp;
    std::vector<int> samples;
    const std::optional<Frame> last = refine_samples(scene, gpu, gpu ? 120 : 60, samples);
    ASSERT_TRUE(last && last->refined()) << "no refined frame in time";
    EXPECT_EQ(samples.back(), spp);
    for (std::size_t k = 1; k < samples.size(); ++k) EXPECT_GT(samples[k], samples[k - 1]);
    EXPECT_EQ(last->image.pixels,
              gpu ? render_gpu(scene, scene.mode).pixels : render(scene, scene.mode).pixels);
}

TEST(ViewProgressive, AMonteCarloSceneRefinesItsSamples) {
    expect_refines("stages/10-sampling/scenes/soft_shadows.json", 16, false);
}

// The GPU path: the refined frame is `rt render --gpu`'s image, and a second camera reuses the
// program compiled for the first (same features).
TEST(ViewProgressive, TheGpuPathGivesTheGpuRenderersImage) {
    PreparedScene scene = whitted();
    scene.image = ImageSize{64, 48};  // small: no coarse passes, and llvmpipe is slow
    ProgressiveRenderer renderer(1);
    const auto refined = [&](const PreparedScene& s) -> std::optional<Frame> {
        const std::uint64_t generation = renderer.restart(s, true);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (std::chrono::steady_clock::now() < deadline) {
            if (auto frame = renderer.take(); frame && frame->generation == generation &&
                                              (frame->refined() || !frame->error.empty()))
                return frame;
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
        return std::nullopt;
    };
    const std::optional<Frame> first = refined(scene);
    ASSERT_TRUE(first) << "no refined GPU frame within 120 s";
    ASSERT_TRUE(first->error.empty()) << first->error;
    EXPECT_TRUE(first->gpu);
    EXPECT_EQ(first->image.pixels, render_gpu(scene, scene.mode).pixels);
    orbit(scene.camera, 5, scene.camera.v, 10, 0);
    const std::optional<Frame> second = refined(scene);
    ASSERT_TRUE(second && second->error.empty());
    EXPECT_EQ(second->image.pixels, render_gpu(scene, scene.mode).pixels);
}

// Stage 10 on the GPU path: the same passes (1, 4, 16 samples), each accumulated over dispatches;
// the refined frame is `rt render --gpu`'s image.
TEST(ViewProgressive, TheGpuPathRefinesAMonteCarloScene) {
    expect_refines("stages/10-sampling/scenes/soft_shadows.json", 16, true);
}

// Stage 11's path tracer (stages/11-path-tracing/path.glsl) refines the same way.
TEST(ViewProgressive, TheGpuPathRefinesAPathTracedScene) {
    expect_refines("stages/11-path-tracing/scenes/cornell_box.json", 16, true);
}

TEST(ViewProgressive, ARenderErrorIsAFrameNotACrash) {
    PreparedScene scene = whitted();
    scene.mode = RenderMode::BvhVisits;  // without a BVH: render() refuses
    ProgressiveRenderer renderer(1);
    renderer.restart(scene);
    std::optional<Frame> frame;
    for (int i = 0; i < 5000 && !frame; ++i) {
        frame = renderer.take();
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_TRUE(frame);
    EXPECT_NE(frame->error.find("bvh_visits"), std::string::npos) << frame->error;
}

std::string script_error(const std::string& text) {
    const fs::path file = fs::temp_directory_path() / "rt_view_test_script.txt";
    std::ofstream(file) << text;
    try {
        read_script(file);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(ViewScript, ErrorsNameTheLineAndHowToWriteIt) {
    EXPECT_EQ(script_error("# fine\nwait-refined\nclick 3 4\nset shadows off\n"), "");
    EXPECT_NE(script_error("wait-refined\n\nclick 3\n").find(":3: error: click takes 2"),
              std::string::npos);
    EXPECT_NE(script_error("sleep soon\n").find(":1: error: \"soon\" is not a number"),
              std::string::npos);
    EXPECT_NE(script_error("set shadows maybe\n").find("on or off"), std::string::npos);
    EXPECT_NE(script_error("screenshot a/b\n").find("without folders"), std::string::npos);
    EXPECT_NE(script_error("key X\n").find("write key S|R|W|P|Q"), std::string::npos);
}

// The panel's (and --debug-pixel's) light-linking line for a hit: the lights that reach its
// material, those of them that cast no shadows, and those that do not reach it.
TEST(RayTree, NamesTheLightsThatReachAHit) {
    const PreparedScene scene =
        prepare_scene(load_scene(source_dir() / "stages/04-shadows/scenes/fill_light.json"));
    EXPECT_EQ(light_links_text(scene, 1), "reached by lights 0, 1 (no shadows: 1); not by any")
        << "material 1, gold, which the fill light is linked to";
    EXPECT_EQ(light_links_text(scene, 0), "reached by lights 0; not by 1") << "the floor";
}

}  // namespace
}  // namespace rt::view
