// Stage 02 intersections checked against exact arithmetic (CGAL, GMP, MPFR).
//
// Every input below is a Real, converted exactly to CGAL (exact_reference.h), so the reference
// answers are exact for precisely the rays and surfaces the Real code sees. The tests check the
// student functions (the reference solution in this tree; stubs in a starter tree, where these
// tests fail) and the framework's watertight triangle test.
//
// Tolerances are written as multiples of eps = std::numeric_limits<Real>::epsilon(), times the
// magnitude of the numbers involved, so the same tests hold in float and in double (RT_DOUBLE).
// Each multiple was measured (the largest value seen is printed by every test) and then given a
// margin of about 4x or more; the reason for the form of each bound is stated where it is used.
// All randomness comes from std::mt19937_64 with fixed seeds.
//
// This file: triangles (Cramer and the watertight test) and closed meshes.
#include "cgal_exact_common.h"

namespace rt {
namespace {

using namespace rt::exact;
using namespace rt::exact_test;

// ---------------------------------------------------------------------------------------------
// The triangle checker shared by the random, grazing, sliver and scale tests. The error model
// (the band of hit/miss, the bound on t) is written in testing/exact_cases.h, where the cases
// come from.
struct Tolerances {
    double band;  // kTriangleBand
    double t;     // kTriangleT
};

struct MethodStats {
    int rays = 0, hits = 0, disagreements = 0;
    double worst_band = 0;  // largest |edge distance| / (eps L / cos) over disagreements
    double worst_t = 0;     // largest |t - t_exact| |d| / (eps L aspect / cos) over hits
    double worst_ulps = 0;  // largest ulp error of t over the well-conditioned hits
};

struct TriangleChecker {
    std::string name;
    Tolerances tol;
    MethodStats stats[2];
    int exact_edge_or_vertex = 0;

    // Checks both methods on one ray; returns false (after reporting) on a violated bound.
    void check(const TriangleCase& one) {
        const Ray& ray = one.ray;
        const Vec3 &a = one.a, &b = one.b, &c = one.c;
        const TriangleTruth& truth = one.truth;
        ASSERT_TRUE(truth.cgal_consistent) << name << ": CGAL predicate and construction disagree";
        if (truth.region == Region::Edge || truth.region == Region::Vertex) ++exact_edge_or_vertex;
        const TriangleScales scales = triangle_scales(one);
        const double cos = scales.cos, dlen = scales.dlen, t_exact = scales.t_exact;
        const double L = scales.L, aspect = scales.aspect;
        for (int m = 0; m < 2; ++m) {
            Hit hit;
            const bool got = kMethods[m].fn(ray, a, b, c, Interval{}, hit);
            MethodStats& s = stats[m];
            ++s.rays;
            if (got != truth.hit) {
                ++s.disagreements;
                const double ratio = std::abs(truth.edge_distance) / (kEps * L / cos);
                s.worst_band = std::max(s.worst_band, ratio);
                EXPECT_LE(ratio, tol.band)
                    << name << ": " << kMethods[m].name << " reports " << hit_or_miss(got)
                    << ", exact arithmetic " << hit_or_miss(truth.hit) << ", for a ray whose "
                    << "plane point is " << few(truth.edge_distance) << " from the nearest edge "
                    << "line: " << few(ratio)
                    << " rounding widths (one width here: eps L / cos = " << few(kEps * L / cos)
                    << "), at most " << tol.band << " allowed. Only rays "
                    << "within rounding of an edge may be decided differently: check the inside "
                    << "test (beta >= 0, gamma >= 0, beta + gamma <= 1) and the open t-range. "
                    << text(ray) << ", t_exact " << digits(t_exact) << ", cos " << few(cos) << "; "
                    << kReadTriangle;
                continue;
            }
            if (!got) continue;
            ++s.hits;
            const double err = std::abs(CGAL::to_double(FT(double(hit.t)) - truth.t)) * dlen;
            const double ratio = err / (kEps * L * aspect / cos);
            s.worst_t = std::max(s.worst_t, ratio);
            EXPECT_LE(ratio, tol.t)
                << name << ": " << kMethods[m].name << " t = " << digits(hit.t) << ", exact "
                << digits(t_exact) << ": the error is " << few(ratio) << " units, at most " << tol.t
                << " allowed (1 unit = the rounding Cramer's rule makes on this ray, "
                << "eps L aspect / cos = " << few(kEps * L * aspect / cos) << "). Is t the "
                << "ratio |a-b, a-c, s| / |M| of the handout? " << text(ray) << ", cos " << few(cos)
                << ", aspect " << few(aspect) << "; " << kReadTriangle;
            if (cos >= 0.2 && aspect <= 4)
                s.worst_ulps = std::max(s.worst_ulps, ulp_error(hit.t, truth.t));
        }
    }

