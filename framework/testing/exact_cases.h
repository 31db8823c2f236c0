// Stage 02's hard intersection cases with their exact answers (CGAL, through exact_reference.h),
// and the rule that says which computed answers are right.
//
// One generator per family of cases (grazing rays, slivers, rays through edges and corners,
// near-tangent rays, rays parallel to a plane, origins on a surface, extreme scales). Each
// returns the rays and surfaces together with the exact truth for exactly those Real inputs.
// The generators draw from fixed seeds, so a family is the same list of cases for every caller:
// stage 02's CGAL test (C++, stages/02-intersections/tests/cgal_exact_test.cpp) and stage 09's
// (the student's GLSL on the GPU, stages/09-gpu/tests/cgal_cases_test.cpp) check the same rays.
// `count` is the number of draws (not of cases: some draws are skipped); a smaller count gives
// a prefix of the same list.
//
// The rule: hit or miss must be the exact one unless the case lies within a stated number of
// rounding widths of the boundary (an edge, a rim, a corner, t = 0), where either answer is
// right; t must be within a stated number of rounding units of the exact t. The widths and
// units are first-order error models in eps (the machine epsilon of the arithmetic checked);
// the functions below compute them, the constants say how many are allowed. Needs CGAL: only
// targets that link rt_exact_cases (and so rt_exact) may include this.
#pragma once

#include <vector>

#include "testing/exact_reference.h"

