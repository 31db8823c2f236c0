// Stage 02 intersections checked against exact arithmetic: spheres, boxes, planes and
// degenerate rays. What the checks share, and how tolerances are set: cgal_exact_common.h and
// cgal_exact_test.cpp.
#include "cgal_exact_common.h"

namespace rt {
namespace {

using namespace rt::exact;
using namespace rt::exact_test;

// ---------------------------------------------------------------------------------------------
// Spheres.

// The error model of the stable quadratic (kSphereBand, kSphereT) is written in
// testing/exact_cases.h, where the cases come from.
struct SphereChecker {
    std::string name;
    double band;  // hit/miss may differ only when |tangency| <= band * eps * (|oc| + r)
    double t_tol;
    int rays = 0, hits = 0, disagreements = 0;
    double worst_band = 0, worst_t = 0, worst_ulps = 0;

    void check(const SphereCase& one, double ulp_bound) {
        const Ray& ray = one.ray;
        const Sphere& sphere = one.sphere;
        const SphereTruth& truth = one.truth;
        Hit hit;
        const bool got = intersect_sphere(ray, sphere, Interval{}, hit);
        ++rays;
        const SphereScales scales = sphere_scales(one);
        const double oc = scales.oc, r = scales.r;
        if (got != truth.hit) {
            ++disagreements;
            const double ratio = std::abs(truth.tangency) / (kEps * (oc + r));
            worst_band = std::max(worst_band, ratio);
            EXPECT_LE(ratio, band)
                << name << ": you report " << hit_or_miss(got) << ", exact arithmetic "
                << hit_or_miss(truth.hit) << ". The ray's line passes "
                << few(std::abs(truth.tangency)) << (truth.tangency < 0 ? " inside" : " outside")
                << " the rim: " << few(ratio) << " rounding widths (one width here: "
                << "eps (|o - c| + r) = " << few(kEps * (oc + r)) << "), at most " << band
                << " allowed. Only near-tangent rays may be decided differently: check the "
                << "discriminant (b^2 - a c' cancels for a small sphere far away: use "
                << "a (r^2 - l.l)), that a root t <= 0 (behind the origin) is never taken, and "
                << "the open t-range. " << text(ray) << ", sphere c " << text(sphere.center)
                << " r " << digits(sphere.radius) << "; " << kReadSphere;
            return;
        }
        if (!got) return;
        ++hits;
        const double dlen = length(ray.direction);
        const double h = scales.h;
        const double err = std::abs(hit.t - truth.t.to_double()) * dlen;
        const double ratio = err / (kEps * (oc + r) * (1 + r / h));
        worst_t = std::max(worst_t, ratio);
        EXPECT_LE(ratio, t_tol)
            << name << ": t = " << digits(hit.t) << ", exact root " << digits(truth.t.to_double())
            << ": t is " << few(ratio) << " units from the exact root, at most " << t_tol
            << " allowed (1 unit = the rounding a stable quadratic makes on this ray, "
            << "eps (|o - c| + r) (1 + r / h) = " << few(kEps * (oc + r) * (1 + r / h))
            << ", h the half chord). Digits lost to cancellation, in -b + sqrt(disc) or in "
            << "b^2 - a c'? Or the wrong root? " << text(ray) << ", sphere c "
            << text(sphere.center) << " r " << digits(sphere.radius) << "; " << kReadSphere;
        const double ulps = truth.t.ulp_error(hit.t);
        worst_ulps = std::max(worst_ulps, ulps);
        EXPECT_LE(ulps, ulp_bound)
            << name << ": t = " << digits(hit.t) << ", exact root " << digits(truth.t.to_double())
            << ": " << few(ulps) << " units in the last place (ulps) from the exact root, at most "
            << ulp_bound << " allowed on this well-conditioned ray (the stable quadratic loses "
            << "only a few ulps): cancellation? " << text(ray) << ", sphere c "
            << text(sphere.center) << " r " << digits(sphere.radius) << "; " << kReadSphere;
    }
    void print() const {
        std::printf(
            "[%s] rays %d hits %d disagreements %d (worst band %.3g of %g) worst t %.3g "
            "of %g, worst ulps %.3g\n",
            name.c_str(), rays, hits, disagreements, worst_band, band, worst_t, t_tol, worst_ulps);
    }
};

RT_TEST_SUITE(SphereExact, "a-stable-quadratic");

TEST_F(SphereExact, RandomRaysAgreeWithExactRoot) {
    // Spheres of radius 0.1 .. 10 around random centres, origins in a box 30 wide. Rays whose
    // line passes at least 0.1 r inside the rim (h >= ~0.45 r) and whose origin is at least
    // 0.5 r away from the surface are well conditioned: there the root is within kUlps units in
    // the last place. Others only obey the error model above.
    constexpr double kUlps = 16;  // measured 4.3
    SphereChecker check{"sphere random", kSphereBand, kSphereT};
    SphereChecker wide{"sphere random, all rays", kSphereBand, kSphereT};
    for (const SphereCase& one : random_sphere_cases()) {
        if (one.well_conditioned)
            check.check(one, kUlps);
        else
            wide.check(one, std::numeric_limits<double>::infinity());
    }
    check.print();
    wide.print();
    EXPECT_GT(check.hits, 1000) << "only " << check.hits << " of " << check.rays
                                << " well-conditioned rays were hits that agree with exact "
                                << "arithmetic (more than 1000 expected); " << kReadSphere;
}

TEST_F(SphereExact, SmallSphereFarAway) {
    // Radius 1 at distance 1e4: the textbook b^2 - a c cancels (b^2 ~ 1e8 |d|^4), the stable
    // form computes the discriminant from the perpendicular offset l instead. Rays well inside
    // the rim (h >= ~0.45 r) are within kUlps units in the last place.
    constexpr double kUlps = 16;  // measured 3.4
    SphereChecker check{"small far sphere", kSphereBand, kSphereT};
    for (const SphereCase& one : small_far_sphere_cases()) check.check(one, kUlps);
    check.print();
    EXPECT_GT(check.hits, 1000) << "only " << check.hits << " of " << check.rays
                                << " rays at the small far sphere were hits that agree with "
                                << "exact arithmetic (more than 1000 expected): b^2 - a c' "
                                << "cancels here, use a (r^2 - l.l); " << kReadSphere;
}

TEST_F(SphereExact, LargeSphereFromJustAboveTheSurface) {
    // Radius 1e3, origins 1e-2 .. 1 above the surface, rays pointing down into it (near root
    // t ~ height) or along it. Here c = |oc|^2 - r^2 cancels: its rounding error eps r^2 makes
    // the near root's relative error about eps r / height, i.e. up to ~1e5 ulps for height
    // 1e-2 in float. The error model (with its 1 + r / h factor and |oc| + r) covers it; the
    // ulp bound below states it: ulps <= kUlpsPerRatio * r / height.
    constexpr double kUlpsPerRatio = 4;
    SphereChecker check{"large sphere, near surface", kSphereBand, kSphereT};
    double worst_ratio_ulps = 0;
    for (const SphereCase& one : large_sphere_above_cases()) {
        const Sphere& s = one.sphere;
        const Ray& ray = one.ray;
        const Vec3& o = ray.origin;
        const SphereTruth& truth = one.truth;
        check.check(one, std::numeric_limits<double>::infinity());
        Hit hit;
        if (truth.hit && intersect_sphere(ray, s, Interval{}, hit)) {
            const double h = length(o - s.center) - s.radius;  // actual height after rounding
            const double r_ulps = truth.t.ulp_error(hit.t) / (s.radius / h);
            worst_ratio_ulps = std::max(worst_ratio_ulps, r_ulps);
            EXPECT_LE(r_ulps, kUlpsPerRatio)
                << "t = " << digits(hit.t) << ", exact root " << digits(truth.t.to_double()) << ": "
                << few(truth.t.ulp_error(hit.t)) << " ulps from the exact root for an "
                << "origin " << few(h) << " above a sphere of radius " << s.radius << ", that is "
                << few(r_ulps) << " ulps per unit of r / height, at most " << kUlpsPerRatio
                << " allowed (the "
                << "rounding of c' = |o - c|^2 - r^2 costs about r / height ulps; more means "
                << "another cancellation). " << text(ray) << ", sphere c " << text(s.center) << "; "
                << kReadSphere;
        }
    }
    check.print();
    std::printf("[large sphere] worst ulps / (r / height) = %.3g (bound %g)\n", worst_ratio_ulps,
                kUlpsPerRatio);
    EXPECT_GT(check.hits, 1000) << "only " << check.hits << " of " << check.rays
                                << " rays from just above the large sphere were hits that agree "
                                << "with exact arithmetic (more than 1000 expected); "
                                << kReadSphere;
}

TEST_F(SphereExact, LargeSphereFromJustInsideTheSurfaceExactC) {
    // Data for which the stable form is exact up to its last roundings: integer centre, radius
    // 1000, origin 1 .. 8 units below the surface on an axis (every square an integer below 2^24,
    // so c = |oc|^2 - r^2 is exact), rays leaving within ~0.1 rad of the outward normal (the
    // offset l from the centre is small, so the discriminant a (r^2 - |l|^2) is accurate). The
    // root wanted is the small positive one: the textbook (-b + sqrt(disc)) / a cancels there
    // (it loses about log2(t_far / t_near) ~ 8 bits), the stable c / q does not: within kUlps.
    // (Seen from just ABOVE a large sphere, the rounding of l dominates instead; that case is
    // LargeSphereFromJustAboveTheSurface, with its r / height bound.)
    constexpr double kUlps = 8;  // measured 1.8 (textbook form: ~2000)
    double worst = 0;
    int hits = 0;
    for (const SphereCase& one : large_sphere_inside_cases()) {
        const Sphere& s = one.sphere;
        const Ray& ray = one.ray;
        const SphereTruth& truth = one.truth;
        ASSERT_TRUE(truth.hit);
        Hit hit;
        ASSERT_TRUE(intersect_sphere(ray, s, Interval{}, hit))
            << text(ray) << " starts inside the sphere c " << text(s.center) << " r 1000, so "
            << "it hits (the far root is the only one > 0); " << kReadSphere;
        ++hits;
        const double ulps = truth.t.ulp_error(hit.t);
        worst = std::max(worst, ulps);
        EXPECT_LE(ulps, kUlps)
            << "t = " << digits(hit.t) << ", exact root " << digits(truth.t.to_double()) << ": "
            << few(ulps) << " ulps from the exact root, at most " << kUlps
            << " allowed. The ray leaves a "
            << "large sphere from just inside: (-b + sqrt(disc)) / a cancels here (about 2000 "
            << "ulps), c' / q does not. " << text(ray) << ", sphere c " << text(s.center)
            << " r 1000; " << kReadSphere;
    }
    std::printf("[large sphere from inside, exact c] hits %d worst ulps %.3g (bound %g)\n", hits,
                worst, kUlps);
}

TEST_F(SphereExact, OriginOnTheSphere) {
    // Origins exactly on the sphere (3-4-5 triangle: |o - c|^2 == r^2 exactly). The roots are
    // 0 and t1. With the open range (0, inf) the root 0 is never reported: a ray heading inside
    // hits the far side at t1 (exactly, c == 0 makes the formula t1 = q / a), one heading
    // outside misses.
    const std::vector<SphereCase> cases = origin_on_sphere_cases();
    const Sphere s = cases[0].sphere;
    const Ray inward = cases[0].ray, outward = cases[1].ray, tangent = cases[2].ray;
    ASSERT_TRUE(cases[0].truth.origin_on_sphere);
    const SphereTruth& in = cases[0].truth;
    ASSERT_TRUE(in.hit);
    Hit hit;
    ASSERT_TRUE(intersect_sphere(inward, s, Interval{}, hit))
        << "origin exactly on the sphere, heading inside: the far side is hit; " << kReadSphere;
    EXPECT_LE(in.t.ulp_error(hit.t), 4)
        << "origin exactly on the sphere (c' = 0), heading inside: t = " << digits(hit.t)
        << ", exact root " << digits(in.t.to_double()) << ", " << few(in.t.ulp_error(hit.t))
        << " ulps away, at most 4 allowed (with c' = 0 the far root is q / a); " << kReadSphere;
    EXPECT_FALSE(cases[1].truth.hit);
    EXPECT_FALSE(intersect_sphere(outward, s, Interval{}, hit))
        << "origin exactly on the sphere, heading outside: the only roots are t = 0 and one "
        << "behind the origin, neither in the open range (0, inf), so a miss (reported t "
        << digits(hit.t) << "); " << kReadRanges;
    EXPECT_FALSE(cases[2].truth.hit);  // double root at 0
    EXPECT_FALSE(intersect_sphere(tangent, s, Interval{}, hit))
        << "origin exactly on the sphere, tangent direction: a double root at t = 0, outside "
        << "the open range (0, inf), so a miss (reported t " << digits(hit.t) << "); "
        << kReadRanges;
}

// ---------------------------------------------------------------------------------------------
// Boxes and planes.

RT_TEST_SUITE(BoxExact, "ray-box-slabs");

TEST_F(BoxExact, SlabsAgreeWithCgal) {
    // Hit/miss against do_intersect(Ray_3, Iso_cuboid_3) (through exact slabs, checked to agree).
    // The slab t of a face is (bound - o) / d: two roundings, a relative error below eps, which
    // is at most kUlps = 2 units in the last place (eps |t| is 2 ulps at the top of a binade).
    // Hit/miss may differ only for rays through an edge or corner to within rounding: exact
    // entry and exit parameters within a relative kGap * eps of each other. The face reported
    // is the exact one unless the next slab's bound is within a relative kGap * eps as well
    // (the ray enters next to an edge of the box, where either face is a right answer).
    // (The cases and kBoxUlps, kBoxGap: testing/exact_cases.h.)
    constexpr double kUlps = kBoxUlps, kGap = kBoxGap;
    int hits = 0, disagreements = 0, faces_checked = 0;
    double worst_ulps = 0, worst_gap = 0;
    for (const BoxCase& one : box_cases()) {
        const Box& box = one.box;
        const Ray& ray = one.ray;
        const BoxTruth& truth = one.truth;
        ASSERT_TRUE(truth.cgal_consistent) << "exact slabs disagree with CGAL do_intersect";
        Hit hit;
        const bool got = intersect_box(ray, box, Interval{}, hit);
        if (got != truth.hit) {
            ++disagreements;
            worst_gap = std::max(worst_gap, std::abs(truth.relative_gap) / kEps);
            EXPECT_LE(std::abs(truth.relative_gap), kGap * kEps)
                << "box: you report " << hit_or_miss(got) << ", exact arithmetic "
                << hit_or_miss(truth.hit) << ". The ray's t-interval inside the three slabs has "
                << "a relative width of " << few(truth.relative_gap) << " ("
                << few(truth.relative_gap / kEps)
                << " eps; negative: it passes beside the box); only rays within " << kGap
                << " eps of an edge or a corner may be decided differently. Check the swap for "
                << "d_i < 0, the case d_i = 0 (no division), t_far > 0 and the open t-range. "
                << text(ray) << ", box " << text(box.min) << " .. " << text(box.max) << "; "
                << kReadBox;
            continue;
        }
        if (!got) continue;
        ++hits;
        const double ulps = ulp_error(hit.t, truth.t);
        worst_ulps = std::max(worst_ulps, ulps);
        EXPECT_LE(ulps, kUlps) << "box: t = " << digits(hit.t) << ", exact "
                               << digits(CGAL::to_double(truth.t)) << ": " << few(ulps)
                               << " units in the last place (ulps) off, at most " << kUlps
                               << " allowed: a slab "
                               << "distance is (bound - o_i) / d_i, two roundings. " << text(ray)
                               << ", box " << text(box.min) << " .. " << text(box.max) << "; "
                               << kReadBox;
        if (truth.face_margin > kGap * kEps) {
            ++faces_checked;
            const bool positive = ray.direction[truth.axis] > 0;
            Vec3 outward(0);  // entering: the face facing the ray; leaving: the one behind it
            outward[truth.axis] = truth.at_near == positive ? Real(-1) : Real(1);
            EXPECT_EQ(hit.normal, hit.front_face ? outward : -outward)
                << "box: wrong face. You stored the normal " << text(hit.normal) << " (front_face "
                << hit.front_face << "), but the ray " << (truth.at_near ? "enters" : "leaves")
                << " through the face with outward "
                << "normal " << text(outward) << " (the slab of axis " << truth.axis << " sets "
                << (truth.at_near ? "t_near" : "t_far") << "), so the stored normal is "
                << text(hit.front_face ? outward : -outward) << ", that one turned to face the "
                << "ray. " << text(ray) << ", box " << text(box.min) << " .. " << text(box.max)
                << "; " << kReadBox;
        }
    }
    std::printf(
        "[box] hits %d, disagreements %d (worst |gap| %.3g eps, bound %g), worst ulps "
        "%.3g (bound %g), faces checked %d\n",
        hits, disagreements, worst_gap, kGap, worst_ulps, kUlps, faces_checked);
    EXPECT_GT(hits, 600) << "only " << hits << " of the random box rays were hits that agree "
                         << "with exact arithmetic (more than 600 expected); " << kReadBox;
}

RT_TEST_SUITE(PlaneExact, "ray-plane");

TEST_F(PlaneExact, RandomRaysMatchExactT) {
    // t = n.(p - o) / n.d. Rounding p - o costs eps |p - o| per component, and the two dot
    // products cancel when n is nearly orthogonal to (p - o) or to d, so
    //   |t - t_exact| |d| <= kT * eps * (|p - o| + |t d|) / cos,   cos = |n.d| / (|n| |d|).
    // (The cases and kPlaneT, measured 0.73: testing/exact_cases.h.)
    constexpr double kT = kPlaneT;
    int hits = 0;
    double worst = 0;
    for (const PlaneCase& one : plane_cases()) {
        const Plane& plane = one.plane;
        const Ray& ray = one.ray;
        const PlaneTruth& truth = one.truth;
        Hit hit;
        const bool got = intersect_plane(ray, plane, Interval{}, hit);
        ASSERT_FALSE(truth.parallel);
        const double dlen = length(ray.direction);
        const double t_exact = CGAL::to_double(truth.t);
        const double scale = plane_unit(one, kEps);
        if (got != truth.hit) {  // only when the exact t is 0 to within rounding
            EXPECT_LE(std::abs(t_exact) * dlen, kT * scale)
                << "plane: you report " << hit_or_miss(got) << ", exact arithmetic "
                << hit_or_miss(truth.hit) << ", at exact t = " << digits(t_exact) << ": the hit "
                << "is " << few(std::abs(t_exact) * dlen) << " from the origin, "
                << few(std::abs(t_exact) * dlen / scale)
                << " rounding units (one unit: eps (|p0 - o| + |t d|) / cos = " << few(scale)
                << "); only hits within " << kT << " units of the origin may be decided "
                << "differently. Check the sign of t = n.(p0 - o) / n.d and the open t-range. "
                << text(ray) << ", plane p0 " << text(plane.point) << " n " << text(plane.normal)
                << "; " << kReadPlane;
            continue;
        }
        if (!got) continue;
        ++hits;
        const double ratio = std::abs(CGAL::to_double(FT(double(hit.t)) - truth.t)) * dlen / scale;
        worst = std::max(worst, ratio);
        EXPECT_LE(ratio, kT)
            << "plane: t = " << digits(hit.t) << ", exact " << digits(t_exact) << ": the error "
            << "is " << few(ratio) << " units, at most " << kT << " allowed (1 unit = the "
            << "rounding of n.(p0 - o) / n.d on this ray, eps (|p0 - o| + |t d|) / cos = "
            << few(scale) << "). " << text(ray) << ", plane p0 " << text(plane.point) << " n "
            << text(plane.normal) << "; " << kReadPlane;
    }
    std::printf("[plane] hits %d, worst t error %.3g of %g\n", hits, worst, kT);
    EXPECT_GT(hits, 1000) << "only " << hits << " of the random plane rays were hits that agree "
                          << "with exact arithmetic (more than 1000 expected); " << kReadPlane;
}

TEST_F(PlaneExact, ParallelInPlaneAndOnPlaneOrigins) {
    // The first three: n = normalize(1, 1, 0) in Real, so n.x == n.y and d = (1, -1, z) is
    // exactly parallel (the last two of them lie in the plane). The last two: the origin exactly
    // on the plane, the direction across it: exact t == 0, outside (0, inf): a miss.
    const std::vector<PlaneCase> cases = parallel_plane_cases();
    for (std::size_t i = 0; i < 3; ++i) {
        const Ray& ray = cases[i].ray;
        ASSERT_TRUE(cases[i].truth.parallel);
        Hit hit;
        EXPECT_FALSE(intersect_plane(ray, cases[i].plane, Interval{}, hit))
            << text(ray) << " is exactly parallel to the plane (n.d = 0): a miss, also when it "
            << "lies in the plane; " << kReadPlane;
    }
    for (std::size_t i = 3; i < cases.size(); ++i) {
        const Ray& ray = cases[i].ray;
        const PlaneTruth& truth = cases[i].truth;
        ASSERT_TRUE(truth.origin_in_plane);
        EXPECT_FALSE(truth.hit);
        Hit hit;
        EXPECT_FALSE(intersect_plane(ray, cases[i].plane, Interval{}, hit))
            << text(ray) << " starts exactly on the plane: t = 0 is outside the open range "
            << "(0, inf), so a miss (reported t " << digits(hit.t) << "); " << kReadRanges;
    }
}

// ---------------------------------------------------------------------------------------------
// Zero, NaN and infinite directions: every function reports a miss and leaves `hit` alone.

RT_TEST_SUITE(DegenerateRays, "what-you-work-with");

TEST_F(DegenerateRays, ZeroNanInfDirectionsMissEverything) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN(), inf = kInfinity;
    std::vector<Vec3> dirs = {Vec3(0), Vec3(-0.0f, 0, -0.0f)};
    for (int i = 0; i < 3; ++i)
        for (const Real bad : {nan, inf, -inf}) {
            Vec3 d(Real(0.3), Real(-0.2), Real(-1));
            d[i] = bad;
            dirs.push_back(d);
        }
    dirs.push_back(Vec3(nan));
    dirs.push_back(Vec3(inf, -inf, inf));
    dirs.push_back(Vec3(inf, nan, 0));
    dirs.push_back(Vec3(std::numeric_limits<Real>::denorm_min(), 0, 0) * Real(0));