    // Checks every case, stopping at the first fatal failure, then prints the table.
    void check_all(const std::vector<TriangleCase>& cases) {
        for (const TriangleCase& one : cases) {
            check(one);
            if (::testing::Test::HasFatalFailure()) return;
        }
        print();
    }

    void print() const {
        std::printf("[%s] exact edge/vertex rays %d\n", name.c_str(), exact_edge_or_vertex);
        for (int m = 0; m < 2; ++m) {
            const MethodStats& s = stats[m];
            std::printf(
                "[%s] %-10s rays %d hits %d hit/miss disagreements %d (worst band %.3g of %g), "
                "worst t %.3g of %g, worst ulps (cos >= 0.2, aspect <= 4) %.3g\n",
                name.c_str(), kMethods[m].name, s.rays, s.hits, s.disagreements, s.worst_band,
                tol.band, s.worst_t, tol.t, s.worst_ulps);
        }
    }
};

RT_TEST_SUITE(TriangleExact, "ray-triangle-cramers-rule");

TEST_F(TriangleExact, RandomRaysAgreeWithCgal) {
    // Random triangles in [-1, 1]^3 and origins in [-4, 4]^3. The hit/miss bands and t bounds
    // are the measured worst cases times about 4 (see the error model above). In addition, for
    // well-conditioned hits (cos >= 0.2, aspect <= 4) the reported t is within kUlps units in the
    // last place of the exact t: both methods compute t from a handful of rounded products
    // (Cramer: a 3x3 determinant ratio; watertight: sheared coordinates, then T / det).
    constexpr double kUlps = 32;  // measured 10.6 (Cramer), 4.9 (watertight)
    TriangleChecker check{"random", {kTriangleBand, kTriangleT}, {}, 0};
    check.check_all(random_triangle_cases());
    if (HasFatalFailure()) return;
    for (int m = 0; m < 2; ++m) {
        const MethodStats& s = check.stats[m];
        EXPECT_GT(s.hits, 500) << kMethods[m].name << ": only " << s.hits << " of " << s.rays
                               << " random rays were hits that agree with exact arithmetic "
                               << "(more than 500 expected); " << kReadTriangle;
        EXPECT_LE(s.worst_ulps, kUlps)
            << kMethods[m].name << ": on well-conditioned hits (cos >= 0.2, aspect <= 4) t is up "
            << "to " << few(s.worst_ulps) << " units in the last place (ulps) from the exact t, at "
            << "most " << kUlps << " allowed: a handful of roundings gives a few ulps, more means "
            << "digits lost somewhere; " << kReadTriangle;
    }
}

TEST_F(TriangleExact, GrazingRays) {
    // Rays meeting the plane at angles from 1e-1 down to 1e-5 radians (cos of the angle to the
    // normal down to 1e-5). The band and t error grow like 1 / cos, which the error model
    // already contains, so the same constants hold as for random rays.
    TriangleChecker check{"grazing", {kTriangleBand, kTriangleT}, {}, 0};
    check.check_all(grazing_triangle_cases());
    if (HasFatalFailure()) return;
    for (int m = 0; m < 2; ++m)
        EXPECT_GT(check.stats[m].hits, 500)
            << kMethods[m].name << ": only " << check.stats[m].hits << " of " << check.stats[m].rays
            << " grazing rays were hits that agree with exact arithmetic "
            << "(more than 500 expected); " << kReadTriangle;
}

TEST_F(TriangleExact, SliverTriangles) {
    // Needles (one edge 1e-3 .. 1e-5 of the others) and caps (one angle close to 180 degrees,
    // the apex 1e-3 .. 1e-5 off the opposite edge). The aspect factor of the t bound covers the
    // badly conditioned normal; the band in distance units does not need it (a sliver is thin,
    // so its edges are close to every interior point, and the exact distance is what counts).
    TriangleChecker check{"sliver", {kTriangleBand, kTriangleT}, {}, 0};
    check.check_all(sliver_triangle_cases());
    if (HasFatalFailure()) return;
}

TEST_F(TriangleExact, FarAwayAndExtremeScales) {
    // The random setup, (1) translated by offsets of 1e4 (unit triangles far from the world
    // origin, the ray starting nearby), (2) scaled by 1e6 and (3) by 1e-4. L contains the
    // coordinate magnitude, so the band grows to eps * 1e4 for the translated case: that is the
    // absolute precision of the coordinates there, and no method can do better.
    TriangleChecker check{"scales", {kTriangleBand, kTriangleT}, {}, 0};
    check.check_all(scaled_triangle_cases());
    if (HasFatalFailure()) return;
    for (int m = 0; m < 2; ++m)
        EXPECT_GT(check.stats[m].hits, 500)
            << kMethods[m].name << ": only " << check.stats[m].hits << " of " << check.stats[m].rays
            << " rays at far or extreme scales were hits that agree with "
            << "exact arithmetic (more than 500 expected); " << kReadTriangle;
}

TEST_F(TriangleExact, ParallelAndInPlaneRaysMiss) {
    // Directions exactly parallel to the plane (confirmed by CGAL), from beside the plane and
    // from inside it through the triangle: the contract says miss for both methods.
    for (const TriangleCase& one : parallel_triangle_cases()) {
        ASSERT_TRUE(one.truth.parallel);
        for (const Method& m : kMethods) {
            Hit hit;
            EXPECT_FALSE(m.fn(one.ray, one.a, one.b, one.c, Interval{}, hit))
                << m.name << ": " << text(one.ray) << " is exactly parallel to the triangle's "
                << "plane (|M| = 0), so it misses, also when it lies in the plane; "
                << kReadTriangle;
        }
    }
}

TEST_F(TriangleExact, OriginOnTheTriangle) {
    // Origins exactly on the triangle (CGAL: origin in the plane, inside). The exact t is 0,
    // outside the open range (0, inf), so the exact answer is "miss". What the methods report:
    //  - an axis-aligned triangle with dyadic coordinates: everything is exact, t == 0, miss;
    //  - a general triangle: the rounded t is 0 or a tiny +-value, so a hit at t > 0 may be
    //    reported, but only with |t| |d| <= 16 eps L / cos (self-intersection "acne"; cos as
    //    in the triangle error model: the rounding across the plane, seen along the ray). With
    //    t_range.min = 1e-3 (a typical shadow-ray epsilon for unit scenes) it is always a miss.
    for (const TriangleCase& one : exact_origin_on_triangle_cases()) {
        ASSERT_TRUE(one.truth.origin_in_plane);
        for (const Method& m : kMethods) {
            Hit hit;
            EXPECT_FALSE(m.fn(one.ray, one.a, one.b, one.c, Interval{}, hit))
                << m.name << ": " << text(one.ray) << " starts exactly on an "
                << "axis-aligned triangle with exact coordinates: t is exactly 0, outside "
                << "the open range (0, inf), so a miss (reported t " << digits(hit.t) << "); "
                << kReadRanges;
        }
    }
    int exact_origins = 0, reported = 0;
    for (const TriangleCase& one : origin_on_triangle_cases()) {
        const Ray& ray = one.ray;
        const Vec3 &a = one.a, &b = one.b, &c = one.c;
        ++exact_origins;
        EXPECT_FALSE(one.truth.hit);
        const double L = vertex_size(one);
        for (const Method& m : kMethods) {
            Hit hit;
            if (m.fn(ray, a, b, c, Interval{}, hit)) {
                ++reported;
                const double cos = triangle_scales(one).cos;
                const double acne = kOnTriangleAcne * kEps * L / cos;
                EXPECT_LE(std::abs(hit.t) * length(ray.direction), acne)
                    << m.name << ": " << text(ray) << " starts exactly on the triangle (exact "
                    << "t = 0), yet a hit at distance "
                    << few(std::abs(hit.t) * length(ray.direction))
                    << " is reported, more than rounding can explain (16 eps L / cos = "
                    << few(acne) << "); " << kReadTriangle;
            }
            Hit hit2;
            EXPECT_FALSE(m.fn(ray, a, b, c, Interval{Real(1e-3), kInfinity}, hit2))
                << m.name << ": " << text(ray) << " starts exactly on the triangle, so with "
                << "t_range.min = 1e-3 nothing may be hit (reported t " << digits(hit2.t) << "); "
                << kReadRanges;
        }
    }
    std::printf("[origin on triangle] %d exact origins, %d tiny-t hits reported\n", exact_origins,
                reported);
    EXPECT_GT(exact_origins, 100);
}

// ---------------------------------------------------------------------------------------------
// Closed meshes: rays through shared edges and vertices.

struct LeakCount {
    int rays = 0, leaks[2] = {0, 0};
};

// Casts `ray` at every triangle of the mesh with both methods; a leak is a ray that CGAL says
// meets the closed mesh (at t > 0) and that no triangle reports.
void cast_at_mesh(const Ray& ray, const Mesh& mesh, LeakCount& count, const char* what) {
    ASSERT_TRUE(exact_mesh_hit(ray, mesh))
        << what << ": test ray built to hit the mesh misses: o " << ray.origin.x << " "
        << ray.origin.y << " " << ray.origin.z << " d " << ray.direction.x << " " << ray.direction.y
        << " " << ray.direction.z;
    ++count.rays;
    // Your intersect_triangle on every triangle at once (call_each: one message when graded).
    std::vector<std::tuple<Ray, Vec3, Vec3, Vec3, Interval, Hit>> calls;
    for (const auto& t : mesh.triangles)
        calls.emplace_back(ray, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]],
                           Interval{}, Hit{});
    const std::vector<bool> cramer = testing::call_each<&intersect_triangle>(calls);
    if (std::count(cramer.begin(), cramer.end(), true) == 0) ++count.leaks[0];
    int hits = 0;
    for (auto& [r, a, b, c, range, hit] : calls)
        hits += intersect_triangle_watertight(r, a, b, c, range, hit);
    if (hits == 0) ++count.leaks[1];
}

