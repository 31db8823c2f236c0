// Stage 10's framework tests (no student code): the scene syntax, Features, the one-line errors,
// the generator's determinism, and that no scene of stages 01-09 takes the sampled path.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "core/source_dir.h"
#include "image/compare.h"
#include "render/prepare.h"
#include "render/sampled.h"
#include "scene/scene_format.h"
#include "scene/scene_loader.h"
#include "testing/scene_text.h"

namespace rt {
namespace {

using testing::scene_of;

TEST(SamplingScenes, KeysReachTheScene) {
    const PreparedScene s = scene_of(R"(
  "camera": {"eye": [0, 0, 5], "aperture": 0.2, "focus_distance": 4.5, "shutter": [0, 0.5]},
  "render": {"mode": "shaded", "samples_per_pixel": 16, "seed": 7, "filter": "tent", "indirect": "occlusion", "occlusion_distance": 2},
  "ambient_light": [0.2, 0.2, 0.2],
  "materials": [{"ambient": [1, 1, 1], "reflective": [0.5, 0.5, 0.5], "fuzz": 0.3}],
  "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "velocity": [1, 0, 0]}],
  "lights": [{"type": "rectangle", "corner": [0, 2, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1], "radiance": [2, 2, 2]},
             {"type": "sphere", "center": [0, 3, 0], "radius": 0.5}])");
    EXPECT_EQ(s.sampling.samples_per_pixel, 16);
    EXPECT_EQ(s.sampling.seed, 7u);
    EXPECT_EQ(s.sampling.filter, PixelFilter::Tent);
    EXPECT_EQ(s.sampling.indirect, IndirectLight::Occlusion);
    EXPECT_FLOAT_EQ(s.sampling.occlusion_distance, 2);
    EXPECT_FLOAT_EQ(s.sampling.aperture, 0.2f);
    EXPECT_FLOAT_EQ(s.sampling.focus_distance, 4.5f);
    EXPECT_FLOAT_EQ(s.sampling.shutter_close, 0.5f);
    ASSERT_EQ(s.area_lights.size(), 2u);
    EXPECT_EQ(s.area_lights[1].kind, AreaLightKind::Sphere);
    EXPECT_EQ(s.lights.size(), 0u) << "area lights are not point lights";
    ASSERT_EQ(s.moving_spheres.size(), 1u);
    EXPECT_EQ(s.spheres.size(), 1u) << "a moving sphere is a sphere at time 0";
    EXPECT_FLOAT_EQ(s.materials[0].fuzz, 0.3f);
    const Features& f = s.features;
    EXPECT_TRUE(f.antialiasing && f.area_lights && f.depth_of_field && f.motion_blur && f.glossy &&
                f.ambient_occlusion && !f.indirect_diffuse);
    EXPECT_NE(f.describe().find("sampled: antialiasing area-lights"), std::string::npos)
        << f.describe();
}

TEST(SamplingScenes, BadInputIsOneLineNamingPlaceAndFix) {
    const std::pair<const char*, const char*> cases[] = {
        {R"("render": {"samples_per_pixel": 0})",
         "s.json:1:34: error: \"samples_per_pixel\" must be between 1 and 65536, got 0"},
        {R"("render": {"filter": "gauss"})", "s.json:1:23: error:"},
        {R"("camera": {"shutter": [1, 0]})", "the shutter closes before it opens"},
        {R"("camera": {"projection": "orthographic", "aperture": 1})",
         "an orthographic camera has no lens"},
        {R"("materials": [{"fuzz": 2}])", "\"fuzz\" must be between 0 and 1"},
        {R"("lights": [{"type": "rectangle", "corner": [0, 0, 0], "edge_u": [1, 0, 0], "edge_v": [1, 0, 1]}])",
         "are not perpendicular; a rectangle light needs perpendicular edges"},
        {R"("lights": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}])", "must be > 0"},
        {R"("render": {"accelerator": "bvh"}, "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "velocity": [1, 0, 0]}])",
         "a moving sphere cannot be in a BVH"},
        {R"("fog": {"albedo": [0.5, 0.5, 0.5]})", "s.json:1:9: error: the fog needs \"density\""},
        {R"("fog": {"density": 0})", "s.json:1:21: error: \"density\" must be > 0, got 0"},
        {R"("fog": {"density": 1, "albedo": [0.5, 1.5, 0.5]})",
         "s.json:1:40: error: \"albedo\" must be between 0 and 1, got 1.5"},
        {R"("fog": {"density": 1, "min": [0, 0, 0]})", "a fog box needs both \"min\" and \"max\""},
        {R"("fog": {"density": 1, "min": [0, 0, 0], "max": [1, -1, 1]})",
         "\"max\" must not be below \"min\", but y is -1 < 0"},
        {R"("fog": {"density": 1, "height": 2})",
         "s.json:1:24: error: unknown key \"height\" in \"fog\""},
        {R"("fog": {"density": 1}, "lights": [{"type": "sphere", "center": [0, 3, 0], "radius": 0.5}])",
         "fog and area lights together are not supported"},
    };
    testing::expect_scene_errors(cases);
}

