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
// Shared by cgal_exact_test.cpp and (later) the accuracy benchmark, so it depends on nothing but
// the framework's core types, CGAL, GMP and MPFR.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/intersections.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <utility>
#include <random>
#include <vector>

#include "core/ray.h"
#include "scene/scene.h"

namespace rt::exact {

// Uniform numbers from a fixed-seed 64-bit Mersenne twister, mapped by hand (the standard
// distributions differ between library implementations; this mapping does not).
struct Rng {
    std::mt19937_64 engine;
    explicit Rng(std::uint64_t seed) : engine(seed) {}
    double uniform(double lo, double hi) { return lo + (hi - lo) * double(engine() >> 11) * 0x1p-53; }
    int integer(int lo, int hi) { return lo + int(engine() % std::uint64_t(hi - lo + 1)); }
    Vec3 vec(double lo, double hi) {
        const double x = uniform(lo, hi), y = uniform(lo, hi), z = uniform(lo, hi);
        return Vec3(Real(x), Real(y), Real(z));
    }
    Vec3 unit() {
        for (;;) {
            const Vec3 v = vec(-1, 1);
            const Real l = glm::length(v);
            if (l > Real(0.1) && l <= 1) return v / l;
        }
    }
};

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Epeck::FT;  // an exact rational (lazily evaluated)
using Q = CGAL::Gmpq;  // an exact rational, for the hand-written formulas

// ---------------------------------------------------------------------------------------------
// Conversions. A Real converts to double exactly (float is a subset of double).

inline Epick::Point_3 epick_point(const Vec3& p) { return {double(p.x), double(p.y), double(p.z)}; }
inline Epick::Vector_3 epick_vector(const Vec3& v) {
    return {double(v.x), double(v.y), double(v.z)};
}
inline Epeck::Point_3 epeck_point(const Vec3& p) { return {double(p.x), double(p.y), double(p.z)}; }
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
    bool parallel = false;         // d is exactly parallel to the plane (n.d == 0)
    bool origin_in_plane = false;  // the origin lies exactly in the plane
    bool cgal_consistent = true;   // Epick do_intersect agrees with the Epeck construction
    Region region = Region::Outside;  // for the plane point (meaningful unless parallel)
    FT t = 0;                          // exact t of the plane point (when not parallel)
    std::array<FT, 3> bary{0, 0, 0};   // exact barycentric weights of a, b, c at that point
    // Signed distance of the plane point to the nearest edge line: the minimum over the three
    // edges of (barycentric weight of the opposite vertex) x (height over that edge). Inside the
    // triangle it is the distance to the boundary; outside it is minus the distance to the line
    // of a violated edge. |edge_distance| is what the near-edge tolerance bands refer to.
    double edge_distance = 0;
};

