// The exact reference answers (exact_reference.h), compiled once into rt_exact.
#include "testing/exact_reference.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <utility>

#include "geometry/procedural_mesh.h"

namespace rt::exact {

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

Epick::Point_3 epick_point(const Vec3& p) {
    return {double(p.x), double(p.y), double(p.z)};
}
Epick::Vector_3 epick_vector(const Vec3& v) {
    return {double(v.x), double(v.y), double(v.z)};
}

}  // namespace

TriangleTruth exact_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c) {
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
    const bool touches =
        CGAL::do_intersect(Epick::Ray_3(epick_point(ray.origin), epick_vector(ray.direction)),
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
    truth.region = !inside         ? Region::Outside
                   : on_edges >= 2 ? Region::Vertex
                   : on_edges == 1 ? Region::Edge
                                   : Region::Interior;

    // Edge distance in double from the exact weights: height over edge bc is 2 area / |bc|.
    const double area2 = std::sqrt(CGAL::to_double(nn));
    const double len_bc = std::sqrt(CGAL::to_double((C - B).squared_length()));
    const double len_ca = std::sqrt(CGAL::to_double((A - C).squared_length()));
    const double len_ab = std::sqrt(CGAL::to_double((B - A).squared_length()));
    truth.edge_distance =
        std::min({CGAL::to_double(alpha) * area2 / len_bc, CGAL::to_double(beta) * area2 / len_ca,
                  CGAL::to_double(gamma) * area2 / len_ab});

    const bool positive_t = CGAL::sign(truth.t) == CGAL::POSITIVE;
    truth.hit = inside && positive_t && !truth.origin_in_plane;
    // do_intersect(Ray_3) also counts the source (t = 0); otherwise both must agree.
    const bool expected_touch = inside && CGAL::sign(truth.t) != CGAL::NEGATIVE;
    truth.cgal_consistent = touches == expected_touch;
    return truth;
}

PlaneTruth exact_plane(const Ray& ray, const Plane& plane) {
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

BoxTruth exact_box(const Ray& ray, const Box& box) {
    BoxTruth truth;
    // Epeck, not Epick: in CGAL 5.5 do_intersect(Ray_3, Iso_cuboid_3) with Epick is NOT exact
    // (it is not a filtered predicate; it evaluates the slab parameters in double). Found by this
    // cross-check: a double-precision ray missing a box corner by a relative 1e-16 was reported
    // as touching by Epick, as missing by Epeck and by the exact slabs below.
    const bool touches =
        CGAL::do_intersect(Epeck::Ray_3(epeck_point(ray.origin), epeck_vector(ray.direction)),
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
    const double scale =
        std::max(std::abs(CGAL::to_double(truth.t_near)), std::abs(CGAL::to_double(truth.t_far)));
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

SphereTruth exact_sphere(const Ray& ray, const Sphere& sphere) {
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
    if (k > 0)
        which = b < 0 ? kSmaller : kNone;  // same signs: both positive iff b < 0
    else if (k < 0)
        which = kLarger;  // opposite signs: the larger one
    else
        which = b < 0 ? kLarger : kNone;  // roots 0 and -2b/a: the nonzero one if > 0
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
        if (b > 0)
            mpfr_add(q.get(), B.get(), s.get(), MPFR_RNDN);
        else
            mpfr_sub(q.get(), B.get(), s.get(), MPFR_RNDN);
        mpfr_neg(q.get(), q.get(), MPFR_RNDN);
        mpfr_div(t0.get(), q.get(), A.get(), MPFR_RNDN);
        mpfr_div(t1.get(), K.get(), q.get(), MPFR_RNDN);
        if (mpfr_cmp(t0.get(), t1.get()) > 0) std::swap(t0, t1);
    }
    truth.t = which == kSmaller ? t0 : t1;
    return truth;
}

Mesh octahedron(Real s) {
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

Mesh cube(Real s) {
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

Mesh icosphere(int levels, Real radius) {
    const TriangleMesh ico = make_icosphere(levels, radius);
    Mesh m;
    m.vertices = ico.vertices;
    for (const auto& t : ico.triangles) m.triangles.push_back({int(t[0]), int(t[1]), int(t[2])});
    return m;
}

bool exact_mesh_hit(const Ray& ray, const Mesh& mesh) {
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
