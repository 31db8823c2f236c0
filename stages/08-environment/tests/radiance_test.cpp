// Stage 08 tests: environment_radiance on small images built in code (texel centres, the seam,
// the poles, cube faces without bleeding, rotation, intensity), the background hook, and the
// committed environment images against their generator.
#include <cmath>
#include <numbers>

#include "core/not_implemented.h"
#include "render/background.h"
#include "render/prepare.h"
#include "scene/procedural_sky.h"
#include "scene/scene_loader.h"
#include "stage_api/stage08.h"
#include "testing/environment_images.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(Radiance, "3-looking-up-the-environment");

constexpr Real kPi = std::numbers::pi_v<Real>;

void expect_color(const Color& got, const Color& want, const std::string& what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], want[c], 1e-4f * std::max(1.0f, want[c])) << what << ", channel " << c;
}

// A w x h lat-long image whose texel (i, j) is (i, j, 1 + i + j) / 10.
PreparedScene latlong_scene(int w, int h) {
    PreparedScene scene;
    std::vector<Color> texels;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i)
            texels.push_back(Color(float(i), float(j), float(1 + i + j)) / 10.0f);
    scene.environment.kind = EnvironmentKind::LatLong;
    scene.environment.image = scene.add_texture_image(w, h, texels);
    refresh_features(scene);
    return scene;
}

Color texel(int i, int j) {
    return Color(float(i), float(j), float(1 + i + j)) / 10.0f;
}

TEST_F(Radiance, LatLongTexelCentersGiveTheirTexel) {
    const PreparedScene scene = latlong_scene(8, 4);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 8; ++i) {
            const Vec3 d = latlong_direction((Real(i) + 0.5f) / 8, (Real(j) + 0.5f) / 4);
            expect_color(environment_radiance(scene, Real(2) * d), texel(i, j),
                         "texel (" + std::to_string(i) + ", " + std::to_string(j) + ")");
        }
}

TEST_F(Radiance, LatLongWrapsAcrossTheSeam) {
    // At -z (u = 0) on row 1's centre: half of column 0, half of column 7.
    const PreparedScene scene = latlong_scene(8, 4);
    const Vec3 d = latlong_direction(0, 1.5f / 4);
    expect_color(environment_radiance(scene, d), (texel(0, 1) + texel(7, 1)) * 0.5f,
                 "u = 0 blends the first and the last column");
}

TEST_F(Radiance, PolesDoNotBlendWithTheOtherEdge) {
    // Straight up is v = 0: row 0 only (the bottom row would add green 0.3).
    const PreparedScene scene = latlong_scene(8, 4);
    const Color up = environment_radiance(scene, Vec3(0, 1, 0));
    EXPECT_NEAR(up.g, 0, 1e-6f) << "straight up must read row 0 only";
    const Color down = environment_radiance(scene, Vec3(0, -2, 0));
    EXPECT_NEAR(down.g, 0.3f, 1e-6f) << "straight down must read the last row only";
}

TEST_F(Radiance, RotationTurnsTheEnvironmentAboutY) {
    PreparedScene scene = latlong_scene(8, 4);
    const PreparedScene unrotated = scene;
    scene.environment.rotate_y = 90;
    // Turned by +90 degrees (right-hand rule about +y): +z goes to +x, +x to -z.
    expect_color(environment_radiance(scene, Vec3(1, 0.3f, 0)),
                 environment_radiance(unrotated, Vec3(0, 0.3f, 1)), "+x shows what was at +z");
    expect_color(environment_radiance(scene, Vec3(0, -0.2f, -1)),
                 environment_radiance(unrotated, Vec3(1, -0.2f, 0)), "-z shows what was at +x");
    scene.environment.rotate_y = -45;
    const Vec3 d(0.3f, 0.1f, -0.8f);
    const Real c = std::cos(kPi / 4), s = std::sin(kPi / 4);  // turning d by +45 degrees
    expect_color(environment_radiance(scene, d),
                 environment_radiance(unrotated, Vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z)),
                 "-45 degrees");
}