// Exact answer for ray vs triangle (a, b, c). The triangle must not be degenerate.
inline TriangleTruth exact_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c) {
    TriangleTruth truth;
    const Epeck::Point_3 A = epeck_point(a), B = epeck_point(b), C = epeck_point(c);
    const Epeck::Point_3 O = epeck_point(ray.origin);
    const Epeck::Vector_3 D = epeck_vector(ray.direction);
    const Epeck::Vector_3 n = CGAL::cross_product(B - A, C - A);
    const FT n_dot_d = n * D;
    truth.parallel = CGAL::sign(n_dot_d) == CGAL::ZERO;
    truth.origin_in_plane = CGAL::orientation(A, B, C, O) == CGAL::COPLANAR;

    // The hit/miss truth straight from CGAL's exact predicate on the ray (which includes its
    // source and, for a ray lying in the plane, segments).
    const bool touches = CGAL::do_intersect(
        Epick::Ray_3(epick_point(ray.origin), epick_vector(ray.direction)),
        Epick::Triangle_3(epick_point(a), epick_point(b), epick_point(c)));
    if (truth.parallel) {
        truth.hit = false;
        return truth;
    }

    // The exact point where the supporting line meets the plane (the line, so misses behind the
    // origin still get a plane point and an edge distance), then t exactly along the ray.
    const Epeck::Plane_3 plane(A, B, C);
    const auto meet = CGAL::intersection(Epeck::Line_3(O, D), plane);
    const Epeck::Point_3* P = meet ? boost::get<Epeck::Point_3>(&*meet) : nullptr;
    if (!P) {  // cannot happen for a non-parallel line; be loud about it
        truth.cgal_consistent = false;
        return truth;
    }
    truth.t = ((*P - O) * D) / (D * D);

    // Barycentric weights from the sub-triangle normals: beta = n.((p - a) x (c - a)) / n.n etc.
    const FT nn = n * n;
    const FT beta = (n * CGAL::cross_product(*P - A, C - A)) / nn;
    const FT gamma = (n * CGAL::cross_product(B - A, *P - A)) / nn;
    const FT alpha = FT(1) - beta - gamma;
    truth.bary = {alpha, beta, gamma};

    // Classification by orientation of the ray's line against each edge: the line meets the
    // edge's line exactly when the four points are coplanar.
    const Epeck::Point_3 Q2 = O + D;
    const bool on_bc = CGAL::orientation(O, Q2, B, C) == CGAL::COPLANAR;
    const bool on_ca = CGAL::orientation(O, Q2, C, A) == CGAL::COPLANAR;
    const bool on_ab = CGAL::orientation(O, Q2, A, B) == CGAL::COPLANAR;
    const bool inside = CGAL::sign(alpha) != CGAL::NEGATIVE && CGAL::sign(beta) != CGAL::NEGATIVE &&
                        CGAL::sign(gamma) != CGAL::NEGATIVE;
    const int on_edges = int(on_bc) + int(on_ca) + int(on_ab);
    truth.region = !inside ? Region::Outside
                   : on_edges >= 2 ? Region::Vertex
                   : on_edges == 1 ? Region::Edge
                                   : Region::Interior;

    // Edge distance in double from the exact weights: height over edge bc is 2 area / |bc|.
    const double area2 = std::sqrt(CGAL::to_double(nn));
    const double len_bc = std::sqrt(CGAL::to_double((C - B).squared_length()));
    const double len_ca = std::sqrt(CGAL::to_double((A - C).squared_length()));
    const double len_ab = std::sqrt(CGAL::to_double((B - A).squared_length()));
    truth.edge_distance = std::min({CGAL::to_double(alpha) * area2 / len_bc,
                                    CGAL::to_double(beta) * area2 / len_ca,
                                    CGAL::to_double(gamma) * area2 / len_ab});

    const bool positive_t = CGAL::sign(truth.t) == CGAL::POSITIVE;
    truth.hit = inside && positive_t && !truth.origin_in_plane;
    // do_intersect(Ray_3) also counts the source (t = 0); otherwise both must agree.
    const bool expected_touch = inside && CGAL::sign(truth.t) != CGAL::NEGATIVE;
    truth.cgal_consistent = touches == expected_touch;
    return truth;
}

// ---------------------------------------------------------------------------------------------
// Planes: {x : n.(x - p) = 0} with the float normal and point taken exactly as given (the normal
// need not be exactly unit length; the plane is the same).

struct PlaneTruth {
    bool hit = false;
    bool parallel = false;
    bool origin_in_plane = false;
    FT t = 0;
};

inline PlaneTruth exact_plane(const Ray& ray, const Plane& plane) {
    PlaneTruth truth;
    const Epeck::Plane_3 P(epeck_point(plane.point), epeck_vector(plane.normal));
    const Epeck::Point_3 O = epeck_point(ray.origin);
    const Epeck::Vector_3 D = epeck_vector(ray.direction);
    truth.parallel = CGAL::sign(P.orthogonal_vector() * D) == CGAL::ZERO;
    truth.origin_in_plane = P.has_on(O);
    if (truth.parallel) return truth;
    const auto meet = CGAL::intersection(Epeck::Line_3(O, D), P);
    const Epeck::Point_3* X = meet ? boost::get<Epeck::Point_3>(&*meet) : nullptr;
    if (!X) return truth;
    truth.t = ((*X - O) * D) / (D * D);
    truth.hit = CGAL::sign(truth.t) == CGAL::POSITIVE;
    return truth;
}

// ---------------------------------------------------------------------------------------------
// Boxes: exact slabs in rationals, cross-checked against CGAL::do_intersect(Ray_3, Iso_cuboid_3)
// evaluated with Epeck.

