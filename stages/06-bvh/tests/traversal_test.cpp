// Stage 06 traversal tests: the slab test on its hard cases, and the BVH's answers compared with
// stage 02's loop over every primitive, ray by ray, on random and on deliberately hard rays.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "bvh_test_support.h"
#include "remote/call_each.h"
#include "render/prepare.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

using bvh_test::Random;
using bvh_test::scene_from_mesh;

RT_TEST_SUITE(Slab, "ray-box-slab-test");
RT_TEST_SUITE(NearestHit, "nearest-hit-traversal");
RT_TEST_SUITE(AnyHit, "any-hit-queries");
RT_TEST_SUITE(Visits, "checking-your-tree");

BvhNode unit_node() {
    return BvhNode{Vec3f(-1), 0, Vec3f(1), 1};
}

bool slab(const Ray& ray, Interval range, Real& t) {
    return intersect_node(unit_node(), ray, Real(1) / ray.direction, range, t);
}

TEST_F(Slab, HitAndEntryDistance) {
    Real t = -1;
    ASSERT_TRUE(slab(Ray{{0, 0, 5}, {0, 0, -1}}, Interval{0, kInfinity}, t));
    EXPECT_EQ(t, 4);
    ASSERT_TRUE(slab(Ray{{-5, 0.5, 0.5}, {2, 0, 0}}, Interval{0, kInfinity}, t));
    EXPECT_EQ(t, 2);
}

TEST_F(Slab, Misses) {
    Real t;
    EXPECT_FALSE(slab(Ray{{0, 2, 5}, {0, 0, -1}}, Interval{0, kInfinity}, t)) << "passes above";
    EXPECT_FALSE(slab(Ray{{0, 0, 5}, {0, 0, 1}}, Interval{0, kInfinity}, t)) << "points away";
    EXPECT_FALSE(slab(Ray{{0, 0, 5}, {0, 0, -1}}, Interval{0, 3}, t)) << "stops before the box";
    EXPECT_FALSE(slab(Ray{{0, 0, 5}, {0, 0, -1}}, Interval{7, kInfinity}, t)) << "starts after it";
    EXPECT_FALSE(slab(Ray{{3, 0, 3}, {1, 0, -1}}, Interval{0, kInfinity}, t)) << "diagonal miss";
}

TEST_F(Slab, OriginInsideEntersAtRangeStart) {
    Real t = -1;
    ASSERT_TRUE(slab(Ray{{0.2, 0.1, 0}, {0.3, -1, 0.5}}, Interval{0, kInfinity}, t));
    EXPECT_EQ(t, 0);
}

TEST_F(Slab, ParallelToASlab) {
    Real t;
    EXPECT_TRUE(slab(Ray{{-5, 0.5, 0}, {1, 0, 0}}, Interval{0, kInfinity}, t))
        << "inside the y slab";
    EXPECT_FALSE(slab(Ray{{-5, 1.5, 0}, {1, 0, 0}}, Interval{0, kInfinity}, t))
        << "outside the y slab";
    // On the slab's plane with a zero direction component: 0 * inf is NaN; the box is touched.
    EXPECT_TRUE(slab(Ray{{-5, 1, 0}, {1, 0, 0}}, Interval{0, kInfinity}, t))
        << "along the top face";
    EXPECT_TRUE(slab(Ray{{-5, -1, -1}, {1, 0, 0}}, Interval{0, kInfinity}, t)) << "along an edge";
}

TEST_F(Slab, FlatBoxOfAnAxisAlignedTriangle) {
    const BvhNode flat{Vec3f(-1, 0.5f, -1), 0, Vec3f(1, 0.5f, 1), 1};
    Real t = -1;
    const Ray ray{{0.3, 3, 0.1}, {0.01, -1, 0.02}};
    ASSERT_TRUE(intersect_node(flat, ray, Real(1) / ray.direction, Interval{0, kInfinity}, t));
    EXPECT_NEAR(t, 2.5, 1e-5);
}

