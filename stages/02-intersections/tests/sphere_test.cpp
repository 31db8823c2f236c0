// Ray-sphere tests with closed-form answers. The exact-arithmetic checks are in
// cgal_exact_shapes_test.cpp.
#include "test_helpers.h"

namespace rt::stage02 {
namespace {

RT_TEST_SUITE(Sphere, "ray-sphere");

// A ray from z = 5 towards the origin hits the unit sphere at z = 1, t = 4, normal +z.
TEST_F(Sphere, HitFromOutside) {
    Hit hit;
    ASSERT_TRUE(
        intersect_sphere(Ray{Vec3(0, 0, 5), Vec3(0, 0, -1)}, rt::Sphere{Vec3(0), 1, 0}, {}, hit));
    EXPECT_NEAR(hit.t, 4, kTol);
    expect_vec_near(hit.point, Vec3(0, 0, 1), "point, ray from z = 5 to the unit sphere");
    expect_vec_near(hit.normal, Vec3(0, 0, 1), "normal, ray from z = 5 to the unit sphere");
    EXPECT_TRUE(hit.front_face) << "a ray from outside hits the front side";
}

// From the centre the only root in (0, inf) is the far one; the normal faces the ray (inwards).
TEST_F(Sphere, HitFromInsideFacesRay) {
    Hit hit;
    ASSERT_TRUE(intersect_sphere(Ray{Vec3(1, 2, 3), Vec3(1, 0, 0)}, rt::Sphere{Vec3(1, 2, 3), 2, 0},
                                 {}, hit));
    EXPECT_NEAR(hit.t, 2, kTol);
    expect_vec_near(hit.normal, Vec3(-1, 0, 0),
                    "normal, ray from the centre along +x: (p - c) / r turned to face the ray");
    EXPECT_FALSE(hit.front_face) << "a ray from inside hits the back side (set_face_normal with "
                                    "the outward normal (p - c) / r)";
}

// t is in units of the direction's length: doubling the direction halves t.
TEST_F(Sphere, NonUnitDirection) {
    Hit hit;
    ASSERT_TRUE(
        intersect_sphere(Ray{Vec3(0, 0, 5), Vec3(0, 0, -2)}, rt::Sphere{Vec3(0), 1, 0}, {}, hit));
    EXPECT_NEAR(hit.t, 2, kTol);
    expect_vec_near(hit.point, Vec3(0, 0, 1), "point, direction (0, 0, -2) from z = 5");
}

TEST_F(Sphere, MissLeavesHitUntouched) {
    Hit hit = sentinel_hit();
    EXPECT_FALSE(
        intersect_sphere(Ray{Vec3(0, 3, 5), Vec3(0, 0, -1)}, rt::Sphere{Vec3(0), 1, 0}, {}, hit));
    EXPECT_TRUE(untouched(hit));
}

// Sphere behind the ray: both roots negative.
TEST_F(Sphere, BehindTheRayMisses) {
    Hit hit = sentinel_hit();
    EXPECT_FALSE(
        intersect_sphere(Ray{Vec3(0, 0, 5), Vec3(0, 0, 1)}, rt::Sphere{Vec3(0), 1, 0}, {}, hit));
    EXPECT_TRUE(untouched(hit));
}

// The t-range is respected at both ends: the near root is excluded by tmax and by tmin.
TEST_F(Sphere, RespectsTRange) {
    const Ray ray{Vec3(0, 0, 5), Vec3(0, 0, -1)};
    const rt::Sphere s{Vec3(0), 1, 0};
    Hit hit;
    EXPECT_FALSE(intersect_sphere(ray, s, Interval{0, 3.9f}, hit));
    ASSERT_TRUE(intersect_sphere(ray, s, Interval{4.5f, kInfinity}, hit));
    EXPECT_NEAR(hit.t, 6, kTol);  // the far root
    EXPECT_FALSE(intersect_sphere(ray, s, Interval{6.5f, kInfinity}, hit));
}

// uv is (0, 0) on a sphere: its texture coordinates are stage 07's, at the shaded hit only.
TEST_F(Sphere, SurfaceCoordinatesAreZero) {
    Hit hit;
    hit.uv = Vec2(0.25, 0.5);
    ASSERT_TRUE(
        intersect_sphere(Ray{Vec3(0, 0, 5), Vec3(0, 0, -1)}, rt::Sphere{Vec3(0), 1, 0}, {}, hit));
    EXPECT_EQ(hit.uv, Vec2(0));
}

// A small sphere far away: the textbook b^2 - 4ac loses every digit in float; the stable form
// does not. Distance 1e4, radius 1: t must be 1e4 - 1 to float precision.
TEST_F(Sphere, SmallSphereFarAway) {
    Hit hit;
    ASSERT_TRUE(intersect_sphere(Ray{Vec3(0, 0, 0), Vec3(0, 0, -1)},
                                 rt::Sphere{Vec3(0, 0, -1e4f), 1, 0}, {}, hit));
    EXPECT_NEAR(hit.t, 9999, 9999 * 4 * std::numeric_limits<Real>::epsilon())
        << "the sphere's near side is at t = 9999: t = 10000 means the discriminant came out 0, "
           "which is what b^2 - a c gives when its two terms (about 1e8 each) cancel in float; "
           "compute it from the ray's offset from the centre instead: read "
           "stages/02-intersections/README.md#a-stable-quadratic";
}

TEST_F(Sphere, BadDirectionsMiss) {
    for (const Vec3& d : kBadDirections) {
        SCOPED_TRACE("direction " + text(d));
        Hit hit = sentinel_hit();
        EXPECT_FALSE(intersect_sphere(Ray{Vec3(0, 0, 5), d}, rt::Sphere{Vec3(0), 1, 0}, {}, hit));
        EXPECT_TRUE(untouched(hit));
    }
}

}  // namespace
}  // namespace rt::stage02
