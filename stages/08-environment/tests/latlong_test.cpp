// Stage 08 tests: latlong_uv at the axes, the poles, the seam (at -z), for any length, and the mapping's
// inverse, the framework's latlong_direction (docs/conventions.md#environment-maps).
#include <cmath>
#include <numbers>

#include "scene/procedural_sky.h"
#include "stage_api/stage08.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(LatLong, "1-lat-long-coordinates");

constexpr Real kPiUv = std::numbers::pi_v<Real>;
constexpr Real kUvTol = 1e-5f;

void expect_uv(const Vec3& d, Real u, Real v) {
    const Vec2 uv = latlong_uv(d);
    EXPECT_NEAR(uv.x, u, kUvTol) << "u of direction (" << d.x << ", " << d.y << ", " << d.z << ")";
    EXPECT_NEAR(uv.y, v, kUvTol) << "v of direction (" << d.x << ", " << d.y << ", " << d.z << ")";
}

TEST_F(LatLong, HorizontalAxesAreQuartersOfU) {
    expect_uv(Vec3(0, 0, -1), 0, 0.5f);
    expect_uv(Vec3(1, 0, 0), 0.25f, 0.5f);
    expect_uv(Vec3(0, 0, 1), 0.5f, 0.5f);
    expect_uv(Vec3(-1, 0, 0), 0.75f, 0.5f);
}

TEST_F(LatLong, VIsZeroStraightUpAndOneStraightDown) {
    EXPECT_NEAR(latlong_uv(Vec3(0, 1, 0)).y, 0, kUvTol);
    EXPECT_NEAR(latlong_uv(Vec3(0, -1, 0)).y, 1, kUvTol);
    expect_uv(Vec3(1, 1, 0), 0.25f, 0.25f);  // 45 degrees above +x
    expect_uv(Vec3(0, -1, 1), 0.5f, 0.75f);  // 45 degrees below +z
}

TEST_F(LatLong, AnyLengthGivesTheSameCoordinates) {
    for (Real scale : {Real(1e-3), Real(0.5), Real(7), Real(1e4)}) {
        expect_uv(scale * Vec3(1, 0, 0), 0.25f, 0.5f);
        expect_uv(scale * Vec3(-1, 1, 0), 0.75f, 0.25f);
    }
}

TEST_F(LatLong, PolesNeverGiveNaN) {
    // Nearly vertical directions whose normalised y may round above 1 (a very short one does:
    // y * y is subnormal in float, and (0, 1e-20, 0) normalises to y = 1.0000026).
    for (const Vec3& d : {Vec3(1e-20f, 5, 0), Vec3(0, -3, 1e-30f), Vec3(0, 1, 0),
                          Vec3(0, 1e-20f, 0), Vec3(0, -3e-20f, 0)}) {
        const Vec2 uv = latlong_uv(d);
        EXPECT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y))
            << "direction (" << d.x << ", " << d.y << ", " << d.z
            << "): clamp d.y to [-1, 1] before acos";
        EXPECT_GE(uv.x, 0);
        EXPECT_LT(uv.x, 1);
        EXPECT_NEAR(uv.y, d.y > 0 ? 0 : 1, kUvTol);
    }
}

TEST_F(LatLong, TheSeamIsAtMinusZAndUStaysBelowOne) {
    // Just past -z towards -x, u is just below 1; just past towards +x, just above 0.
    const Real eps = 0.01f;
    expect_uv(Vec3(-eps, 0, -1), 1 - std::atan(eps) / (2 * kPiUv), 0.5f);
    expect_uv(Vec3(eps, 0, -1), std::atan(eps) / (2 * kPiUv), 0.5f);
    // On the seam itself (x = +0 or -0) and a hair beside it, u is in [0, 1).
    for (Real x : {Real(0), -Real(0), Real(-1e-9), Real(-1e-30), Real(-1e-7)}) {
        const Real u = latlong_uv(Vec3(x, 0, -1)).x;
        EXPECT_GE(u, 0) << "x = " << x;
        EXPECT_LT(u, 1) << "x = " << x << ": u must stay in [0, 1)";
    }
}

TEST_F(LatLong, RoundTripThroughTheInverse) {
    // Directions spread over the sphere (a Fibonacci lattice), poles excluded.
    const int n = 500;
    for (int k = 0; k < n; ++k) {
        const Real y = 1 - 2 * (Real(k) + 0.5f) / Real(n);
        const Real r = std::sqrt(1 - y * y), a = Real(k) * 2.39996323f;
        const Vec3 d(r * std::cos(a), y, r * std::sin(a));
        const Vec2 uv = latlong_uv(Real(3) * d);
        ASSERT_GE(uv.x, 0);
        ASSERT_LT(uv.x, 1);
        ASSERT_GE(uv.y, 0);
        ASSERT_LE(uv.y, 1);
        const Vec3 back = latlong_direction(uv.x, uv.y);  // the framework's inverse
        EXPECT_NEAR(glm::length(back - d), 0, 1e-4f) << "direction " << k;
    }
}

}  // namespace
}  // namespace rt
