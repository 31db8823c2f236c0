// Stage 08 tests: cube_face_uv against the OpenGL table, face by face, at edges and corners (the
// documented tie order), for any length; every face reachable; the round trip through the
// table's inverse; neighbouring faces agreeing along their shared edge.
#include <array>

#include "stage_api/stage08.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(CubeMap, "2-cube-map-faces");

constexpr Real kFaceTol = 1e-6f;
const char* const kNames[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};

void expect_face(const Vec3& d, int face, Real u, Real v) {
    const CubeFaceUv r = cube_face_uv(d);
    const std::string what = "direction (" + std::to_string(d.x) + ", " + std::to_string(d.y) +
                             ", " + std::to_string(d.z) + ")";
    ASSERT_EQ(r.face, face) << what << " must be on face " << kNames[face] << ", got face "
                            << r.face;
    EXPECT_NEAR(r.uv.x, u, kFaceTol) << what << ": u";
    EXPECT_NEAR(r.uv.y, v, kFaceTol) << what << ": v";
}

TEST_F(CubeMap, AxesHitTheCenterOfTheirFace) {
    expect_face(Vec3(1, 0, 0), 0, 0.5f, 0.5f);
    expect_face(Vec3(-1, 0, 0), 1, 0.5f, 0.5f);
    expect_face(Vec3(0, 1, 0), 2, 0.5f, 0.5f);
    expect_face(Vec3(0, -1, 0), 3, 0.5f, 0.5f);
    expect_face(Vec3(0, 0, 1), 4, 0.5f, 0.5f);
    expect_face(Vec3(0, 0, -1), 5, 0.5f, 0.5f);
}

// One off-centre direction per face, (u, v) worked out from the table by hand:
// u = (sc/|ma| + 1)/2, v = (tc/|ma| + 1)/2.
TEST_F(CubeMap, EachFaceFollowsTheOpenGlTable) {
    expect_face(Vec3(1, 0.5f, 0.25f), 0, 0.375f, 0.25f);   // sc = -z, tc = -y
    expect_face(Vec3(-1, 0.5f, 0.25f), 1, 0.625f, 0.25f);  // sc = +z, tc = -y
    expect_face(Vec3(0.25f, 1, 0.5f), 2, 0.625f, 0.75f);   // sc = +x, tc = +z
    expect_face(Vec3(0.25f, -1, 0.5f), 3, 0.625f, 0.25f);  // sc = +x, tc = -z
    expect_face(Vec3(0.25f, 0.5f, 1), 4, 0.625f, 0.25f);   // sc = +x, tc = -y
    expect_face(Vec3(0.25f, 0.5f, -1), 5, 0.375f, 0.25f);  // sc = -x, tc = -y
}

TEST_F(CubeMap, AnyLengthGivesTheSameFaceAndUv) {
    for (Real scale : {Real(1e-3), Real(0.5), Real(7), Real(1e4)}) {
        expect_face(scale * Vec3(1, 0.5f, 0.25f), 0, 0.375f, 0.25f);
        expect_face(scale * Vec3(0.25f, 0.5f, -1), 5, 0.375f, 0.25f);
    }
}

TEST_F(CubeMap, TiesGoToXThenYThenZ) {
    expect_face(Vec3(1, 1, 0), 0, 0.5f, 0);    // edge +x/+y: +x
    expect_face(Vec3(-1, 0, 1), 1, 1, 0.5f);   // edge -x/+z: -x
    expect_face(Vec3(0, 1, 1), 2, 0.5f, 1);    // edge +y/+z: +y
    expect_face(Vec3(0, -1, -1), 3, 0.5f, 1);  // edge -y/-z: -y
    expect_face(Vec3(1, 0, -1), 0, 1, 0.5f);   // edge +x/-z: +x
    expect_face(Vec3(1, 1, 1), 0, 0, 0);       // corners: x
    expect_face(Vec3(-1, -1, -1), 1, 0, 1);
    expect_face(Vec3(2, -2, 2), 0, 0, 1);
}

