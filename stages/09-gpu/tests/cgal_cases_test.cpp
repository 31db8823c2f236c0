// Stage 09's GPU unit test on stage 02's hard cases: the student's intersect_sphere, _plane,
// _triangle and _box (GLSL, run by shaders/intersect_cases.comp) on the rays stage 02's CGAL test
// checks (testing/exact_cases.h: grazing rays, slivers, rays through box edges and corners,
// near-tangent rays, rays parallel to a plane, origins on a surface, extreme scales), judged
// against the exact answers CGAL gives for exactly those float inputs, by stage 02's rule:
//   - hit or miss is the exact one, except for a case within the stated band of the boundary
//     (kTriangleBand rounding widths of an edge, kSphereBand of the rim, kBoxGap eps of an edge
//     or a corner, kPlaneT units of t = 0), where either answer is accepted, as in stage 02;
//   - t is within the error model's bound of the exact t (kTriangleT, kSphereT, kPlaneT units;
//     kBoxUlps ulps for a box), and within stage 02's ulp bounds on its well-conditioned rays;
//   - the box face is the exact one unless the ray enters next to an edge (face_margin);
//   - origins exactly on a surface: a miss, or on a triangle a hit no farther than rounding
//     explains (kOnTriangleAcne), and always a miss with t_range.min = 1e-3.
// The bands and bounds are in units of the float epsilon: the GPU computes in float. (Stage 02's
// leak test of closed meshes casts every ray at every triangle of a mesh: too many cases for
// llvmpipe, and its claim is about the watertight method, which the GPU stage does not port.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "render/gpu/gpu_cases.h"
#include "testing/exact_cases.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

namespace gc = ::rt::gpu_cases;
using namespace ::rt::exact;

constexpr double kFloatEps = std::numeric_limits<float>::epsilon();
constexpr const char* kReadIntersections = "read stages/09-gpu/README.md#intersections";

// One case's verdict: empty when the answer is right, else why not.
using Judge = std::function<std::string(const gc::GpuAnswer&)>;

std::string cgal_case_text(const Ray& ray) {
    char buffer[200];
    std::snprintf(buffer, sizeof buffer, "ray o (%.9g, %.9g, %.9g) d (%.9g, %.9g, %.9g)",
                  double(ray.origin.x), double(ray.origin.y), double(ray.origin.z),
                  double(ray.direction.x), double(ray.direction.y), double(ray.direction.z));
    return buffer;
}
std::string cgal_number(const char* format, double x) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, format, x);
    return buffer;
}
const char* cgal_hit_or_miss(bool hit) {
    return hit ? "a hit" : "a miss";
}
std::string cgal_flip(const gc::GpuAnswer& g, bool exact) {
    return std::string("the GPU reports ") + cgal_hit_or_miss(g.found) + ", exact arithmetic " +
           cgal_hit_or_miss(exact);
}
double cgal_length(const Vec3& v) {
    return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
}

// Triangles (random, grazing, sliver, scales): stage 02's TriangleChecker, Cramer's rule.
std::string judge_triangle(const TriangleCase& c, const gc::GpuAnswer& g) {
    const TriangleScales s = triangle_scales(c);
    if (g.found != c.truth.hit) {
        const double widths = std::abs(c.truth.edge_distance) / s.band_unit(kFloatEps);
        if (widths <= kTriangleBand) return "";  // within rounding of an edge: either answer
        return cgal_flip(g, c.truth.hit) + ", for a plane point " + cgal_number("%.3g", widths) +
               " rounding widths from the nearest edge line (at most " +
               cgal_number("%g", kTriangleBand) + " may flip)";
    }
    if (!g.found) return "";
    const double err = std::abs(CGAL::to_double(FT(double(g.t)) - c.truth.t)) * s.dlen;
    const double units = err / s.t_unit(kFloatEps);
    if (units > kTriangleT)
        return "t = " + cgal_number("%.9g", g.t) + ", exact " + cgal_number("%.9g", s.t_exact) +
               ": " + cgal_number("%.3g", units) + " rounding units off (at most " +
               cgal_number("%g", kTriangleT) + ")";
    constexpr double kUlps = 32;  // stage 02's bound on well-conditioned hits
    if (s.cos >= 0.2 && s.aspect <= 4 && ulp_error(Real(g.t), c.truth.t) > kUlps)
        return "t = " + cgal_number("%.9g", g.t) + " is " +
               cgal_number("%.3g", ulp_error(Real(g.t), c.truth.t)) +
               " ulps from the exact t on a well-conditioned ray (at most 32)";
    return "";
}

