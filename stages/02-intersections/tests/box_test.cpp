// Ray-box (slabs) tests.
#include "test_helpers.h"

namespace rt::stage02 {
namespace {

RT_TEST_SUITE(Box, "ray-box-slabs");

const rt::Box kUnit{Vec3(-1), Vec3(1), 0};

TEST_F(Box, HitEntryFace) {
    Hit hit;
    ASSERT_TRUE(intersect_box(Ray{Vec3(0.5, 0.25, 5), Vec3(0, 0, -1)}, kUnit, {}, hit));
    EXPECT_NEAR(hit.t, 4, kTol);
    expect_vec_near(hit.normal, Vec3(0, 0, 1), "normal entering the +z face from z = 5");
    EXPECT_TRUE(hit.front_face) << "a ray entering from outside hits the front side";
}

// Entering through the -x face: the outward normal is -x.
TEST_F(Box, NormalOfEachFace) {
    const struct {
        Vec3 o, d, n;
    } cases[] = {{Vec3(-5, 0.1, 0.2), Vec3(1, 0, 0), Vec3(-1, 0, 0)},
                 {Vec3(5, 0.1, 0.2), Vec3(-1, 0, 0), Vec3(1, 0, 0)},
                 {Vec3(0.1, -5, 0.2), Vec3(0, 1, 0), Vec3(0, -1, 0)},
                 {Vec3(0.1, 5, 0.2), Vec3(0, -1, 0), Vec3(0, 1, 0)},
                 {Vec3(0.1, 0.2, -5), Vec3(0, 0, 1), Vec3(0, 0, -1)},
                 {Vec3(0.1, 0.2, 5), Vec3(0, 0, -1), Vec3(0, 0, 1)}};
    for (const auto& c : cases) {
        const std::string what =
            "ray from " + text(c.o) + " along " + text(c.d) + " into the face " + text(c.n);
        SCOPED_TRACE(what);
        Hit hit;
        ASSERT_TRUE(intersect_box(Ray{c.o, c.d}, kUnit, {}, hit));
        expect_vec_near(hit.normal, c.n, "normal, " + what);
        EXPECT_NEAR(hit.t, 4, kTol);
    }
}

// From inside, the exit face is hit and its normal turned to face the ray.
TEST_F(Box, FromInsideHitsExitFace) {
    Hit hit;
    ASSERT_TRUE(intersect_box(Ray{Vec3(0), Vec3(0, 2, 0)}, kUnit, {}, hit));
    EXPECT_NEAR(hit.t, 0.5, kTol);
    expect_vec_near(hit.normal, Vec3(0, -1, 0),
                    "normal leaving through the +y face from the centre, turned to face the ray");
    EXPECT_FALSE(hit.front_face) << "a ray from inside leaves through the +y face: its outward "
                                    "normal (0, 1, 0) points the way the ray goes, so the ray "
                                    "hits the back side (set_face_normal with the outward normal)";
}

TEST_F(Box, Oblique) {
    Hit hit;
    ASSERT_TRUE(intersect_box(Ray{Vec3(-3, -3, 0), Vec3(1, 1, 0)}, kUnit, {}, hit));
    EXPECT_NEAR(hit.t, 2, kTol);
}

TEST_F(Box, Misses) {
    Hit hit = sentinel_hit();
    EXPECT_FALSE(intersect_box(Ray{Vec3(-3, 0, 0), Vec3(1, 2, 0)}, kUnit, {}, hit));  // passes by
    EXPECT_FALSE(
        intersect_box(Ray{Vec3(-3, 0, 0), Vec3(-1, 0, 0)}, kUnit, {}, hit));  // points away
    EXPECT_FALSE(intersect_box(Ray{Vec3(0, 2, -5), Vec3(0, 0, 1)}, kUnit, {},
                               hit));  // parallel, outside slab
    EXPECT_TRUE(untouched(hit));
}

TEST_F(Box, RespectsTRange) {
    const Ray ray{Vec3(0, 0, 5), Vec3(0, 0, -1)};
    Hit hit;
    EXPECT_FALSE(intersect_box(ray, kUnit, Interval{0, 3.5f}, hit));
    ASSERT_TRUE(intersect_box(ray, kUnit, Interval{4.5f, kInfinity}, hit));
    EXPECT_NEAR(hit.t, 6, kTol);  // the exit face
}

TEST_F(Box, BadDirectionsMiss) {
    for (const Vec3& d : kBadDirections) {
        SCOPED_TRACE("direction " + text(d));
        Hit hit = sentinel_hit();
        EXPECT_FALSE(intersect_box(Ray{Vec3(0, 0, 5), d}, kUnit, {}, hit));
        EXPECT_FALSE(intersect_box(Ray{Vec3(0), d}, kUnit, {}, hit));  // even from inside
        EXPECT_TRUE(untouched(hit));
    }
}

}  // namespace
}  // namespace rt::stage02
