// Stage 01 image tests: each scene of stages/01-camera-rays/scenes rendered with your code and
// compared with reference_images/01-camera-rays/ (docs/conventions.md#image-tests).
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(Image);

TEST_F(Image, PerspectiveDirections) { testing::expect_matches_reference("01-camera-rays", "perspective_directions"); }
TEST_F(Image, WideAngleDirections) { testing::expect_matches_reference("01-camera-rays", "wide_angle_directions"); }
TEST_F(Image, OrthographicDirections) { testing::expect_matches_reference("01-camera-rays", "orthographic_directions"); }
TEST_F(Image, TiltedCamera) { testing::expect_matches_reference("01-camera-rays", "tilted_camera"); }

}  // namespace
}  // namespace rt
