// Nearest hit over a scene.
#include "test_helpers.h"

namespace rt::stage02 {
namespace {

RT_TEST_SUITE(Nearest, "nearest-hit");

// Three primitives along -z, added in an order that is not the depth order.
Scene row_scene() {
    Scene s;
    s.materials.resize(4);
    s.spheres.push_back(rt::Sphere{Vec3(0, 0, -10), 1, 1});
    s.planes.push_back(rt::Plane{Vec3(0, 0, -20), Vec3(0, 0, 1), 2});
    s.vertices = {Vec3(-1, -1, -5), Vec3(1, -1, -5), Vec3(0, 1, -5)};
    s.triangles.push_back(rt::Triangle{{0, 1, 2}, 3});
    s.boxes.push_back(rt::Box{Vec3(-1, -1, -16), Vec3(1, 1, -14), 0});
    return s;
}

TEST_F(Nearest, FindsTheClosest) {
    const Scene s = row_scene();
    Hit hit;
    ASSERT_TRUE(intersect_nearest(Ray{Vec3(0), Vec3(0, 0, -1)}, s, {}, hit));
    EXPECT_NEAR(hit.t, 5, kTol);
    EXPECT_EQ(hit.primitive, s.primitive_id(rt::Scene::Kind::Triangle, 0));
    EXPECT_EQ(hit.material, 3);
}

// Shrinking tmin past each primitive reveals the next one, with its id and material.
TEST_F(Nearest, RangeSelectsEachPrimitive) {
    const Scene s = row_scene();
    const struct {
        Real tmin, t;
        rt::Scene::Kind kind;
        int material;
    } expected[] = {{6, 9, rt::Scene::Kind::Sphere, 1},
                    {12, 14, rt::Scene::Kind::Box, 0},
                    {17, 20, rt::Scene::Kind::Plane, 2}};
    for (const auto& e : expected) {
        SCOPED_TRACE(::testing::Message() << "t_range.min = " << e.tmin
                                          << ": the nearest hit is then the one at t = " << e.t);
        Hit hit;
        ASSERT_TRUE(
            intersect_nearest(Ray{Vec3(0), Vec3(0, 0, -1)}, s, Interval{e.tmin, kInfinity}, hit));
        EXPECT_NEAR(hit.t, e.t, kTol);
        EXPECT_EQ(hit.primitive, s.primitive_id(e.kind, 0));
        EXPECT_EQ(hit.material, e.material);
    }
}

TEST_F(Nearest, EmptySceneMisses) {
    Scene s;
    Hit hit = sentinel_hit();
    EXPECT_FALSE(intersect_nearest(Ray{Vec3(0), Vec3(0, 0, -1)}, s, {}, hit));
    EXPECT_TRUE(untouched(hit));
}

// Stage 10's motion blur: a moving sphere is met where it is at the ray's time
// (scene.sphere_at(i, ray.time)), not where it is stored.
TEST_F(Nearest, AMovingSphereIsWhereItIsAtTheRaysTime) {
    Scene s;
    s.materials.resize(1);
    s.spheres.push_back(rt::Sphere{Vec3(0, 0, -10), 1, 0});
    s.moving_spheres.push_back(rt::MovingSphere{0, Vec3(0, 4, 0)});
    Hit hit;
    Ray up{Vec3(0, 2, 0), Vec3(0, 0, -1)};
    EXPECT_FALSE(intersect_nearest(up, s, {}, hit))
        << "at time 0 the sphere is at (0, 0, -10): a ray at y = 2 passes above it";
    up.time = 0.5;
    ASSERT_TRUE(intersect_nearest(up, s, {}, hit))
        << "at time 0.5 the sphere is at (0, 2, -10): read spheres as scene.sphere_at(i, "
           "ray.time)";
    EXPECT_NEAR(hit.t, 9, kTol);
    EXPECT_NEAR(hit.normal.y, 0, kTol);
}

TEST_F(Nearest, TMaxExcludesEverything) {
    const Scene s = row_scene();
    Hit hit;
    EXPECT_FALSE(intersect_nearest(Ray{Vec3(0), Vec3(0, 0, -1)}, s, Interval{0, 4}, hit));
}

}  // namespace
}  // namespace rt::stage02
