// Framework tests that live with stage 08 but call none of its code, so they are labelled
// "framework", not "stage08" (a starter tree's stage08 tests must all fail on the stubs): the
// background hook without an environment, the committed environment images, and the scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "core/not_implemented.h"
#include "image/image.h"
#include "render/background.h"
#include "render/prepare.h"
#include "scene/scene_loader.h"
#include "stage_api/stage08.h"
#include "testing/environment_images.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

// The hook: a scene without an environment never reaches stage 08 code (no stub is counted even
// in a starter tree), one with an environment gets environment_radiance.
TEST(Background, WithoutAnEnvironmentIsTheScenesColorAndCallsNoStageCode) {
    PreparedScene scene;
    scene.background = Color(0.1f, 0.2f, 0.3f);
    refresh_features(scene);
    const auto stubs = stub_calls_total();
    EXPECT_EQ(background(scene, Vec3(0, 0, -1)), scene.background);
    EXPECT_EQ(background(scene, Vec3(5, 1, 0)), scene.background);
    EXPECT_EQ(stub_calls_total(), stubs);
    EXPECT_FALSE(scene.features.environment);
}

// ---- the committed images -------------------------------------------------------------------

const std::filesystem::path kScenes = testing::source_dir() / "stages/08-environment/scenes";

TEST(EnvironmentImages, CommittedFilesAreTheGeneratorsOutput) {
    // Regenerate with: build/bin/make-environment-images stages/08-environment/scenes
    const Image sky = read_image(kScenes / "sky.exr");
    const Image made = testing::make_latlong_sky();
    ASSERT_EQ(sky.width, made.width);
    ASSERT_EQ(sky.height, made.height);
    for (std::size_t k = 0; k < sky.pixels.size(); ++k)
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(sky.pixels[k][c], made.pixels[k][c],
                        2e-3f * std::max(1.0f, made.pixels[k][c]))
                << "sky.exr pixel " << k;
    for (int f = 0; f < kCubeFaces; ++f) {
        const auto file = kScenes / "cube" / (std::string(kCubeFaceNames[f]) + ".png");
        const Image8 face = read_image8(file);
        const Image8 want = to_image8(testing::make_cube_face(f));
        EXPECT_EQ(face.width, want.width) << file;
        EXPECT_TRUE(face.data == want.data) << file << " differs from make_cube_face(" << f << ")";
    }
}

TEST(EnvironmentScenes, LoadWithTheirEnvironment) {
    const PreparedScene sky = prepare_scene(load_scene(kScenes / "sky.json"));
    EXPECT_EQ(sky.environment.kind, EnvironmentKind::LatLong);
    EXPECT_TRUE(sky.features.environment);
    EXPECT_NE(sky.features.describe().find("environment"), std::string::npos);
    const PreparedScene cube = prepare_scene(load_scene(kScenes / "cube_mirror.json"));
    ASSERT_EQ(cube.environment.kind, EnvironmentKind::CubeMap);
    for (int f = 0; f < kCubeFaces; ++f) {
        const TextureImage& image = cube.texture_images[std::size_t(cube.environment.faces[f])];
        EXPECT_EQ(image.width, 32);
        EXPECT_EQ(image.height, 32);
    }
}

}  // namespace
}  // namespace rt
