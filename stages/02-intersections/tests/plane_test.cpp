// Ray-plane tests.
#include "test_helpers.h"

namespace rt::stage02 {
namespace {

RT_TEST_SUITE(Plane, "ray-plane");

TEST_F(Plane, HitFromAbove) {
    Hit hit;
    ASSERT_TRUE(intersect_plane(Ray{Vec3(1, 3, 2), Vec3(0, -1, 0)},
                                rt::Plane{Vec3(0, -1, 0), Vec3(0, 1, 0), 0}, {}, hit));
    EXPECT_NEAR(hit.t, 4, kTol);
    expect_vec_near(hit.point, Vec3(1, -1, 2), "point, ray straight down onto y = -1");
    expect_vec_near(hit.normal, Vec3(0, 1, 0), "normal, ray from above: the plane's normal");
    EXPECT_TRUE(hit.front_face) << "a ray from the side the normal points to hits the front";
}

// From below, the normal is flipped to face the ray and front_face is false.
TEST_F(Plane, HitFromBelowFacesRay) {
    Hit hit;
    ASSERT_TRUE(intersect_plane(Ray{Vec3(0, -3, 0), Vec3(0, 2, 0)},
                                rt::Plane{Vec3(0), Vec3(0, 1, 0), 0}, {}, hit));
    EXPECT_NEAR(hit.t, 1.5, kTol);
    expect_vec_near(hit.normal, Vec3(0, -1, 0),
                    "normal, ray from below: the plane's normal turned to face the ray");
    EXPECT_FALSE(hit.front_face) << "a ray from below hits the back side (set_face_normal with "
                                    "plane.normal)";
}

// An oblique ray: t from the closed form n.(p - o) / n.d.
TEST_F(Plane, ObliqueRay) {
    const Vec3 n = glm::normalize(Vec3(1, 1, 0));
    Hit hit;
    ASSERT_TRUE(
        intersect_plane(Ray{Vec3(0), Vec3(1, 0, 0)}, rt::Plane{Vec3(2, 0, 0), n, 0}, {}, hit));
    EXPECT_NEAR(hit.t, 2, kTol);
}

// Parallel rays miss, whether above the plane or lying in it.
TEST_F(Plane, ParallelAndInPlaneRaysMiss) {
    const rt::Plane p{Vec3(0), Vec3(0, 1, 0), 0};
    Hit hit = sentinel_hit();
    EXPECT_FALSE(intersect_plane(Ray{Vec3(0, 1, 0), Vec3(1, 0, 0)}, p, {}, hit));
    EXPECT_FALSE(intersect_plane(Ray{Vec3(0, 0, 0), Vec3(1, 0, 1)}, p, {}, hit));
    EXPECT_TRUE(untouched(hit));
}

// An origin on the plane gives t = 0, outside the open range (0, inf).
TEST_F(Plane, OriginOnPlaneIsNotAHit) {
    Hit hit = sentinel_hit();
    EXPECT_FALSE(intersect_plane(Ray{Vec3(3, 0, 4), Vec3(0, 1, 1)},
                                 rt::Plane{Vec3(0), Vec3(0, 1, 0), 0}, {}, hit));
    EXPECT_TRUE(untouched(hit));
}

TEST_F(Plane, BehindTheRayMisses) {
    Hit hit;
    EXPECT_FALSE(intersect_plane(Ray{Vec3(0, 1, 0), Vec3(0, 1, 0)},
                                 rt::Plane{Vec3(0), Vec3(0, 1, 0), 0}, {}, hit));
}

TEST_F(Plane, BadDirectionsMiss) {
    for (const Vec3& d : kBadDirections) {
        SCOPED_TRACE("direction " + text(d));
        Hit hit = sentinel_hit();
        EXPECT_FALSE(
            intersect_plane(Ray{Vec3(0, 1, 0), d}, rt::Plane{Vec3(0), Vec3(0, 1, 0), 0}, {}, hit));
        EXPECT_TRUE(untouched(hit));
    }
}

}  // namespace
}  // namespace rt::stage02
