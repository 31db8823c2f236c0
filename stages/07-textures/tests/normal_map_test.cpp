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

RT_TEST_SUITE(NormalMap, "normal-mapping");

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

TEST_F(NormalMap, TheFrameIsOrthonormal) {
    // The pure texels (1, .5, .5), (.5, 1, .5) and (.5, .5, 1) give T', B and N themselves: unit
    // length, mutually perpendicular, right-handed (B = N x T'), for leaning tangents too.
    const Vec3 normals[] = {glm::normalize(Vec3(0.2f, 1, -0.3f)), glm::normalize(Vec3(-1, 0.1f, 0)),
                            glm::normalize(Vec3(0.3f, -0.4f, 0.8f))};
    const Vec3 tangents[] = {Vec3(1, 0.5f, 0), Vec3(0, 2, 1), Vec3(1, 1, 1)};
    for (int k = 0; k < 3; ++k) {
        const Vec3& n = normals[k];
        const Vec3 t = normal_from_map(n, tangents[k], Color(1, 0.5f, 0.5f), n);
        const Vec3 b = normal_from_map(n, tangents[k], Color(0.5f, 1, 0.5f), n);
        const Vec3 same = normal_from_map(n, tangents[k], Color(0.5f, 0.5f, 1), n);
        EXPECT_NEAR(glm::length(t), 1, 1e-5) << "case " << k;
        EXPECT_NEAR(glm::length(b), 1, 1e-5) << "case " << k;
        EXPECT_NEAR(glm::dot(t, n), 0, 1e-5) << "T' is perpendicular to N, case " << k;
        EXPECT_NEAR(glm::dot(b, n), 0, 1e-5) << "B is perpendicular to N, case " << k;
        EXPECT_NEAR(glm::dot(t, b), 0, 1e-5) << "T' is perpendicular to B, case " << k;
        expect_vec_near(b, glm::cross(n, t), "B = cross(N, T')");
        expect_vec_near(same, n, "the flat texel");
    }
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