namespace rt::exact {

// ---------------------------------------------------------------------------------------------
// Triangles.
//
// Error model (first-order rounding analysis of Cramer's rule and of the watertight test):
//   L      = max |coordinate| of o, a, b, c, plus the hit distance |t d|: the size of the numbers
//            whose rounding (each an absolute error of about eps L) moves the decision;
//   cos    = |n.d| / (|n| |d|), the cosine between ray and normal: a rounding error of eps L
//            across the ray becomes eps L / cos along the triangle's plane;
//   aspect = (longest edge)^2 / |n| = longest edge / smallest height: the conditioning of the
//            triangle's normal, which scales the error of t.
// Hit/miss may differ from the exact answer only when the exact plane point is within
//   band = kTriangleBand * eps * L / cos                           (distance to an edge line)
// of an edge, and the reported t obeys
//   |t - t_exact| |d| <= kTriangleT * eps * L * aspect / cos.
// Measured worst band ratio 0.16 in float, 0.15 in double (slivers); worst t ratio 0.67 in
// float (random, Cramer), 0.74 in double (slivers, Cramer). Bounds with a margin of 4x or more:
constexpr double kTriangleBand = 1, kTriangleT = 3;

struct TriangleCase {
    Ray ray;
    Vec3 a, b, c;
    TriangleTruth truth;
};

// The numbers of the error model for one case.
struct TriangleScales {
    double cos = 0;      // |n.d| / (|n| |d|)
    double dlen = 0;     // |d|
    double t_exact = 0;  // the exact t rounded to double (0 when parallel)
    double L = 0;        // the size of the numbers, see above
    double aspect = 0;   // (longest edge)^2 / |n|
    // The rounding widths: the unit of the hit/miss band and of the t error, for epsilon eps.
    double band_unit(double eps) const { return eps * L / cos; }
    double t_unit(double eps) const { return eps * L * aspect / cos; }
};
TriangleScales triangle_scales(const TriangleCase& c);

// Random triangles in [-1, 1]^3 (slivers skipped), origins in [-4, 4]^3, rays aimed at points
// near (and often inside) the triangle, non-unit directions. Seed 0x5eed0001.
std::vector<TriangleCase> random_triangle_cases(int count = 3000);
// Rays meeting the plane at angles from 1e-1 down to 1e-5 radians. Seed 0x5eed0002.
std::vector<TriangleCase> grazing_triangle_cases(int count = 1500);
// Needles (one edge 1e-3 .. 1e-5 of the others) and caps (the apex 1e-3 .. 1e-5 off the
// opposite edge), rays aimed at the sliver. Seed 0x5eed0003.
std::vector<TriangleCase> sliver_triangle_cases(int count = 2000);
// The random setup translated by offsets of 1e4, scaled by 1e6 and by 1e-4, in turn.
// Seed 0x5eed0004.
std::vector<TriangleCase> scaled_triangle_cases(int count = 3000);
// Directions exactly parallel to the plane (from beside it and from inside it): all misses.
std::vector<TriangleCase> parallel_triangle_cases();
// Origins exactly on an axis-aligned triangle with dyadic coordinates: every number is exact,
// t is exactly 0, a miss for any method.
std::vector<TriangleCase> exact_origin_on_triangle_cases();
// Origins exactly on general triangles (a vertex, or an exact edge midpoint), at most 200 cases
// from `count` draws. Exact answer: a miss; rounding may report a hit at t > 0, but only with
// |t| |d| <= kOnTriangleAcne * eps * L / cos (L = max |vertex coordinate|), and never beyond
// t_range.min = 1e-3. Seed 0x5eed0005.
std::vector<TriangleCase> origin_on_triangle_cases(int count = 4000);
constexpr double kOnTriangleAcne = 16;
// max |coordinate| of the vertices: the L of the bound above.
double vertex_size(const TriangleCase& c);

// ---------------------------------------------------------------------------------------------
// Spheres.
//
// Error model of the stable quadratic (first order): with oc = o - c, h = sqrt(r^2 - dist^2)
// the half chord (dist: centre to line), the reported root obeys
//   |t - t_exact| |d| <= kSphereT * eps * (|oc| + r) * (1 + r / h),
// and hit/miss may differ only when |tangency| <= kSphereBand * eps * (|oc| + r).
// (|oc| + r) is the size of the rounded quantities; 1 / h is the sensitivity of a root to the
// discriminant, unbounded at tangency (a property of the problem, not of the formula). For the
// near root, c = |oc|^2 - r^2 cancels when the origin is close to the surface: its error
// eps (|oc|^2 + r^2) divided by q ~ a t_far is also of this form.
// Measured worst: t ratio 0.93 (small far sphere); band ratio: see the rim rays of the random
// test (printed). Bounds with a margin of 4x or more:
constexpr double kSphereBand = 4, kSphereT = 4;

struct SphereCase {
    Ray ray;
    Sphere sphere;
    SphereTruth truth;
    // The line passes at least 0.1 r inside the rim and the origin is at least 0.5 r from the
    // surface (random family; true for every case of the small far sphere family).
    bool well_conditioned = false;
};

struct SphereScales {
    double oc = 0;  // |o - c|
    double r = 0;
    double h = 0;  // the half chord, from the exact tangency
    double band_unit(double eps) const { return eps * (oc + r); }
    double t_unit(double eps) const { return eps * (oc + r) * (1 + r / h); }
};
SphereScales sphere_scales(const SphereCase& c);

// Spheres of radius 0.1 .. 10, origins in a box 30 wide; every fourth ray at the rim (within
// 1e-7 .. 1e-3 r of tangency, on either side). Seed 0x5eed0007.
std::vector<SphereCase> random_sphere_cases(int count = 4000);
// Radius 1 at distance 1e4 (b^2 - a c cancels), rays well inside the rim. Seed 0x5eed0008.
std::vector<SphereCase> small_far_sphere_cases(int count = 2000);
// Radius 1e3, origins 1e-2 .. 1 above the surface, rays pointing down into it or along it.
// Seed 0x5eed0009.
std::vector<SphereCase> large_sphere_above_cases(int count = 2000);
// Radius 1000 about an integer centre, origins 1 .. 8 below the surface on an axis, rays
// leaving close to the outward normal: every case hits. Seed 0x5eed000d.
std::vector<SphereCase> large_sphere_inside_cases(int count = 1000);
// Origins exactly on a sphere (a 3-4-5 triangle): heading inside (hit), outside (miss) and
// tangent (miss), in that order.
std::vector<SphereCase> origin_on_sphere_cases();

// ---------------------------------------------------------------------------------------------
// Boxes and planes.

// Box: a slab distance is (bound - o) / d, two roundings: t within kBoxUlps units in the last
// place. Hit/miss may differ only when |relative_gap| <= kBoxGap * eps (through an edge or a
// corner to within rounding); the face is checked only when face_margin > kBoxGap * eps.
constexpr double kBoxUlps = 2, kBoxGap = 4;

struct BoxCase {
    Ray ray;
    Box box;
    BoxTruth truth;
};
// Random boxes in [-3, 3]^3, origins in [-6, 6]^3; a quarter of the rays aimed at a corner, a
// quarter at an edge's plane, one in seven parallel to a slab. Seed 0x5eed000a.
std::vector<BoxCase> box_cases(int count = 4000);

// Plane: t = n.(p - o) / n.d, so |t - t_exact| |d| <= kPlaneT * eps * (|p - o| + |t d|) / cos,
// and hit/miss may differ only when the exact hit is within kPlaneT of those units of the origin.
constexpr double kPlaneT = 3;  // measured 0.73

struct PlaneCase {
    Ray ray;
    Plane plane;
    PlaneTruth truth;
};
// The rounding unit of the plane rule above, for epsilon eps.
double plane_unit(const PlaneCase& c, double eps);
// Random planes through [-10, 10]^3, random rays. Seed 0x5eed000b.
std::vector<PlaneCase> plane_cases(int count = 4000);
// Directions exactly parallel to the plane (also from inside it), then origins exactly on a
// plane with directions across it: all misses.
std::vector<PlaneCase> parallel_plane_cases();

}  // namespace rt::exact
