// Exact-arithmetic reference answers for the stage 02 intersection functions, built on CGAL.
//
// Every input is a Real (float, or double with RT_DOUBLE). Both convert to double without
// rounding, so the CGAL objects built here are exactly the rays and surfaces the Real code sees,
// and every answer below is exact for those inputs:
//   - hit/miss of ray and triangle: CGAL::do_intersect with Epick (exact predicates); ray and
//     box: do_intersect with Epeck (Epick's ray/iso-cuboid test is not exact, see exact_box);
//   - exact points and t: Epeck (exact constructions, lazy rationals); t is measured exactly
//     along the ray, t = (p - o).d / d.d;
//   - edge and vertex classification: CGAL::orientation of the ray line against each edge;
//   - spheres: the discriminant in rationals (CGAL::Gmpq), the root by MPFR at 256 bits.
// Shared by the CGAL tests (stage 02, framework) and the accuracy lab (tools/bench), so it
// depends on nothing but the framework's core types, CGAL, GMP and MPFR. Compiled once, into the
// library rt_exact (framework/CMakeLists.txt), which passes CGAL's flags (-frounding-math) on to
// whatever links it.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <mpfr.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/ray.h"
#include "scene/scene.h"
#include "testing/random.h"

namespace rt::exact {

// The seeded generator of the exact cases and the accuracy lab (testing/random.h).
using Rng = testing::Random;

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Epeck::FT;  // an exact rational (lazily evaluated)
using Q = CGAL::Gmpq;  // an exact rational, for the hand-written formulas

// ---------------------------------------------------------------------------------------------
// Conversions. A Real converts to double exactly (float is a subset of double).
inline Epeck::Point_3 epeck_point(const Vec3& p) {
    return {double(p.x), double(p.y), double(p.z)};
}
inline Epeck::Vector_3 epeck_vector(const Vec3& v) {
    return {double(v.x), double(v.y), double(v.z)};
}

// The spacing of Real numbers at |x| (one unit in the last place of the Real nearest to x).
inline double ulp_of(double x) {
    const Real r = std::abs(Real(x));
    if (!std::isfinite(r)) return std::numeric_limits<double>::infinity();
    return double(std::nextafter(r, std::numeric_limits<Real>::infinity())) - double(r);
}

// |computed - exact| in units of the last place at the exact value. The difference is formed
// exactly, so only its final conversion to double rounds (a relative error of 1e-16 of the
// error itself, harmless also in double builds).
inline double ulp_error(Real computed, const FT& exact) {
    const double err = std::abs(CGAL::to_double(FT(double(computed)) - exact));
    return err / ulp_of(CGAL::to_double(exact));
}
inline double ulp_error(Real computed, const Q& exact) {
    const double err = std::abs(CGAL::to_double(Q(double(computed)) - exact));
    return err / ulp_of(CGAL::to_double(exact));
}
inline double relative_error(Real computed, const FT& exact) {
    return std::abs(CGAL::to_double((FT(double(computed)) - exact) / exact));
}

// ---------------------------------------------------------------------------------------------
// Triangles.

// Where the ray's supporting line meets the closed triangle, exactly.
enum class Region { Interior, Edge, Vertex, Outside };

struct TriangleTruth {
    // The truth under the stage 02 contract with t_range = (0, +inf): the ray meets the closed
    // triangle at one point with t > 0. A ray parallel to the plane (also one lying in it) and a
    // ray starting in the plane (t = 0) do not hit.
    bool hit = false;
    bool parallel = false;            // d is exactly parallel to the plane (n.d == 0)
    bool origin_in_plane = false;     // the origin lies exactly in the plane
    bool cgal_consistent = true;      // Epick do_intersect agrees with the Epeck construction
    Region region = Region::Outside;  // for the plane point (meaningful unless parallel)
    FT t = 0;                         // exact t of the plane point (when not parallel)
    std::array<FT, 3> bary{0, 0, 0};  // exact barycentric weights of a, b, c at that point
    // Signed distance of the plane point to the nearest edge line: the minimum over the three
    // edges of (barycentric weight of the opposite vertex) x (height over that edge). Inside the
    // triangle it is the distance to the boundary; outside it is minus the distance to the line
    // of a violated edge. |edge_distance| is what the near-edge tolerance bands refer to.
    double edge_distance = 0;
};

// Exact answer for ray vs triangle (a, b, c). The triangle must not be degenerate.
TriangleTruth exact_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c);

// ---------------------------------------------------------------------------------------------
// Planes: {x : n.(x - p) = 0} with the float normal and point taken exactly as given (the normal
// need not be exactly unit length; the plane is the same).

struct PlaneTruth {
    bool hit = false;
    bool parallel = false;
    bool origin_in_plane = false;
    FT t = 0;
};

PlaneTruth exact_plane(const Ray& ray, const Plane& plane);