// The optional fog: its keys, Features (so scenes without fog never call its code), the box.
TEST(SamplingScenes, FogReachesTheSceneAndFeatures) {
    const PreparedScene plain = scene_of(R"("render": {"mode": "shaded"})");
    EXPECT_FALSE(plain.features.fog || plain.features.sampled()) << "no fog, no sampled path";
    const PreparedScene s = scene_of(
        R"("fog": {"density": 0.25, "albedo": [0.5, 0.6, 0.7], "min": [-1, 0, -2], "max": [1, 2, 0]})");
    EXPECT_FLOAT_EQ(s.fog.density, 0.25f);
    EXPECT_FLOAT_EQ(s.fog.albedo.g, 0.6f);
    EXPECT_TRUE(s.fog.bounded);
    EXPECT_EQ(s.fog.max, Vec3(1, 2, 0));
    EXPECT_TRUE(s.features.fog && s.features.sampled());
    EXPECT_NE(s.features.describe().find("sampled: fog"), std::string::npos)
        << s.features.describe();
    const PreparedScene everywhere = scene_of(R"("fog": {"density": 1})");
    EXPECT_FALSE(everywhere.fog.bounded);
    EXPECT_EQ(everywhere.fog.albedo, Color(1));
    // The canonical form puts "fog" after "environment" and its keys in table order.
    const std::string text = canonical_scene_text(
        R"({"lights": [], "fog": {"max": [1, 1, 1], "min": [0, 0, 0], "albedo": [1, 1, 1], "density": 1}, "background": [0, 0, 0]})",
        "s.json", ".");
    EXPECT_NE(text.find(R"("background": [0, 0, 0],
  "fog": {"density": 1, "albedo": [1, 1, 1], "min": [0, 0, 0], "max": [1, 1, 1]},
  "lights")"),
              std::string::npos)
        << text;
}

// The framework's medium_interval: the part of a range inside the fog's box.
TEST(SamplingScenes, MediumIntervalClipsToTheBox) {
    Medium box;
    box.density = 1;
    box.bounded = true;
    box.min = Vec3(-1, -1, -1);
    box.max = Vec3(1, 1, 1);
    const Ray ray{Vec3(-3, 0, 0), Vec3(2, 0, 0)};
    Interval in = medium_interval(box, ray, Interval{});
    EXPECT_FLOAT_EQ(in.min, 1);
    EXPECT_FLOAT_EQ(in.max, 2);
    in = medium_interval(box, ray, Interval{0, 1.5f});
    EXPECT_FLOAT_EQ(in.max, 1.5f);
    in = medium_interval(box, Ray{Vec3(-3, 2, 0), Vec3(1, 0, 0)}, Interval{});
    EXPECT_FALSE(in.min < in.max) << "a ray beside the box (parallel to a slab): empty";
    in = medium_interval(box, ray, Interval{0, 0.5f});
    EXPECT_FALSE(in.min < in.max) << "a range that ends before the box: empty";
    Medium everywhere;
    everywhere.density = 1;
    in = medium_interval(everywhere, ray, Interval{0.5f, 7});
    EXPECT_FLOAT_EQ(in.min, 0.5f);
    EXPECT_FLOAT_EQ(in.max, 7);
}

TEST(SamplingScenes, NoEarlierStageSceneTakesTheSampledPath) {
    int scenes = 0;
    for (const auto& stage : std::filesystem::directory_iterator(source_dir() / "stages")) {
        if (stage.path().filename().string() >= "10") continue;
        if (!std::filesystem::is_directory(stage.path() / "scenes")) continue;
        for (const auto& file : std::filesystem::directory_iterator(stage.path() / "scenes")) {
            if (file.path().extension() != ".json") continue;
            const PreparedScene s = prepare_scene(load_scene(file.path()));
            EXPECT_FALSE(s.features.sampled()) << file.path();
            ++scenes;
        }
    }
    EXPECT_GT(scenes, 30);
}

TEST(SampleStreams, DependOnlyOnSeedPixelAndSample) {
    std::set<float> seen;
    for (std::uint64_t pixel : {0u, 1u}) {
        for (std::uint64_t sample : {0u, 1u}) {
            SampleStream a(9, pixel, sample), b(9, pixel, sample);
            for (int i = 0; i < 100; ++i) {
                const Real x = a.next();
                ASSERT_EQ(x, b.next());
                ASSERT_TRUE(x >= 0 && x < 1);
                if (i == 0) seen.insert(float(x));
            }
        }
    }
    EXPECT_EQ(seen.size(), 4u) << "neighbouring pixels and samples start alike";
    SampleStream other_seed(10, 0, 0), first(9, 0, 0);
    EXPECT_NE(other_seed.next(), first.next());
}

// The block-mean comparison of Monte Carlo images (CompareOptions::block): pixel noise around
// the right mean passes, a block whose mean moved fails all its pixels.
TEST(BlockMeans, ForgiveNoiseAndCatchShiftedMeans) {
    Image8 reference{16, 16, std::vector<std::uint8_t>(16 * 16 * 3, 128)};
    Image8 noisy = reference;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c) noisy.at(x, y)[c] = (x + y) % 2 ? 118 : 138;
    CompareOptions pixels;
    EXPECT_FALSE(compare_images(noisy, reference, pixels).passed) << "per pixel, noise fails";
    CompareOptions blocks;
    blocks.block = 8;
    const CompareResult quiet = compare_images(noisy, reference, blocks);
    EXPECT_TRUE(quiet.passed) << quiet.summary();
    EXPECT_NE(quiet.summary().find("8x8 blocks"), std::string::npos) << quiet.summary();
    Image8 shifted = noisy;
    for (int y = 8; y < 16; ++y)
        for (int x = 0; x < 8; ++x) shifted.at(x, y)[1] += 20;
    const CompareResult moved = compare_images(shifted, reference, blocks);
    EXPECT_FALSE(moved.passed);
    EXPECT_EQ(moved.failing_pixels, 64) << "exactly the moved block fails";
    EXPECT_GE(moved.max_difference, 15);
}

}  // namespace
}  // namespace rt