// Origins exactly on a general triangle: a hit only within rounding of t = 0.
std::string judge_on_triangle(const TriangleCase& c, Interval range, const gc::GpuAnswer& g) {
    if (!g.found) return "";
    if (range.min > 0)
        return "starts exactly on the triangle, yet with t_range.min = 1e-3 the GPU reports a hit "
               "at t = " +
               cgal_number("%.9g", g.t);
    const double distance = std::abs(double(g.t)) * cgal_length(c.ray.direction);
    const double acne = kOnTriangleAcne * kFloatEps * vertex_size(c) / triangle_scales(c).cos;
    if (distance <= acne) return "";
    return "starts exactly on the triangle (exact t = 0), yet a hit at distance " +
           cgal_number("%.3g", distance) + " is reported (rounding explains " +
           cgal_number("%.3g", acne) + ")";
}

std::string judge_must_miss(const gc::GpuAnswer& g, const char* why) {
    if (!g.found) return "";
    return std::string(why) +
           ": a miss, but the GPU reports a hit at t = " + cgal_number("%.9g", g.t);
}

// Spheres: stage 02's SphereChecker, with its ulp bound for the family (infinite: none).
std::string judge_sphere(const SphereCase& c, double ulp_bound, const gc::GpuAnswer& g) {
    const SphereScales s = sphere_scales(c);
    if (g.found != c.truth.hit) {
        const double widths = std::abs(c.truth.tangency) / s.band_unit(kFloatEps);
        if (widths <= kSphereBand) return "";  // near-tangent: either answer
        return cgal_flip(g, c.truth.hit) + ", for a line " + cgal_number("%.3g", widths) +
               " rounding widths from tangency (at most " + cgal_number("%g", kSphereBand) +
               " may flip)";
    }
    if (!g.found) return "";
    const double err = std::abs(double(g.t) - c.truth.t.to_double()) * cgal_length(c.ray.direction);
    const double units = err / s.t_unit(kFloatEps);
    if (units > kSphereT)
        return "t = " + cgal_number("%.9g", g.t) + ", exact root " +
               cgal_number("%.9g", c.truth.t.to_double()) + ": " + cgal_number("%.3g", units) +
               " rounding units off (at most " + cgal_number("%g", kSphereT) + ")";
    const double ulps = c.truth.t.ulp_error(Real(g.t));
    if (ulps > ulp_bound)
        return "t = " + cgal_number("%.9g", g.t) + " is " + cgal_number("%.3g", ulps) +
               " ulps from the exact root (at most " + cgal_number("%g", ulp_bound) + ")";
    return "";
}

// From just above a large sphere: also stage 02's ulps <= 4 r / height.
std::string judge_sphere_above(const SphereCase& c, const gc::GpuAnswer& g) {
    std::string verdict = judge_sphere(c, std::numeric_limits<double>::infinity(), g);
    if (!verdict.empty() || !g.found || !c.truth.hit) return verdict;
    const double height = cgal_length(c.ray.origin - c.sphere.center) - double(c.sphere.radius);
    const double per_ratio = c.truth.t.ulp_error(Real(g.t)) / (double(c.sphere.radius) / height);
    if (per_ratio <= 4) return "";
    return "t = " + cgal_number("%.9g", g.t) + ": " + cgal_number("%.3g", per_ratio) +
           " ulps per unit of r / height (at most 4)";
}

// Boxes: stage 02's SlabsAgreeWithCgal.
std::string judge_box(const BoxCase& c, const gc::GpuAnswer& g) {
    const BoxTruth& truth = c.truth;
    if (g.found != truth.hit) {
        if (std::abs(truth.relative_gap) <= kBoxGap * kFloatEps) return "";  // edge or corner
        return cgal_flip(g, truth.hit) +
               ", for a ray whose t-interval in the slabs has a "
               "relative width of " +
               cgal_number("%.3g", truth.relative_gap / kFloatEps) + " eps (at most " +
               cgal_number("%g", kBoxGap) + " may flip)";
    }
    if (!g.found) return "";
    const double ulps = ulp_error(Real(g.t), truth.t);
    if (ulps > kBoxUlps)
        return "t = " + cgal_number("%.9g", g.t) + " is " + cgal_number("%.3g", ulps) +
               " ulps from the exact t (at most " + cgal_number("%g", kBoxUlps) + ")";
    if (!(truth.face_margin > kBoxGap * kFloatEps)) return "";  // next to an edge: either face
    glm::vec3 outward(0);
    outward[truth.axis] = truth.at_near == (c.ray.direction[truth.axis] > 0) ? -1.0f : 1.0f;
    if (g.normal == (g.front_face ? outward : -outward)) return "";
    return "wrong face: normal (" + cgal_number("%g", g.normal.x) + ", " +
           cgal_number("%g", g.normal.y) + ", " + cgal_number("%g", g.normal.z) + "), the ray " +
           (truth.at_near ? "enters" : "leaves") + " through the face of axis " +
           std::to_string(truth.axis);
}