// Rays at points on (or, for non-dyadic vertices, within rounding of) every edge and at every
// vertex: from outside, along roughly the inward direction, and from interior points.
LeakCount shoot_edges_and_vertices(const Mesh& mesh, const Vec3& center, Real lateral, Rng& rng,
                                   int samples_per_edge, const char* what) {
    LeakCount count;
    std::vector<Vec3> targets(mesh.vertices);
    for (const auto& e : mesh.edges())
        for (int k = 1; k <= samples_per_edge; ++k) {
            // s = k / (samples + 1) is dyadic for samples = 1, 3, 7, 15: exactly on the edge
            // when the vertices are small dyadic numbers (octahedron, cube).
            const Real s = Real(k) / Real(samples_per_edge + 1);
            const Vec3& p = mesh.vertices[e[0]];
            const Vec3& q = mesh.vertices[e[1]];
            targets.push_back(p + s * (q - p));
        }
    for (const Vec3& p : targets) {
        const Vec3 radial = p - center;
        for (int j = 0; j < 2; ++j) {  // from outside, two jittered origins
            Vec3 jitter(Real(rng.integer(-8, 8)), Real(rng.integer(-8, 8)),
                        Real(rng.integer(-8, 8)));
            const Vec3 o = center + Real(3) * radial + lateral * jitter;
            cast_at_mesh(Ray{o, p - o}, mesh, count, what);
        }
        cast_at_mesh(Ray{center, radial}, mesh, count, what);  // from the centre
        const Vec3 inner = center + radial * Real(0.25) + Vec3(lateral * Real(rng.integer(-2, 2)));
        cast_at_mesh(Ray{inner, p - inner}, mesh, count, what);  // from another interior point
    }
    return count;
}