struct BoxTruth {
    bool hit = false;           // some t > 0 inside the closed box
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

inline BoxTruth exact_box(const Ray& ray, const Box& box) {
    BoxTruth truth;
    // Epeck, not Epick: in CGAL 5.5 do_intersect(Ray_3, Iso_cuboid_3) with Epick is NOT exact
    // (it is not a filtered predicate; it evaluates the slab parameters in double). Found by this
    // cross-check: a double-precision ray missing a box corner by a relative 1e-16 was reported
    // as touching by Epick, as missing by Epeck and by the exact slabs below.
    const bool touches = CGAL::do_intersect(
        Epeck::Ray_3(epeck_point(ray.origin), epeck_vector(ray.direction)),
        Epeck::Iso_cuboid_3(epeck_point(box.min), epeck_point(box.max)));
    bool parallel_outside = false;
    std::vector<std::pair<Q, int>> entries, exits;
    truth.origin_inside = true;
    for (int i = 0; i < 3; ++i) {
        const Q o(double(ray.origin[i])), d(double(ray.direction[i]));
        const Q lo(double(box.min[i])), hi(double(box.max[i]));
        if (o < lo || o > hi) truth.origin_inside = false;
        if (d == 0) {
            if (o < lo || o > hi) parallel_outside = true;
            continue;
        }
        Q t0 = (lo - o) / d, t1 = (hi - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        entries.push_back({t0, i});
        exits.push_back({t1, i});
    }
    if (entries.empty() || parallel_outside) {  // zero direction, or beside a slab it never enters
        truth.cgal_consistent = !touches;
        return truth;
    }
    std::sort(entries.begin(), entries.end(), [](auto& x, auto& y) { return x.first > y.first; });
    std::sort(exits.begin(), exits.end(), [](auto& x, auto& y) { return x.first < y.first; });
    truth.t_near = entries[0].first;
    truth.t_far = exits[0].first;
    const double scale = std::max(std::abs(CGAL::to_double(truth.t_near)),
                                  std::abs(CGAL::to_double(truth.t_far)));
    truth.relative_gap = CGAL::to_double(truth.t_far - truth.t_near) / scale;
    const bool meets = truth.t_near <= truth.t_far;
    truth.hit = meets && truth.t_far > 0;
    if (truth.hit) {
        truth.at_near = truth.t_near > 0;
        const auto& bounds = truth.at_near ? entries : exits;
        truth.t = bounds[0].first;
        truth.axis = bounds[0].second;
        if (bounds.size() > 1)
            truth.face_margin =
                std::abs(CGAL::to_double(bounds[0].first - bounds[1].first)) / scale;
    }
    const bool expected_touch = meets && truth.t_far >= 0;
    truth.cgal_consistent = touches == expected_touch;
    return truth;
}

// ---------------------------------------------------------------------------------------------
// Spheres: |o + t d - c|^2 = r^2, i.e. a t^2 + 2 b t + k = 0 with a = d.d, b = d.(o - c),
// k = |o - c|^2 - r^2, all exact rationals. The discriminant b^2 - a k decides hit/miss exactly;
// the root itself is irrational, so it is computed with MPFR at 256 bits (relative error about
// 1e-77, i.e. exact for any comparison with a float or a double).

class BigFloat {
public:
    static constexpr mpfr_prec_t kBits = 256;
    BigFloat() { mpfr_init2(v_, kBits); mpfr_set_zero(v_, 1); }
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
    int discriminant_sign = -1;  // exact sign of b^2 - a k
    bool hit = false;            // a root with t > 0 exists (the contract with (0, +inf))
    bool origin_on_sphere = false;  // k == 0 exactly
    BigFloat t;                  // the smallest root > 0 (when hit)
    // (distance from the centre to the ray's line) - radius, approximately: negative for lines
    // that cut the sphere, positive for lines that pass by it. Near-tangent rays have a tiny
    // |tangency|; only those may be decided differently in Real arithmetic.
    double tangency = 0;
};

inline SphereTruth exact_sphere(const Ray& ray, const Sphere& sphere) {
    SphereTruth truth;
    Q a = 0, b = 0, k = 0;
    for (int i = 0; i < 3; ++i) {
        const Q d(double(ray.direction[i]));
        const Q oc = Q(double(ray.origin[i])) - Q(double(sphere.center[i]));
        a += d * d;
        b += d * oc;
        k += oc * oc;
    }
    const Q r(double(sphere.radius));
    k -= r * r;
    const Q disc = b * b - a * k;
    truth.discriminant_sign = CGAL::sign(disc);
    truth.origin_on_sphere = k == 0;
    // dist^2 - r^2 = -disc / a; dist - r = (dist^2 - r^2) / (dist + r), with dist + r ~ 2r.
    truth.tangency = -CGAL::to_double(disc / a) / (2 * CGAL::to_double(r));
    if (truth.discriminant_sign < 0 || a == 0) return truth;

    // Which root, decided exactly without square roots: the roots multiply to k / a and add up
    // to -2 b / a.
    enum { kNone, kSmaller, kLarger } which = kNone;
    if (k > 0) which = b < 0 ? kSmaller : kNone;  // same signs: both positive iff b < 0
    else if (k < 0) which = kLarger;              // opposite signs: the larger one
    else which = b < 0 ? kLarger : kNone;         // roots 0 and -2b/a: the nonzero one if > 0
    if (which == kNone) return truth;
    truth.hit = true;

    // The root in 256-bit MPFR, in the cancellation-free form (q = -(b + sign(b) sqrt(disc)),
    // roots q / a and k / q), so that even the high-precision value has no cancellation.
    BigFloat s(disc), A(a), B(b), K(k), q, t0, t1;
    mpfr_sqrt(s.get(), s.get(), MPFR_RNDN);
    if (b == 0) {
        mpfr_div(t1.get(), s.get(), A.get(), MPFR_RNDN);  // roots -+ sqrt(disc) / a
        mpfr_neg(t0.get(), t1.get(), MPFR_RNDN);
    } else {
        if (b > 0) mpfr_add(q.get(), B.get(), s.get(), MPFR_RNDN);
        else mpfr_sub(q.get(), B.get(), s.get(), MPFR_RNDN);
        mpfr_neg(q.get(), q.get(), MPFR_RNDN);
        mpfr_div(t0.get(), q.get(), A.get(), MPFR_RNDN);
        mpfr_div(t1.get(), K.get(), q.get(), MPFR_RNDN);
        if (mpfr_cmp(t0.get(), t1.get()) > 0) std::swap(t0, t1);
    }
    truth.t = which == kSmaller ? t0 : t1;
    return truth;
}

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
inline Mesh octahedron(Real s = 1) {
    Mesh m;
    m.vertices = {{s, 0, 0}, {-s, 0, 0}, {0, s, 0}, {0, -s, 0}, {0, 0, s}, {0, 0, -s}};
    // Each face: one vertex from each axis pair, ordered counter-clockwise from outside.
    for (int sx = 0; sx < 2; ++sx)
        for (int sy = 0; sy < 2; ++sy)
            for (int sz = 0; sz < 2; ++sz) {
                std::array<int, 3> t{sx, 2 + sy, 4 + sz};
                if ((sx + sy + sz) % 2 == 1) std::swap(t[1], t[2]);
                m.triangles.push_back(t);
            }
    return m;
}

// The cube [-s, s]^3 as 12 triangles (each face split along a diagonal).
inline Mesh cube(Real s = 1) {
    Mesh m;
    for (int i = 0; i < 8; ++i)
        m.vertices.push_back({i & 1 ? s : -s, i & 2 ? s : -s, i & 4 ? s : -s});
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

// An icosahedron subdivided `levels` times, vertices pushed onto the sphere of radius `radius`
// (in Real arithmetic: the vertices are whatever floats that gives; shared vertices are shared
// by index, so the mesh is closed exactly).
inline Mesh icosphere(int levels, Real radius = 1) {
    Mesh m;
    const Real g = (1 + std::sqrt(Real(5))) / 2;
    const Vec3 base[12] = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                           {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                           {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (const Vec3& v : base) m.vertices.push_back(glm::normalize(v) * radius);
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<int, int>, int> midpoint;
        auto mid = [&](int u, int v) {
            const auto key = std::minmax(u, v);
            const auto it = midpoint.find(key);
            if (it != midpoint.end()) return it->second;
            m.vertices.push_back(glm::normalize(m.vertices[u] + m.vertices[v]) * radius);
            return midpoint[key] = int(m.vertices.size()) - 1;
        };
        std::vector<std::array<int, 3>> next;
        for (const auto& t : m.triangles) {
            const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
            next.push_back({t[0], ab, ca});
            next.push_back({t[1], bc, ab});
            next.push_back({t[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        m.triangles = std::move(next);
    }
    return m;
}

// True when the ray (t > 0) meets the closed mesh, exactly: some triangle is hit, or the ray
// passes through an edge or a vertex (which do_intersect on the triangles already covers).
inline bool exact_mesh_hit(const Ray& ray, const Mesh& mesh) {
    const Epick::Ray_3 r(epick_point(ray.origin), epick_vector(ray.direction));
    for (const auto& t : mesh.triangles) {
        const Epick::Triangle_3 tri(epick_point(mesh.vertices[t[0]]),
                                    epick_point(mesh.vertices[t[1]]),
                                    epick_point(mesh.vertices[t[2]]));
        if (CGAL::do_intersect(r, tri)) return true;
    }
    return false;
}

}  // namespace rt::exact
