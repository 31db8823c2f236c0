// Stage 05 image tests: each scene of stages/05-recursion/scenes rendered with your code and
// compared with reference_images/05-recursion/.
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(Image);

void check(const char* scene) {
    testing::expect_matches_reference("05-recursion", scene);
}

TEST_F(Image, Reflection) {
    check("reflection");
}
TEST_F(Image, Refraction) {
    check("refraction");
}
TEST_F(Image, MirrorBox) {
    check("mirror_box");
}
TEST_F(Image, TransparentCube) {
    check("transparent_cube");
}
TEST_F(Image, RefractingCylinder) {
    check("refracting_cylinder");
}
TEST_F(Image, Whitted) {
    check("whitted");
}

}  // namespace
}  // namespace rt