TEST_F(Slab, NeverLosesABoxToRounding) {
    // Rays aimed at points on the edges of a box far from the origin, from far away: the
    // computed entry may round past the exit; the slab test must widen its far bound for that.
    Random random(11);
    const BvhNode node{Vec3f(1000.25f, -3.5f, 7), 0, Vec3f(1000.75f, -3.25f, 7.125f), 1};
    std::vector<std::tuple<BvhNode, Ray, Vec3, Interval, Real>> calls;
    for (int i = 0; i < 20000; ++i) {
        // On an edge: two coordinates on the box's bounds, where the entry through one slab and
        // the exit through another coincide and rounding decides.
        Vec3 target = Vec3(node.min) + (Vec3(node.max) - Vec3(node.min)) * random.vec(0, 1);
        const int axis = i % 3, other = (axis + 1 + (i / 3) % 2) % 3;
        target[axis] = (i / 6) % 2 ? node.min[axis] : node.max[axis];
        target[other] = (i / 12) % 2 ? node.min[other] : node.max[other];
        const Vec3 origin = target + random.unit() * Real(500);
        const Ray ray{origin, target - origin};
        calls.emplace_back(node, ray, Real(1) / ray.direction, Interval{0, kInfinity}, Real(0));
    }
    const std::vector<bool> hit = testing::call_each<&intersect_node>(calls);
    EXPECT_EQ(std::count(hit.begin(), hit.end(), false), 0)
        << "rays aimed at points on the box's edges missed it";
}

// Compares one ray's answers: BVH nearest vs stage 02 loop, BVH any-hit vs "nearest exists".
struct Comparison {
    int rays = 0, hits = 0, mismatches = 0, ties = 0;
    std::string first;
};

// `steps`: how many float steps of t two answers may differ by and both be right. Hard rays
// (through vertices, along edges) get more: there an intersection test's t is ill-conditioned
// and may even fall a little outside the triangle's own box.
void compare_ray(const PreparedScene& scene, const Ray& ray, Interval range, Comparison& c,
                 Real steps = 8) {
    Hit brute, bvh;
    const bool b = intersect_nearest(ray, scene, range, brute);
    const bool v = bvh_intersect_nearest(scene, ray, range, bvh);
    const bool any = bvh_intersect_any(scene, ray, range);
    ++c.rays;
    c.hits += b;
    // Equal t. Where two surfaces are hit at the same t up to the rounding of the intersection
    // tests (a ray through a shared edge or vertex) either one is a right answer: a tree may
    // skip a box whose entry rounds a float step beyond the nearest hit. Count those; they are
    // not mistakes.
    const Real rounding = steps * std::numeric_limits<Real>::epsilon() * std::abs(brute.t);
    const bool same = b == v && b == any && (!b || std::abs(brute.t - bvh.t) <= rounding);
    if (same) {
        c.ties += b && brute.primitive != bvh.primitive;
        return;
    }
    if (c.mismatches++ == 0) {
        char text[400];
        std::snprintf(
            text, sizeof text,
            "ray o=(%.9g, %.9g, %.9g) d=(%.9g, %.9g, %.9g) range (%g, %g): loop %s t=%.9g "
            "primitive %d; BVH nearest %s t=%.9g primitive %d; any-hit %s",
            double(ray.origin.x), double(ray.origin.y), double(ray.origin.z),
            double(ray.direction.x), double(ray.direction.y), double(ray.direction.z),
            double(range.min), double(range.max), b ? "hit" : "miss", double(brute.t),
            brute.primitive, v ? "hit" : "miss", double(bvh.t), bvh.primitive,
            any ? "hit" : "miss");
        c.first = text;
        if (b && v && bvh.t > brute.t)
            c.first +=
                " (the BVH's hit is farther than the loop's: a later leaf replaced a nearer hit, "
                "or a box holding it was skipped; is t_range.max shrunk to hit.t after every "
                "hit?)";
    }
}

PreparedScene built(PreparedScene scene) {
    const AccelerationReport report = build_acceleration(scene);
    EXPECT_TRUE(report.built) << report.problem;
    return scene;
}