TEST_F(CubeMap, EveryFaceIsReachedByTheDirectionsAroundIt) {
    std::array<int, 6> count{};
    const int n = 600;
    for (int k = 0; k < n; ++k) {
        const Real y = 1 - 2 * (Real(k) + 0.5f) / Real(n);
        const Real r = std::sqrt(1 - y * y), a = Real(k) * 2.39996323f;
        const Vec3 d(r * std::cos(a), y, r * std::sin(a));
        const CubeFaceUv f = cube_face_uv(d);
        ASSERT_GE(f.face, 0);
        ASSERT_LT(f.face, 6);
        ++count[std::size_t(f.face)];
        // The face's axis is the largest component, with the face's sign.
        const int axis = f.face / 2;
        const Real major = d[axis];
        EXPECT_EQ(major > 0, f.face % 2 == 0) << "direction " << k;
        for (int other = 0; other < 3; ++other)
            EXPECT_GE(std::abs(major), std::abs(d[other])) << "direction " << k;
        EXPECT_TRUE(f.uv.x >= 0 && f.uv.x <= 1 && f.uv.y >= 0 && f.uv.y <= 1) << "direction " << k;
    }
    for (int face = 0; face < 6; ++face)
        EXPECT_GT(count[std::size_t(face)], n / 12) << "face " << kNames[face] << " is rarely hit";
}

// The table read backwards: the direction (on the unit cube) of (u, v) on `face`.
Vec3 direction_of(int face, Vec2 uv) {
    const Real sc = 2 * uv.x - 1, tc = 2 * uv.y - 1;
    switch (face) {
        case 0:
            return Vec3(1, -tc, -sc);
        case 1:
            return Vec3(-1, -tc, sc);
        case 2:
            return Vec3(sc, 1, tc);
        case 3:
            return Vec3(sc, -1, -tc);
        case 4:
            return Vec3(sc, -tc, 1);
        default:
            return Vec3(-sc, -tc, -1);
    }
}

TEST_F(CubeMap, RoundTripThroughTheInverseTable) {
    for (int face = 0; face < 6; ++face)
        for (Real u : {Real(0.05), Real(0.3), Real(0.5), Real(0.8), Real(0.97)})
            for (Real v : {Real(0.02), Real(0.4), Real(0.75), Real(0.99)}) {
                const Vec3 d = direction_of(face, Vec2(u, v));
                const CubeFaceUv r = cube_face_uv(Real(5) * d);
                ASSERT_EQ(r.face, face)
                    << "(u, v) = (" << u << ", " << v << ") on " << kNames[face];
                EXPECT_NEAR(r.uv.x, u, 1e-5f) << kNames[face];
                EXPECT_NEAR(r.uv.y, v, 1e-5f) << kNames[face];
                const Vec3 back = direction_of(r.face, r.uv);
                EXPECT_NEAR(glm::length(glm::normalize(back) - glm::normalize(d)), 0, 1e-5f);
            }
}

// Either side of an edge, two faces meet with the same position along the edge: with the
// unfolded cross of the conventions, +z's right edge (u = 1) meets +x's left edge (u = 0), and
// +y's bottom edge (v = 1) meets +z's top edge (v = 0).
TEST_F(CubeMap, NeighbouringFacesAgreeAlongTheirEdge) {
    const Real e = 1e-4f;
    for (Real t : {Real(-0.8), Real(-0.3), Real(0.1), Real(0.6)}) {
        const CubeFaceUv x = cube_face_uv(Vec3(1, t, 1 - e)), z = cube_face_uv(Vec3(1 - e, t, 1));
        ASSERT_EQ(x.face, 0);
        ASSERT_EQ(z.face, 4);
        EXPECT_NEAR(x.uv.x, 0, 1e-3f);
        EXPECT_NEAR(z.uv.x, 1, 1e-3f);
        EXPECT_NEAR(x.uv.y, z.uv.y, 1e-3f) << "v must match across the +x/+z edge";
        const CubeFaceUv y = cube_face_uv(Vec3(t, 1, 1 - e)), z2 = cube_face_uv(Vec3(t, 1 - e, 1));
        ASSERT_EQ(y.face, 2);
        ASSERT_EQ(z2.face, 4);
        EXPECT_NEAR(y.uv.y, 1, 1e-3f);
        EXPECT_NEAR(z2.uv.y, 0, 1e-3f);
        EXPECT_NEAR(y.uv.x, z2.uv.x, 1e-3f) << "u must match across the +y/+z edge";
    }
}

}  // namespace
}  // namespace rt