// Planes: stage 02's RandomRaysMatchExactT.
std::string judge_plane(const PlaneCase& c, const gc::GpuAnswer& g) {
    const double unit = plane_unit(c, kFloatEps);
    const double dlen = cgal_length(c.ray.direction);
    const double t_exact = CGAL::to_double(c.truth.t);
    if (g.found != c.truth.hit) {
        if (std::abs(t_exact) * dlen <= kPlaneT * unit) return "";  // t = 0 within rounding
        return cgal_flip(g, c.truth.hit) + " at exact t = " + cgal_number("%.9g", t_exact);
    }
    if (!g.found) return "";
    const double units = std::abs(CGAL::to_double(FT(double(g.t)) - c.truth.t)) * dlen / unit;
    if (units <= kPlaneT) return "";
    return "t = " + cgal_number("%.9g", g.t) + ", exact " + cgal_number("%.9g", t_exact) + ": " +
           cgal_number("%.3g", units) + " rounding units off (at most " +
           cgal_number("%g", kPlaneT) + ")";
}

// The cases of every family, uploaded in one batch, and how to judge each answer.
struct CgalBatch {
    struct Family {
        std::string name;
        std::size_t first = 0, count = 0;
    };
    std::vector<Family> families;
    std::vector<gc::GpuRayCase> cases;
    std::vector<Judge> judges;
    std::vector<Ray> rays;  // for messages

    void start(const std::string& name) { families.push_back({name, cases.size(), 0}); }
    void add(const gc::GpuRayCase& c, const Ray& ray, Judge judge) {
        cases.push_back(c);
        rays.push_back(ray);
        judges.push_back(std::move(judge));
        ++families.back().count;
    }
};

// The families are kept alive here: the judges refer to their cases.
struct CgalFamilies {
    std::vector<std::vector<TriangleCase>> triangles;
    std::vector<TriangleCase> parallel = parallel_triangle_cases();
    std::vector<TriangleCase> exact_on = exact_origin_on_triangle_cases();
    std::vector<TriangleCase> on = origin_on_triangle_cases();
    std::vector<SphereCase> spheres = random_sphere_cases(), far = small_far_sphere_cases(),
                            above = large_sphere_above_cases(),
                            inside = large_sphere_inside_cases(),
                            on_sphere = origin_on_sphere_cases();
    std::vector<BoxCase> boxes = box_cases();
    std::vector<PlaneCase> planes = plane_cases(), parallel_planes = parallel_plane_cases();
    CgalFamilies()
        : triangles{random_triangle_cases(), grazing_triangle_cases(), sliver_triangle_cases(),
                    scaled_triangle_cases()} {}
};