void expect_same_as_loop(const PreparedScene& scene, const char* name, std::uint64_t seed) {
    Random random(seed);
    Comparison c;
    Aabb box;
    for (const Vec3& p : scene.vertices) box.grow(Vec3f(p));
    const Vec3 center = Vec3(box.center()), extent = Vec3(box.extent());
    const Real radius = glm::length(extent);
    for (int i = 0; i < 3000; ++i) {  // from outside towards a point in the box
        const Vec3 origin = center + random.unit() * radius * Real(1.5);
        const Vec3 target = center + (random.vec(-1, 1) * extent) * Real(0.5);
        compare_ray(scene, Ray{origin, target - origin}, Interval{0, kInfinity}, c);
    }
    for (int i = 0; i < 2000; ++i)  // from inside, in every direction
        compare_ray(scene, Ray{center + random.vec(-1, 1) * extent * Real(0.3), random.unit()},
                    Interval{0, kInfinity}, c);
    for (int i = 0; i < 1000; ++i) {  // short segments, as shadow rays are
        const Vec3 origin = center + random.vec(-1, 1) * extent;
        compare_ray(scene, Ray{origin, random.unit()},
                    Interval{0, Real(random.uniform(0, radius * Real(0.3)))}, c);
    }
    // Hard rays: aimed exactly at vertices and at edge midpoints, and axis-parallel rays.
    for (std::size_t t = 0; t < scene.triangles.size(); t += 1 + scene.triangles.size() / 500) {
        Vec3 a, b, cc;
        scene.triangle_vertices(t, a, b, cc);
        for (const Vec3& target : {a, (a + b) * Real(0.5), (a + b + cc) / Real(3)}) {
            const Vec3 origin = center + random.unit() * radius * Real(1.5);
            compare_ray(scene, Ray{origin, target - origin}, Interval{0, kInfinity}, c, 64);
            Vec3 axis_dir(0);
            axis_dir[int(t % 3)] = t % 2 ? 1 : -1;
            compare_ray(scene, Ray{target - axis_dir * radius * Real(2), axis_dir},
                        Interval{0, kInfinity}, c, 64);
        }
    }
    EXPECT_EQ(c.mismatches, 0) << name << ": " << c.mismatches << " of " << c.rays
                               << " rays differ from stage 02's loop; first: " << c.first;
    EXPECT_GT(c.hits, c.rays / 4) << name << ": too few rays hit to mean anything";
    EXPECT_LT(c.ties, c.rays / 10)
        << name << ": " << c.ties << " rays hit a different primitive at the same t";
}

TEST_F(NearestHit, SameAsLoopOnIcosphere) {
    expect_same_as_loop(built(scene_from_mesh(make_icosphere(3))), "icosphere", 1);
}
TEST_F(NearestHit, SameAsLoopOnTorus) {
    expect_same_as_loop(built(scene_from_mesh(make_torus(48, 24))), "torus", 2);
}
TEST_F(NearestHit, SameAsLoopOnTerrain) {
    expect_same_as_loop(built(scene_from_mesh(make_terrain(40, 40, 7))), "terrain", 3);
}
TEST_F(NearestHit, SameAsLoopOnTriangleSoup) {
    expect_same_as_loop(built(scene_from_mesh(make_triangle_soup(3000, 5))), "soup", 4);
}

TEST_F(NearestHit, SameAsLoopOnMixedPrimitives) {
    PreparedScene scene = scene_from_mesh(make_torus(24, 12));
    Random random(8);
    for (int i = 0; i < 40; ++i) {
        scene.spheres.push_back(Sphere{random.vec(-2, 2), Real(random.uniform(0.05, 0.4)), 0});
        const Vec3 lo = random.vec(-2, 2);
        scene.boxes.push_back(Box{lo, lo + random.vec(Real(0.05), Real(0.5)), 0});
    }
    scene.planes.push_back(Plane{{0, -1.5, 0}, {0, 1, 0}, 0});
    refresh_features(scene);
    expect_same_as_loop(built(scene), "torus, spheres, boxes and a plane", 5);
}

TEST_F(NearestHit, FillsPrimitiveAndMaterial) {
    PreparedScene scene = scene_from_mesh(make_icosphere(2));
    scene.materials.resize(3);
    for (std::size_t i = 0; i < scene.triangles.size(); ++i)
        scene.triangles[i].material = int(i % 3);
    scene = built(scene);
    Hit hit;
    ASSERT_TRUE(
        bvh_intersect_nearest(scene, Ray{{0.1, 0.2, 5}, {0, 0, -1}}, Interval{0, kInfinity}, hit));
    ASSERT_TRUE(scene.is_primitive(hit.primitive)) << hit.primitive;
    std::size_t index = 0;
    ASSERT_EQ(Scene::primitive_kind(hit.primitive, index), Scene::Kind::Triangle);
    EXPECT_EQ(hit.material, scene.triangles[index].material);
    EXPECT_NEAR(hit.t, 4, 0.05);
}

TEST_F(AnyHit, RespectsTheRange) {
    const PreparedScene scene = built(scene_from_mesh(make_icosphere(3)));
    const Ray ray{{0, 0, 5}, {0, 0, -1}};  // enters the unit sphere near t = 4
    EXPECT_TRUE(bvh_intersect_any(scene, ray, Interval{0, kInfinity}));
    EXPECT_FALSE(bvh_intersect_any(scene, ray, Interval{0, 3.9})) << "stops before the sphere";
    EXPECT_TRUE(bvh_intersect_any(scene, ray, Interval{4.5, kInfinity})) << "the far side";
    EXPECT_FALSE(bvh_intersect_any(scene, ray, Interval{6.1, kInfinity})) << "starts beyond it";
}

