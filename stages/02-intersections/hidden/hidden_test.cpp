// Hidden stage 02 tests: graded by rt-grade (stages/02-intersections/grading.json), never
// released (rt-grade release skips hidden/), so students cannot tune their code to them.
#include "../tests/test_helpers.h"

namespace rt::stage02 {
namespace {

RT_TEST_SUITE(HiddenSphere, "ray-sphere");

// A grazing ray far from the origin: the stable quadratic still finds the near root.
TEST_F(HiddenSphere, FarAwayHit) {
    Hit hit;
    ASSERT_TRUE(intersect_sphere(Ray{Vec3(1000, 0, 5), Vec3(0, 0, -1)},
                                 rt::Sphere{Vec3(1000, 0, 0), 2, 0}, {}, hit));
    EXPECT_NEAR(hit.t, 3, Real(1e-3));
    expect_vec_near(hit.normal, Vec3(0, 0, 1), "normal of the far-away hit", Real(1e-3));
}

RT_TEST_SUITE(HiddenPlane, "ray-plane");

// A ray starting on the plane does not report it at t = 0 (open interval).
TEST_F(HiddenPlane, OriginOnPlaneMisses) {
    Hit hit = sentinel_hit();
    EXPECT_FALSE(intersect_plane(Ray{Vec3(0, 0, 0), Vec3(1, 0, 0)},
                                 rt::Plane{Vec3(0), Vec3(0, 1, 0), 0}, {}, hit));
    EXPECT_TRUE(untouched(hit));
}

}  // namespace
}  // namespace rt::stage02