RT_TEST_SUITE(ClosedMesh, "ray-triangle-cramers-rule");

// A precondition of the leak test, checked inside it (it exercises no student code, so on its
// own it would pass in a starter tree): the generated meshes are closed and face outwards.
void expect_closed_and_outward() {
    for (const Mesh& mesh : {octahedron(), cube(), icosphere(2)}) {
        std::map<std::pair<int, int>, int> directed;
        for (const auto& t : mesh.triangles) {
            for (int i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
            const Vec3 n = glm::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]],
                                      mesh.vertices[t[2]] - mesh.vertices[t[0]]);
            EXPECT_GT(glm::dot(n, mesh.vertices[t[0]]), 0) << "inward triangle";
        }
        for (const auto& [edge, uses] : directed) {  // every edge used once in each direction
            EXPECT_EQ(uses, 1);
            EXPECT_EQ(directed.count({edge.second, edge.first}), 1u);
        }
    }
}

TEST_F(ClosedMesh, WatertightNeverLeaksCramerLeakRateIsBounded) {
    expect_closed_and_outward();
    // The watertight method decides every ray exactly for the rounded, sheared vertices, which
    // are shared bit for bit between neighbouring triangles: it must NEVER leak. Cramer's rule
    // computes the barycentrics of the shared edge separately in each triangle, with different
    // roundings, so a ray within rounding distance of an edge can be rejected by both
    // triangles (e.g. beta = -1e-8 in one and beta + gamma = 1 + 1e-8 in the other): in float a
    // nonzero leak rate is expected for rays aimed at edges of non-dyadic meshes (icosphere,
    // translated meshes). Exactly dyadic meshes (octahedron, cube at the origin) are computed
    // exactly and do not leak with either method.
    Rng rng(0x5eed0006);
    struct Case {
        const char* name;
        Mesh mesh;
        Vec3 center;
        int samples;
        Real lateral;  // jitter step of the origins; dyadic, so dyadic meshes get exact rays
        bool dyadic;   // vertices and ray data small dyadic numbers: Cramer is exact too
    };
    std::vector<Case> cases;
    cases.push_back({"octahedron", octahedron(), Vec3(0), 15, Real(1) / 16, true});
    cases.push_back({"cube", cube(), Vec3(0), 15, Real(1) / 16, true});
    cases.push_back({"icosphere", icosphere(2), Vec3(0), 3, Real(1) / 16, false});
    Mesh moved = icosphere(2, Real(0.75));
    const Vec3 offset(Real(100.3), Real(-41.7), Real(12.9));
    for (Vec3& v : moved.vertices) v += offset;
    cases.push_back({"icosphere at (100, -42, 13)", moved, offset, 3, Real(1) / 16, false});
    Mesh oct = octahedron(Real(0.3));
    for (Vec3& v : oct.vertices) v += Vec3(Real(-7.1), Real(3.3), Real(5.7));
    cases.push_back({"octahedron at (-7, 3, 6)", oct, Vec3(Real(-7.1), Real(3.3), Real(5.7)), 15,
                     Real(1) / 128, false});

    LeakCount total;
    for (const Case& c : cases) {
        const LeakCount count =
            shoot_edges_and_vertices(c.mesh, c.center, c.lateral, rng, c.samples, c.name);
        if (HasFatalFailure()) return;
        std::printf("[leaks] %-28s rays %5d  Cramer leaks %4d (%.3f%%)  watertight leaks %d\n",
                    c.name, count.rays, count.leaks[0], 100.0 * count.leaks[0] / count.rays,
                    count.leaks[1]);
        EXPECT_EQ(count.leaks[1], 0) << c.name << ": the watertight method leaked";
        if (c.dyadic) {
            EXPECT_EQ(count.leaks[0], 0)
                << c.name << ": Cramer's rule let " << count.leaks[0] << " of " << count.rays
                << " rays through the closed mesh although every number here is exact (no "
                << "rounding at all): do edges and vertices count as inside (beta >= 0, not > 0; "
                << "beta + gamma <= 1, not < 1)? " << kReadTriangle;
        }
        total.rays += count.rays;
        total.leaks[0] += count.leaks[0];
        total.leaks[1] += count.leaks[1];
    }
    const double rate = double(total.leaks[0]) / total.rays;
    std::printf("[leaks] total rays %d, Cramer leak rate %.3f%%, watertight leaks %d\n", total.rays,
                100 * rate, total.leaks[1]);
    // Bound on the measured Cramer rate: observed 2.2% in float over these rays (4.4% on the
    // icosphere at the origin, where rays aim at edges and vertices from the centre), bounded
    // at 6% for margin. In double the rate is measured and printed the same way.
    constexpr double kCramerLeakBound = 0.06;
    EXPECT_LE(rate, kCramerLeakBound)
        << "Cramer's rule let " << few(100 * rate) << "% of " << total.rays
        << " rays aimed at edges "
        << "and vertices through the closed meshes, at most " << 100 * kCramerLeakBound
        << "% allowed (the reference leaks about 2%): edges and vertices must count as inside "
        << "(beta >= 0, gamma >= 0, beta + gamma <= 1); " << kReadTriangle;
}

}  // namespace
}  // namespace rt