    Scene scene;
    scene.spheres.push_back({Vec3(0, 0, -5), 1});
    scene.planes.push_back({Vec3(0, -1, 0), Vec3(0, 1, 0)});
    scene.vertices = {{-1, -1, -3}, {1, -1, -3}, {0, 1, -3}};
    scene.triangles.push_back({{0, 1, 2}, 0});
    scene.boxes.push_back({Vec3(-1, -1, -9), Vec3(1, 1, -7)});
    const Vec3 a = scene.vertices[0], b = scene.vertices[1], c = scene.vertices[2];

    Hit sentinel;
    sentinel.t = 42;
    sentinel.point = Vec3(1, 2, 3);
    sentinel.normal = Vec3(0, 0, 1);
    sentinel.front_face = false;
    sentinel.uv = Vec2(0.25, 0.5);
    sentinel.primitive = 7;
    sentinel.material = 3;
    auto untouched = [&](const Hit& h) {
        return h.t == sentinel.t && h.point == sentinel.point && h.normal == sentinel.normal &&
               h.front_face == sentinel.front_face && h.uv == sentinel.uv &&
               h.primitive == sentinel.primitive && h.material == sentinel.material;
    };
    // Also with the unbounded range (-inf, inf): then no accidental "t is NaN or 0, hence not in
    // (0, inf)" can hide a missing check.
    for (const Vec3& d : dirs)
        for (const Interval range : {Interval{}, Interval{-kInfinity, kInfinity}})
            for (const Vec3 o :
                 {Vec3(0), Vec3(0, 0, -5)}) {  // outside everything, inside the sphere
                const Ray ray{o, d};
                const std::string what = "direction (" + std::to_string(d.x) + ", " +
                                         std::to_string(d.y) + ", " + std::to_string(d.z) + ")";
                Hit h = sentinel;
                EXPECT_FALSE(intersect_sphere(ray, scene.spheres[0], range, h)) << what;
                EXPECT_FALSE(intersect_plane(ray, scene.planes[0], range, h)) << what;
                EXPECT_FALSE(intersect_triangle(ray, a, b, c, range, h)) << what;
                EXPECT_FALSE(intersect_triangle_watertight(ray, a, b, c, range, h)) << what;
                EXPECT_FALSE(intersect_box(ray, scene.boxes[0], range, h)) << what;
                EXPECT_FALSE(intersect_nearest(ray, scene, range, h)) << what;
                EXPECT_TRUE(untouched(h)) << what << ": hit was modified on a miss";
            }
    // Sanity: the same scene is hit with a proper direction, so the misses above mean something.
    Hit h;
    EXPECT_TRUE(intersect_nearest(Ray{Vec3(0), Vec3(0, 0, -1)}, scene, Interval{}, h));
    EXPECT_TRUE(
        intersect_triangle_watertight(Ray{Vec3(0), Vec3(0, 0, -1)}, a, b, c, Interval{}, h));
}

}  // namespace
}  // namespace rt
