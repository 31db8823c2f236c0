// Ray-triangle (Cramer's rule) tests with closed-form answers. Shared edges, vertices, slivers,
// far geometry and comparisons with exact arithmetic are in cgal_exact_test.cpp.

#include "test_helpers.h"
#include "testing/random.h"

namespace rt::stage02 {
namespace {

RT_TEST_SUITE(Triangle, "ray-triangle-cramers-rule");

const Vec3 A(0, 0, 0), B(1, 0, 0), C(0, 1, 0);  // counter-clockwise seen from +z

TEST_F(Triangle, HitInside) {
    Hit hit;
    ASSERT_TRUE(intersect_triangle(Ray{Vec3(0.25, 0.25, 2), Vec3(0, 0, -1)}, A, B, C, {}, hit));
    EXPECT_NEAR(hit.t, 2, kTol);
    expect_vec_near(hit.point, Vec3(0.25, 0.25, 0), "point, ray down at (0.25, 0.25)");
    expect_vec_near(hit.normal, Vec3(0, 0, 1),
                    "normal, seen from the front: normalize(cross(b - a, c - a))");
    EXPECT_TRUE(hit.front_face) << "seen from +z the triangle is counter-clockwise: the front";
    EXPECT_NEAR(hit.uv.x, 0.25, kTol) << "uv.x is beta, the weight of b";
    EXPECT_NEAR(hit.uv.y, 0.25, kTol) << "uv.y is gamma, the weight of c";
}

// Seen from behind (clockwise), the triangle is still hit; the normal faces the ray.
TEST_F(Triangle, BackFaceIsHit) {
    Hit hit;
    ASSERT_TRUE(intersect_triangle(Ray{Vec3(0.2, 0.3, -1), Vec3(0, 0, 1)}, A, B, C, {}, hit));
    expect_vec_near(hit.normal, Vec3(0, 0, -1), "normal, seen from behind: turned to face the ray");
    EXPECT_FALSE(hit.front_face) << "seen from -z the triangle is clockwise: the back side";
}

TEST_F(Triangle, MissOutsideEachEdge) {
    for (const Vec3& o : {Vec3(-0.1, 0.5, 1), Vec3(0.5, -0.1, 1), Vec3(0.6, 0.6, 1)}) {
        Hit hit = sentinel_hit();
        EXPECT_FALSE(intersect_triangle(Ray{o, Vec3(0, 0, -1)}, A, B, C, {}, hit))
            << "ray straight down at (" << o.x << ", " << o.y << "), just outside an edge of the "
            << "triangle (0, 0, 0), (1, 0, 0), (0, 1, 0)";
        EXPECT_TRUE(untouched(hit));
    }
}

// Points exactly on an edge or at a vertex count as inside (beta >= 0, not > 0). These points
// are exact in float, so Cramer's rule gives exact zeros here.
TEST_F(Triangle, EdgesAndVerticesCount) {
    for (const Vec3& o : {Vec3(0.5, 0, 1), Vec3(0, 0.5, 1), Vec3(0.5, 0.5, 1), Vec3(0, 0, 1),
                          Vec3(1, 0, 1), Vec3(0, 1, 1)}) {
        Hit hit;
        EXPECT_TRUE(intersect_triangle(Ray{o, Vec3(0, 0, -1)}, A, B, C, {}, hit))
            << "ray straight down at (" << o.x << ", " << o.y << "), exactly on an edge or a "
            << "vertex of the triangle (0, 0, 0), (1, 0, 0), (0, 1, 0): inside, since beta >= 0, "
            << "gamma >= 0 and beta + gamma <= 1 include equality";
    }
}

// Rays aimed at a random point of a random triangle hit it, and the barycentrics reproduce both
// the aimed-at weights and the hit point: p = (1 - beta - gamma) a + beta b + gamma c.
TEST_F(Triangle, BarycentricsReproduceThePoint) {
    testing::Random random(2);
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3 a = random.vec(-1, 1);
        const Vec3 b = random.vec(-1, 1);
        const Vec3 c = random.vec(-1, 1);
        Real beta0 = Real(random.uniform(0.05, 0.9));
        Real gamma0 = Real(random.uniform(0.05, 0.9));
        if (beta0 + gamma0 > Real(0.95)) {
            beta0 *= Real(0.5);
            gamma0 *= Real(0.5);
        }
        const Vec3 target = (1 - beta0 - gamma0) * a + beta0 * b + gamma0 * c;
        const Vec3 origin(Real(random.uniform(-1, 1)), Real(random.uniform(-1, 1)), 4);
        const Ray aimed{origin, target - origin};
        SCOPED_TRACE(::testing::Message()
                     << "random triangle " << i << ": a " << text(a) << ", b " << text(b) << ", c "
                     << text(c) << ", aimed at beta " << beta0 << ", gamma " << gamma0);
        Hit hit;
        if (!intersect_triangle(aimed, a, b, c, {}, hit)) continue;
        ++hits;
        const Real beta = hit.uv.x, gamma = hit.uv.y;
        EXPECT_NEAR(beta, beta0, Real(1e-3));
        EXPECT_NEAR(gamma, gamma0, Real(1e-3));
        EXPECT_NEAR(hit.t, 1, Real(1e-3));
        expect_vec_near((1 - beta - gamma) * a + beta * b + gamma * c, hit.point,
                        "(1 - beta - gamma) a + beta b + gamma c against hit.point", Real(1e-3));
        expect_vec_near(aimed.at(hit.t), hit.point, "ray.at(hit.t) against hit.point", Real(1e-5));
    }
    // Only triangles seen almost edge-on may be missed.
    EXPECT_GT(hits, 490);
}

TEST_F(Triangle, RespectsTRange) {
    const Ray ray{Vec3(0.2, 0.2, 2), Vec3(0, 0, -1)};
    Hit hit;
    EXPECT_FALSE(intersect_triangle(ray, A, B, C, Interval{0, 1.5f}, hit));
    EXPECT_FALSE(intersect_triangle(ray, A, B, C, Interval{2.5f, kInfinity}, hit));
    EXPECT_TRUE(intersect_triangle(ray, A, B, C, Interval{1.5f, 2.5f}, hit));
}

// A ray in the triangle's plane, and a degenerate (zero-area) triangle, never hit.
TEST_F(Triangle, ParallelAndDegenerateMiss) {
    Hit hit = sentinel_hit();
    EXPECT_FALSE(intersect_triangle(Ray{Vec3(-1, 0.2, 0), Vec3(1, 0, 0)}, A, B, C, {}, hit));
    EXPECT_FALSE(
        intersect_triangle(Ray{Vec3(0.5, 0, 1), Vec3(0, 0, -1)}, A, B, Vec3(2, 0, 0), {}, hit));
    EXPECT_TRUE(untouched(hit));
}

TEST_F(Triangle, BadDirectionsMiss) {
    for (const Vec3& d : kBadDirections) {
        SCOPED_TRACE("direction " + text(d));
        Hit hit = sentinel_hit();
        EXPECT_FALSE(intersect_triangle(Ray{Vec3(0.2, 0.2, 1), d}, A, B, C, {}, hit));
        EXPECT_TRUE(untouched(hit));
    }
}

}  // namespace
}  // namespace rt::stage02
