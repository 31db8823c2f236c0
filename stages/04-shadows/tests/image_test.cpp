// Stage 04 image tests: each scene of stages/04-shadows/scenes rendered with your code and
// compared with reference_images/04-shadows/.
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(Image);

void check(const char* scene) {
    testing::expect_matches_reference("04-shadows", scene);
}

TEST_F(Image, Shadows) {
    check("shadows");
}
TEST_F(Image, CornellBox) {
    check("cornell_box");
}
TEST_F(Image, GlassShadows) {
    check("glass_shadows");
}
TEST_F(Image, FarFromOrigin) {
    check("far_from_origin");
}

}  // namespace
}  // namespace rt
