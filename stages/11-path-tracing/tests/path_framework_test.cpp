// Stage 11's framework tests (no student code): the scene keys and their errors, Features, the
// canonical form, the framework's nearest_area_light, and that no earlier scene path-traces.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/source_dir.h"
#include "render/prepare.h"
#include "scene/area_light_hit.h"
#include "scene/scene_format.h"
#include "scene/scene_loader.h"
#include "testing/scene_text.h"

namespace rt {
namespace {

using testing::scene_of;

TEST(PathScenes, KeysReachTheSceneAndFeatures) {
    const PreparedScene plain = scene_of(R"("render": {"mode": "shaded"})");
    EXPECT_EQ(plain.sampling.integrator, Integrator::Whitted);
    EXPECT_FALSE(plain.features.path_tracing || plain.features.sampled());
    const PreparedScene s = scene_of(R"(
  "render": {"mode": "shaded", "integrator": "path", "max_depth": 12},
  "materials": [{"specular": [0.9, 0.9, 0.9], "roughness": 0.25}])");
    EXPECT_EQ(s.sampling.integrator, Integrator::Path);
    EXPECT_FLOAT_EQ(s.materials[0].roughness, 0.25f);
    EXPECT_EQ(s.max_depth, 12);
    EXPECT_TRUE(s.features.path_tracing && s.features.sampled())
        << "a path-traced scene takes the sampled path, whatever its samples per pixel";
    EXPECT_NE(s.features.describe().find("path-tracing"), std::string::npos)
        << s.features.describe();
}

TEST(PathScenes, BadInputIsOneLineNamingPlaceAndFix) {
    const std::pair<const char*, const char*> cases[] = {
        {R"("render": {"integrator": "bidirectional"})", "s.json:1:27: error:"},
        {R"("materials": [{"roughness": 1.5}])", "\"roughness\" must be between 0 and 1"},
        {R"("materials": [{"roughness": -0.1}])", "\"roughness\" must be between 0 and 1"},
    };
    testing::expect_scene_errors(cases);
}

TEST(PathScenes, CanonicalFormOrdersTheNewKeys) {
    const std::string text = canonical_scene_text(
        R"({"render": {"integrator": "path", "mode": "shaded", "seed": 3},
            "materials": [{"roughness": 0.3, "name": "m", "fuzz": 0.1, "diffuse_map": "t"}],
            "textures": [{"name": "t", "checker": {"a": [0, 0, 0], "b": [1, 1, 1]}}]})",
        "s.json", ".");
    EXPECT_NE(text.find(R"("render": {"mode": "shaded", "seed": 3, "integrator": "path"})"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(R"({"name": "m", "fuzz": 0.1, "roughness": 0.3, "diffuse_map": "t"})"),
              std::string::npos)
        << text;
}

TEST(AreaLightHits, NearestLightInFrontOfTheSurface) {
    Scene scene;
    AreaLight rectangle;  // y = 2, lit downwards (cross(edge_u, edge_v) = -y)
    rectangle.corner = Vec3(-1, 2, -1);
    rectangle.edge_u = Vec3(2, 0, 0);
    rectangle.edge_v = Vec3(0, 0, 2);
    rectangle.radiance = Color(3);
    AreaLight sphere;
    sphere.kind = AreaLightKind::Sphere;
    sphere.center = Vec3(0, 5, 0);
    sphere.radius = 1;
    sphere.radiance = Color(7);
    scene.area_lights = {rectangle, sphere};
    const Ray up{Vec3(0, 0, 0), Vec3(0, 1, 0)};
    AreaLightHit hit = nearest_area_light(scene, up, Interval{0, kInfinity});
    EXPECT_EQ(hit.light, 0);
    EXPECT_FLOAT_EQ(hit.t, 2);
    EXPECT_EQ(hit.radiance, Color(3)) << "seen from its lit side";
    EXPECT_EQ(nearest_area_light(scene, up, Interval{0, 1.5f}).light, -1)
        << "a surface at t = 1.5 hides both lights";
    hit = nearest_area_light(scene, Ray{Vec3(0, 3, 0), Vec3(0, 1, 0)}, Interval{0, kInfinity});
    EXPECT_EQ(hit.light, 1);
    EXPECT_FLOAT_EQ(hit.t, 1) << "the near side of the sphere";
    hit = nearest_area_light(scene, Ray{Vec3(0, 3, 0), Vec3(0, -1, 0)}, Interval{0, kInfinity});
    EXPECT_EQ(hit.light, 0);
    EXPECT_EQ(hit.radiance, Color(0)) << "the back of a rectangle light is dark";
    EXPECT_EQ(nearest_area_light(scene, Ray{Vec3(5, 0, 0), Vec3(0, 1, 0)}, Interval{}).light, -1);
}

TEST(PathScenes, NoEarlierStageScenePathTraces) {
    int scenes = 0;
    for (const auto& stage : std::filesystem::directory_iterator(source_dir() / "stages")) {
        if (stage.path().filename().string() >= "11") continue;
        if (!std::filesystem::is_directory(stage.path() / "scenes")) continue;
        for (const auto& file : std::filesystem::directory_iterator(stage.path() / "scenes")) {
            if (file.path().extension() != ".json") continue;
            EXPECT_FALSE(prepare_scene(load_scene(file.path())).features.path_tracing)
                << file.path();
            ++scenes;
        }
    }
    EXPECT_GT(scenes, 30);
}

}  // namespace
}  // namespace rt