TEST_F(Radiance, IntensityScalesTheImage) {
    PreparedScene scene = latlong_scene(8, 4);
    scene.environment.intensity = 2.5f;
    const Vec3 d = latlong_direction(2.5f / 8, 2.5f / 4);
    expect_color(environment_radiance(scene, d), texel(2, 2) * 2.5f, "intensity 2.5");
}

// Six 2x2 faces; face f's texel (i, j) is colour (f + 1, i, j) / 10.
PreparedScene cube_scene() {
    PreparedScene scene;
    scene.environment.kind = EnvironmentKind::CubeMap;
    for (int f = 0; f < 6; ++f) {
        std::vector<Color> texels;
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                texels.push_back(Color(float(f + 1), float(i), float(j)) / 10.0f);
        scene.environment.faces[f] = scene.add_texture_image(2, 2, texels);
    }
    refresh_features(scene);
    return scene;
}

TEST_F(Radiance, CubeFacesAreLookedUpWithClampAndNoBleeding) {
    const PreparedScene scene = cube_scene();
    const Vec3 axes[6] = {Vec3(1, 0, 0),  Vec3(-1, 0, 0), Vec3(0, 1, 0),
                          Vec3(0, -1, 0), Vec3(0, 0, 1),  Vec3(0, 0, -1)};
    for (int f = 0; f < 6; ++f)  // the centre: the four texels equally
        expect_color(environment_radiance(scene, Real(3) * axes[f]),
                     Color(float(f + 1), 0.5f, 0.5f) / 10.0f,
                     "centre of face " + std::to_string(f));
    // The corner (u, v) = (0, 0) of +x, (1, 1, 1): texel (0, 0) of +x alone, nothing of +y or +z.
    expect_color(environment_radiance(scene, Vec3(1, 1, 1)), Color(0.1f, 0, 0), "corner of +x");
    // Texel centres: (u, v) = (0.25, 0.75) on -z is texel (0, 1).
    expect_color(environment_radiance(scene, Vec3(0.5f, -0.5f, -1)), Color(0.6f, 0, 0.1f),
                 "texel (0, 1) of -z");
}

TEST_F(Radiance, NoEnvironmentIsTheBackgroundColor) {
    PreparedScene scene;
    scene.background = Color(0.1f, 0.2f, 0.3f);
    refresh_features(scene);
    EXPECT_EQ(environment_radiance(scene, Vec3(0, 0, -1)), scene.background);
}

TEST_F(Radiance, BackgroundUsesTheEnvironment) {
    const PreparedScene scene = latlong_scene(8, 4);
    ASSERT_TRUE(scene.features.environment);
    const Vec3 d(0.2f, 0.4f, -1);
    EXPECT_EQ(background(scene, d), environment_radiance(scene, d));
}

TEST_F(Radiance, ImagesAreReadLinearNotSrgbDecoded) {
    // Uniform images of 0.5: environment images are linear radiance, so every direction reads
    // 0.5; sRGB decoding would give 0.214.
    PreparedScene scene;
    scene.environment.kind = EnvironmentKind::LatLong;
    scene.environment.image = scene.add_texture_image(4, 2, std::vector<Color>(8, Color(0.5f)));
    refresh_features(scene);
    expect_color(environment_radiance(scene, Vec3(0.3f, 0.2f, -1)), Color(0.5f),
                 "lat-long: read the linear image as stored (texture_view(index, false)), not "
                 "sRGB-decoded");
    PreparedScene cube;
    cube.environment.kind = EnvironmentKind::CubeMap;
    for (int f = 0; f < 6; ++f)
        cube.environment.faces[f] =
            cube.add_texture_image(2, 2, std::vector<Color>(4, Color(0.5f)));
    refresh_features(cube);
    expect_color(environment_radiance(cube, Vec3(0.3f, 0.2f, -1)), Color(0.5f),
                 "cube face: read the linear image as stored, not sRGB-decoded");
}

}  // namespace
}  // namespace rt