// ---------------------------------------------------------------------------------------------
// Boxes: exact slabs in rationals, cross-checked against CGAL::do_intersect(Ray_3, Iso_cuboid_3)
// evaluated with Epeck.

struct BoxTruth {
    bool hit = false;  // some t > 0 inside the closed box
    bool cgal_consistent = true;
    bool origin_inside = false;  // closed box
    Q t_near, t_far;             // the ray's parameter interval inside the slabs (may be empty)
    Q t;                         // the reported parameter: t_near if > 0, else t_far
    int axis = -1;               // the slab whose face bounds t (the face hit)
    bool at_near = false;        // t is t_near (entry face), else t_far (exit face)
    // Relative width (t_far - t_near) / max(|t_near|, |t_far|) of the ray's parameter interval
    // in the slabs; negative when the ray passes beside the box. Rays grazing an edge or a corner
    // have a tiny |relative_gap|, and only those may be decided differently in Real arithmetic.
    double relative_gap = 0;
    // Relative margin between t and the same bound (entry or exit) of the next slab: a ray
    // entering close to an edge of the box has a tiny one, and the face it reports may be
    // either of the two faces meeting there. Infinite when only one slab bounds the ray.
    double face_margin = std::numeric_limits<double>::infinity();
};

BoxTruth exact_box(const Ray& ray, const Box& box);

// ---------------------------------------------------------------------------------------------
// Spheres: |o + t d - c|^2 = r^2, i.e. a t^2 + 2 b t + k = 0 with a = d.d, b = d.(o - c),
// k = |o - c|^2 - r^2, all exact rationals. The discriminant b^2 - a k decides hit/miss exactly;
// the root itself is irrational, so it is computed with MPFR at 256 bits (relative error about
// 1e-77, i.e. exact for any comparison with a float or a double).

class BigFloat {
  public:
    static constexpr mpfr_prec_t kBits = 256;
    BigFloat() {
        mpfr_init2(v_, kBits);
        mpfr_set_zero(v_, 1);
    }
    explicit BigFloat(const Q& q) : BigFloat() { mpfr_set_q(v_, q.mpq(), MPFR_RNDN); }
    BigFloat(const BigFloat& o) : BigFloat() { mpfr_set(v_, o.v_, MPFR_RNDN); }
    BigFloat& operator=(const BigFloat& o) {
        mpfr_set(v_, o.v_, MPFR_RNDN);
        return *this;
    }
    ~BigFloat() { mpfr_clear(v_); }
    mpfr_ptr get() { return v_; }
    mpfr_srcptr get() const { return v_; }
    double to_double() const { return mpfr_get_d(v_, MPFR_RNDN); }

    // |computed - this| in units of the last place (of Real) at this value.
    double ulp_error(Real computed) const {
        BigFloat diff;
        mpfr_sub_d(diff.v_, v_, double(computed), MPFR_RNDN);
        return std::abs(diff.to_double()) / ulp_of(to_double());
    }

  private:
    mpfr_t v_;
};

struct SphereTruth {
    int discriminant_sign = -1;     // exact sign of b^2 - a k
    bool hit = false;               // a root with t > 0 exists (the contract with (0, +inf))
    bool origin_on_sphere = false;  // k == 0 exactly
    BigFloat t;                     // the smallest root > 0 (when hit)
    // (distance from the centre to the ray's line) - radius, approximately: negative for lines
    // that cut the sphere, positive for lines that pass by it. Near-tangent rays have a tiny
    // |tangency|; only those may be decided differently in Real arithmetic.
    double tangency = 0;
};

SphereTruth exact_sphere(const Ray& ray, const Sphere& sphere);

// ---------------------------------------------------------------------------------------------
// Closed triangle meshes (consistently counter-clockwise seen from outside), for leak tests.

struct Mesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    std::vector<std::array<int, 2>> edges() const {  // each undirected edge once
        std::vector<std::array<int, 2>> out;
        for (const auto& t : triangles)
            for (int i = 0; i < 3; ++i) {
                const int u = t[i], v = t[(i + 1) % 3];
                if (u < v) out.push_back({u, v});
            }
        return out;
    }
};

// The regular octahedron with vertices +-s on the axes (exact in float for s a power of two).
Mesh octahedron(Real s = 1);

// The cube [-s, s]^3 as 12 triangles (each face split along a diagonal).
Mesh cube(Real s = 1);

// An icosahedron subdivided `levels` times on the sphere of radius `radius`: the framework's
// make_icosphere (geometry/procedural_mesh.h; computed in double, rounded to Real). Shared
// vertices are shared by index, so the mesh is closed exactly.
Mesh icosphere(int levels, Real radius = 1);

// True when the ray (t > 0) meets the closed mesh, exactly: some triangle is hit, or the ray
// passes through an edge or a vertex (which do_intersect on the triangles already covers).
bool exact_mesh_hit(const Ray& ray, const Mesh& mesh);

}  // namespace rt::exact
