// Stage 03 image tests: each scene of stages/03-blinn-phong/scenes rendered with your code and
// compared with reference_images/03-blinn-phong/.
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(Image);

void check(const char* scene) {
    testing::expect_matches_reference("03-blinn-phong", scene);
}

TEST_F(Image, DirectLight) {
    check("direct_light");
}
TEST_F(Image, AmbientOnly) {
    check("ambient_only");
}
TEST_F(Image, DiffuseOnly) {
    check("diffuse_only");
}
TEST_F(Image, SpecularOnly) {
    check("specular_only");
}
TEST_F(Image, Attenuation) {
    check("attenuation");
}

}  // namespace
}  // namespace rt