TEST_F(AnyHit, StopsEarlierThanNearest) {
    const PreparedScene scene = built(scene_from_mesh(make_triangle_soup(5000, 12)));
    Random random(2);
    std::uint64_t any_tests = 0, nearest_tests = 0;
    for (int i = 0; i < 500; ++i) {
        const Ray ray{random.unit() * Real(3), random.vec(-1, 1) * Real(0.2) - random.unit()};
        BvhStats a, n;
        Hit hit;
        bvh_intersect_any(scene, ray, Interval{0, kInfinity}, &a);
        bvh_intersect_nearest(scene, ray, Interval{0, kInfinity}, hit, &n);
        any_tests += a.primitives_tested;
        nearest_tests += n.primitives_tested;
    }
    EXPECT_LT(any_tests, nearest_tests) << "any-hit should stop at the first hit it finds";
}

TEST_F(NearestHit, NoTreeMeansPlanesOnly) {
    PreparedScene scene;
    scene.planes.push_back(Plane{{0, 0, 0}, {0, 1, 0}, 0});
    scene.materials.emplace_back();
    Hit hit;
    EXPECT_TRUE(
        bvh_intersect_nearest(scene, Ray{{0, 1, 0}, {0, -1, 0}}, Interval{0, kInfinity}, hit));
    EXPECT_FALSE(bvh_intersect_any(scene, Ray{{0, 1, 0}, {0, 1, 0}}, Interval{0, kInfinity}));
}

// Node visits per ray grow like log n, not like n: on spheres of 1280 to 81920 triangles (64
// times more), rays hitting them visit only a few times more nodes.
TEST_F(Visits, GrowLogarithmically) {
    double visits[4] = {};
    std::size_t triangles[4] = {};
    for (int level = 3; level <= 6; ++level) {
        const PreparedScene scene = built(scene_from_mesh(make_icosphere(level)));
        triangles[level - 3] = scene.triangles.size();
        Random random(42);
        BvhStats stats;
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3 origin = random.unit() * Real(4);
            const Ray ray{origin, random.vec(-1, 1) * Real(0.5) - origin};
            Hit hit;
            hits += bvh_intersect_nearest(scene, ray, Interval{0, kInfinity}, hit, &stats);
        }
        ASSERT_EQ(hits, 2000);
        visits[level - 3] = double(stats.nodes_visited) / 2000;
    }
    for (int i = 0; i < 4; ++i)
        EXPECT_LT(visits[i], 8 * std::log2(double(triangles[i])))
            << triangles[i] << " triangles: " << visits[i] << " nodes per ray";
    EXPECT_LT(visits[3] / visits[0], 3.0)
        << "64 times the triangles took " << visits[3] / visits[0] << " times the node visits ("
        << visits[0] << " -> " << visits[3] << "): that is not logarithmic";
}

// Nearer child first: a ray hitting a wall in front of a dense sphere finds the wall first; the
// sphere's subtree, entered beyond that hit, is never opened.
TEST_F(Visits, NearerChildFirstSkipsWhatIsBehindTheHit) {
    TriangleMesh mesh = make_icosphere(5);  // 20,480 triangles, radius 1, at the origin
    const std::uint32_t base = std::uint32_t(mesh.vertices.size());
    for (const Vec3& v : {Vec3(-2, -2, 3), Vec3(2, -2, 3), Vec3(2, 2, 3), Vec3(-2, 2, 3)})
        mesh.vertices.push_back(v);  // a wall at z = 3, between the rays' origin and the sphere
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
    const PreparedScene scene = built(scene_from_mesh(mesh));
    Random random(9);
    BvhStats stats;
    const int rays = 1000;
    for (int i = 0; i < rays; ++i) {
        const Vec3 jitter = random.vec(-0.2, 0.2);
        const Ray ray{{0, 0, 10}, {jitter.x, jitter.y, -1}};
        Hit hit;
        ASSERT_TRUE(bvh_intersect_nearest(scene, ray, Interval{0, kInfinity}, hit, &stats));
        ASSERT_NEAR(hit.t, 7, 1e-3) << "the wall at z = 3";
    }
    const double per_ray = double(stats.nodes_visited) / rays;
    EXPECT_LT(per_ray, 12) << per_ray
                           << " nodes visited per ray: the sphere behind the wall was opened; go "
                              "into the nearer child first and skip a popped node whose entry is "
                              "beyond the nearest hit";
}

}  // namespace
}  // namespace rt
