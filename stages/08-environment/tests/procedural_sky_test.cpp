// Framework tests of the procedural sky and the environment's ambient term
// (scene/procedural_sky.h, docs/scene-format.md#environment). They call no stage 08 code: the
// sky is baked by the framework, so they are labelled "framework".
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/not_implemented.h"
#include "scene/prepared_scene.h"
#include "scene/procedural_sky.h"
#include "scene/scene_loader.h"

namespace rt {
namespace {

void expect_near(const Color& got, const Color& want, float tolerance, const std::string& what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], want[c], tolerance) << what << ", channel " << c;
}

TEST(ProceduralSky, LatLongDirectionIsTheConventionsInverse) {
    // docs/conventions.md#environment-maps: u = 0 at -z, 0.25 at +x, 0.5 at +z, 0.75 at -x.
    const struct {
        Real u, v;
        Vec3 d;
    } cases[] = {{0, 0.5f, {0, 0, -1}},     {0.25f, 0.5f, {1, 0, 0}}, {0.5f, 0.5f, {0, 0, 1}},
                 {0.75f, 0.5f, {-1, 0, 0}}, {0.3f, 0, {0, 1, 0}},     {0.6f, 1, {0, -1, 0}}};
    for (const auto& c : cases) {
        const Vec3 d = latlong_direction(c.u, c.v);
        EXPECT_NEAR(glm::length(d - c.d), 0, 1e-6f) << "u = " << c.u << ", v = " << c.v;
    }
}

TEST(ProceduralSky, BakesGradientGroundAndSun) {
    SkyParameters sky;
    sky.sun_direction = glm::normalize(Vec3(0, 1, -1));  // 45 degrees up, straight ahead
    sky.sun_radius_degrees = 5;
    sky.height = 64;
    const Image image = bake_sky(sky);
    ASSERT_EQ(image.width, 128);
    ASSERT_EQ(image.height, 64);
    // Row 0 is nearly straight up: nearly the zenith; the row just above the horizon nearly the
    // horizon colour (the square root of a small height); every row below is the ground.
    expect_near(image.at(40, 0), sky.zenith, 0.05f, "top row");
    expect_near(image.at(40, 31), sky.horizon, 0.12f, "just above the horizon");
    expect_near(image.at(40, 32), sky.ground, 0, "just below the horizon");
    expect_near(image.at(100, 63), sky.ground, 0, "bottom row");
    // The sun at u = 0 (-z), v = 0.25 (45 degrees up): texel (0, 15) has its centre 1.4 degrees
    // from the sun's centre; texel (20, 16) is 56 degrees to the side.
    expect_near(image.at(0, 15), sky.sun, 0, "the sun's texel");
    EXPECT_LT(image.at(20, 16).r, 2.0f) << "far from the sun";
    sky.sun_radius_degrees = 0;
    EXPECT_LT(bake_sky(sky).at(0, 15).r, 2.0f) << "radius 0 leaves the sun out";
}

Scene latlong_scene(const std::vector<Color>& texels, int w, int h) {
    Scene scene;
    scene.environment.kind = EnvironmentKind::LatLong;
    scene.environment.image = scene.add_texture_image(w, h, texels);
    return scene;
}

TEST(EnvironmentAmbient, MeanRadianceWeighsBySolidAngle) {
    // Uniform: the colour itself, times the intensity.
    Scene uniform = latlong_scene(std::vector<Color>(32 * 16, Color(0.2f, 0.4f, 0.6f)), 32, 16);
    uniform.environment.intensity = 2;
    expect_near(mean_environment_radiance(uniform), Color(0.4f, 0.8f, 1.2f), 1e-5f, "uniform");
    // White above the horizon, black below: half of all directions.
    std::vector<Color> half(32 * 16, Color(0));
    for (int k = 0; k < 32 * 8; ++k) half[std::size_t(k)] = Color(1);
    expect_near(mean_environment_radiance(latlong_scene(half, 32, 16)), Color(0.5f), 1e-5f,
                "upper half");
    // Only the top row white: a cap of solid angle 2 pi (1 - cos(pi / 16)) out of 4 pi, which
    // texel-centre weights estimate to within 2%, where counting texels would say 1/16.
    std::vector<Color> cap(32 * 16, Color(0));
    for (int k = 0; k < 32; ++k) cap[std::size_t(k)] = Color(1);
    const float want = float((1 - std::cos(3.14159265358979 / 16)) / 2);
    EXPECT_NEAR(mean_environment_radiance(latlong_scene(cap, 32, 16)).g, want, 0.02f * want);
    // A cube map with only +y white: one sixth.
    Scene cube;
    cube.environment.kind = EnvironmentKind::CubeMap;
    for (int f = 0; f < kCubeFaces; ++f)
        cube.environment.faces[f] =
            cube.add_texture_image(8, 8, std::vector<Color>(64, Color(f == 2 ? 1.0f : 0.0f)));
    expect_near(mean_environment_radiance(cube), Color(1.0f / 6), 1e-5f, "+y face only");
    EXPECT_EQ(mean_environment_radiance(Scene{}), Color(0));
}

TEST(EnvironmentAmbient, SkySceneLoadsWithoutAnyFileAndAddsItsAmbient) {
    const auto stubs = stub_calls_total();
    const Scene plain = parse_scene(R"({"environment": {"sky": {}}})", "sky.json", ".");
    ASSERT_EQ(plain.environment.kind, EnvironmentKind::LatLong);
    const TextureImage& image = plain.texture_images[std::size_t(plain.environment.image)];
    EXPECT_EQ(image.width, 512);
    EXPECT_EQ(image.height, 256);
    EXPECT_TRUE(scene_features(plain).environment);
    EXPECT_EQ(plain.ambient_light, Color(0));
    const Scene lit = parse_scene(
        R"({"ambient_light": [0.1, 0.1, 0.1], "environment": {"sky": {}, "ambient": 0.5}})",
        "sky.json", ".");
    expect_near(lit.ambient_light, Color(0.1f) + 0.5f * mean_environment_radiance(plain), 1e-6f,
                "ambient_light plus half the sky's mean");
    EXPECT_EQ(stub_calls_total(), stubs) << "loading a sky calls no student code";
}

}  // namespace
}  // namespace rt