CgalBatch cgal_batch(const CgalFamilies& f) {
    CgalBatch batch;
    const Interval all{};
    const char* triangle_names[4] = {"triangle, random", "triangle, grazing", "triangle, sliver",
                                     "triangle, far away and extreme scales"};
    for (int k = 0; k < 4; ++k) {
        batch.start(triangle_names[k]);
        for (const TriangleCase& c : f.triangles[k])
            batch.add(gc::triangle_case(c.ray, c.a, c.b, c.c, all), c.ray,
                      [&c](const gc::GpuAnswer& g) { return judge_triangle(c, g); });
    }
    batch.start("triangle, parallel to its plane");
    for (const TriangleCase& c : f.parallel)
        batch.add(gc::triangle_case(c.ray, c.a, c.b, c.c, all), c.ray, [](const gc::GpuAnswer& g) {
            return judge_must_miss(g, "exactly parallel to the plane");
        });
    batch.start("triangle, origin on an exact axis-aligned triangle");
    for (const TriangleCase& c : f.exact_on)
        batch.add(gc::triangle_case(c.ray, c.a, c.b, c.c, all), c.ray, [](const gc::GpuAnswer& g) {
            return judge_must_miss(g, "starts exactly on the triangle, t is exactly 0");
        });
    batch.start("triangle, origin on the triangle");
    for (const Interval range : {all, Interval{1e-3f, kInfinity}})
        for (const TriangleCase& c : f.on)
            batch.add(
                gc::triangle_case(c.ray, c.a, c.b, c.c, range), c.ray,
                [&c, range](const gc::GpuAnswer& g) { return judge_on_triangle(c, range, g); });

    const double inf = std::numeric_limits<double>::infinity();
    batch.start("sphere, random and at the rim");
    for (const SphereCase& c : f.spheres)
        batch.add(gc::sphere_case(c.ray, c.sphere, all), c.ray, [&c, inf](const gc::GpuAnswer& g) {
            return judge_sphere(c, c.well_conditioned ? 16 : inf, g);
        });
    batch.start("sphere, small and far away");
    for (const SphereCase& c : f.far)
        batch.add(gc::sphere_case(c.ray, c.sphere, all), c.ray,
                  [&c](const gc::GpuAnswer& g) { return judge_sphere(c, 16, g); });
    batch.start("sphere, large, from just above");
    for (const SphereCase& c : f.above)
        batch.add(gc::sphere_case(c.ray, c.sphere, all), c.ray,
                  [&c](const gc::GpuAnswer& g) { return judge_sphere_above(c, g); });
    batch.start("sphere, large, from just inside");
    for (const SphereCase& c : f.inside)
        batch.add(gc::sphere_case(c.ray, c.sphere, all), c.ray, [&c](const gc::GpuAnswer& g) {
            if (!g.found) return std::string("starts inside the sphere: a hit, the GPU misses");
            return judge_sphere(c, 8, g);
        });
    batch.start("sphere, origin on the sphere");
    for (const SphereCase& c : f.on_sphere)
        batch.add(gc::sphere_case(c.ray, c.sphere, all), c.ray,
                  [&c](const gc::GpuAnswer& g) { return judge_sphere(c, 4, g); });

    batch.start("box, edges, corners and slabs");
    for (const BoxCase& c : f.boxes)
        batch.add(gc::box_case(c.ray, c.box, all), c.ray,
                  [&c](const gc::GpuAnswer& g) { return judge_box(c, g); });
    batch.start("plane, random");
    for (const PlaneCase& c : f.planes)
        batch.add(gc::plane_case(c.ray, c.plane, all), c.ray,
                  [&c](const gc::GpuAnswer& g) { return judge_plane(c, g); });
    batch.start("plane, parallel or starting on it");
    for (const PlaneCase& c : f.parallel_planes)
        batch.add(gc::plane_case(c.ray, c.plane, all), c.ray, [](const gc::GpuAnswer& g) {
            return judge_must_miss(g, "parallel to the plane or starting on it");
        });
    return batch;
}

RT_TEST_SUITE(GpuExactCases, "intersections");

// Only where Real is float: the GPU computes in float, and a double build's exact answers are
// for its double inputs (a test that would only skip there is not compiled).
#ifndef RT_DOUBLE
TEST_F(GpuExactCases, AnswersAsExactArithmeticAllows) {
    const CgalFamilies families;
    const CgalBatch batch = cgal_batch(families);
    std::vector<gc::GpuAnswer> answers;
    std::string error;
    ASSERT_TRUE(run_gpu_cases(batch.cases, answers, error)) << error;
    for (const CgalBatch::Family& family : batch.families) {
        int wrong = 0, hits = 0;
        std::string first;
        for (std::size_t i = family.first; i < family.first + family.count; ++i) {
            hits += answers[i].found;
            const std::string verdict = batch.judges[i](answers[i]);
            if (verdict.empty()) continue;
            if (++wrong <= 3) first += "\n  " + verdict + "; " + cgal_case_text(batch.rays[i]);
        }
        std::printf("[%s] cases %zu, GPU hits %d, wrong %d\n", family.name.c_str(), family.count,
                    hits, wrong);
        EXPECT_EQ(wrong, 0) << family.name << ": " << wrong << " of " << family.count
                            << " answers are not what exact arithmetic allows (the first ones):"
                            << first << "\n"
                            << kReadIntersections;
    }
}
#endif

}  // namespace
}  // namespace rt
