// Stage 07 tests: normal mapping. The flat texel (0.5, 0.5, 1) leaves the normal alone, tilted
// texels tilt it along the tangent and bitangent (OpenGL style: +y towards the image top),
// the tangent is made perpendicular first (Gram-Schmidt), and a normal bent away from the viewer
// is turned back to its side.
#include <cmath>

#include "stage_api/stage07.h"
#include "testing/expect_near.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(NormalMap);

using rt::testing::expect_vec_near;

const Vec3 kUp(0, 1, 0), kToViewer = glm::normalize(Vec3(0, 1, 1));

TEST_F(NormalMap, FlatTexelKeepsTheNormal) {
    expect_vec_near(normal_from_map(kUp, Vec3(1, 0, 0), Color(0.5f, 0.5f, 1), kToViewer), kUp,
                    "texel (0.5, 0.5, 1) on a floor");
}

TEST_F(NormalMap, TiltsAlongTangentAndBitangent) {
    // Floor: N = +y, T = +x, B = cross(N, T) = -z (towards the image top: v decreases).
    const Vec3 t(1, 0, 0);
    expect_vec_near(normal_from_map(kUp, t, Color(1, 0.5f, 0.5f), kToViewer),
                    glm::normalize(Vec3(1, 0, 0) * Real(1) + kUp * Real(0)),
                    "texel (1, 0.5, 0.5): m = (1, 0, 0), along T");
    expect_vec_near(normal_from_map(kUp, t, Color(0.5f, 1, 1), kToViewer),
                    glm::normalize(Vec3(0, 1, -1)), "texel (0.5, 1, 1): m = (0, 1, 1), B + N");
    const Vec3 n = normal_from_map(kUp, t, Color(0.75f, 0.5f, 1), kToViewer);
    EXPECT_NEAR(glm::length(n), 1, 1e-5) << "always unit length";
}

TEST_F(NormalMap, TangentIsOrthonormalisedFirst) {
    // A tangent that leans into the normal gives the same frame as its perpendicular part.
    const Vec3 leaning(2, 3, 0);
    expect_vec_near(normal_from_map(kUp, leaning, Color(1, 0.5f, 0.5f), kToViewer), Vec3(1, 0, 0),
                    "tangent (2, 3, 0) on N = +y acts as +x");
}

TEST_F(NormalMap, NeverFacesAwayFromTheViewer) {
    // m = (-1, 0, 0.2): tilted hard towards -x; a viewer low on the +x side would see its back.
    const Vec3 to_viewer = glm::normalize(Vec3(1, 0.1f, 0));
    const Vec3 n = normal_from_map(kUp, Vec3(1, 0, 0), Color(0, 0.5f, 0.6f), to_viewer);
    EXPECT_GE(glm::dot(n, to_viewer), -1e-6f) << "turned back to the viewer's side";
    EXPECT_NEAR(glm::length(n), 1, 1e-5);
}

TEST_F(NormalMap, DegenerateInputsKeepTheNormal) {
    expect_vec_near(normal_from_map(kUp, kUp, Color(1, 0.5f, 0.5f), kToViewer), kUp,
                    "tangent parallel to N");
    expect_vec_near(normal_from_map(kUp, Vec3(1, 0, 0), Color(0.5f), kToViewer), kUp,
                    "texel (0.5, 0.5, 0.5): m = 0");
}

}  // namespace
}  // namespace rt
