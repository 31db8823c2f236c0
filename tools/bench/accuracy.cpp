// The accuracy lab's run (see accuracy.h): exact answers by CGAL, the self-intersection
// experiment, and run_accuracy over the scenarios of scenarios.cpp.
//
// Every case is made of floats, and the double methods get the same floats converted: both
// precisions then solve the very same geometric problem, CGAL decides it exactly once, and any
// difference between them is arithmetic, not input rounding.
#include "bench/accuracy.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <thread>

#include "bench/cases.h"
#include "bench/scenarios.h"
#include "testing/exact_reference.h"

namespace rt::bench {
namespace {

using namespace detail;
using exact::Epeck;
using exact::Rng;
using V3f = glm::vec<3, float>;
using V3d = glm::vec<3, double>;
using Clock = std::chrono::steady_clock;

// ---------------------------------------------------------------------------------------------
// Exact answers.

ExactT split(const exact::FT& t) {
    const double hi = CGAL::to_double(t);
    return {hi, CGAL::to_double(t - exact::FT(hi))};
}

// Exact predicates on the float inputs (converted to double exactly). Filtered: only close
// calls pay for exact rationals.
PairTruth exact_pair(const V3f& o, const V3f& d, const V3f& a, const V3f& b, const V3f& c) {
    PairTruth r;
    using P = Epeck::Point_3;
    const P O(o.x, o.y, o.z), A(a.x, a.y, a.z), B(b.x, b.y, b.z), C(c.x, c.y, c.z);
    const Epeck::Vector_3 D(d.x, d.y, d.z);
    const Epeck::Vector_3 n = CGAL::cross_product(B - A, C - A);
    const exact::FT nd = n * D;
    r.facing = int(CGAL::sign(nd));
    if (r.facing == 0) return r;
    const exact::FT na = n * (A - O);
    if (int(CGAL::sign(na)) != r.facing) return r;  // t <= 0
    const P Q = O + D;
    const int s1 = int(CGAL::orientation(O, Q, B, C)), s2 = int(CGAL::orientation(O, Q, C, A)),
              s3 = int(CGAL::orientation(O, Q, A, B));
    if ((s1 < 0 || s2 < 0 || s3 < 0) && (s1 > 0 || s2 > 0 || s3 > 0)) return r;
    r.hit = true;
    r.region = int(s1 == 0) + int(s2 == 0) + int(s3 == 0);
    r.t = split(na / nd);
    return r;
}

SphereTruthLite exact_sphere_case(const SphereCase& c) {
    const Ray ray{Vec3(c.o), Vec3(c.d)};
    const Sphere sphere{Vec3(c.center), Real(c.radius)};
    exact::SphereTruth truth = exact::exact_sphere(ray, sphere);
    SphereTruthLite r;
    r.hit = truth.hit;
    if (r.hit) {
        r.t.hi = truth.t.to_double();
        exact::BigFloat diff;
        mpfr_sub_d(diff.get(), truth.t.get(), r.t.hi, MPFR_RNDN);
        r.t.lo = diff.to_double();
    }
    return r;
}

TriTruthSet triangle_truth(const Scenario& s) {
    TriTruthSet t;
    const auto start = Clock::now();
    for (const TriangleCase& c : s.tris) t.single.push_back(exact_pair(c.o, c.d, c.a, c.b, c.c));
    for (const MeshCase& r : s.rays) {
        const MeshData& m = s.meshes[r.mesh];
        std::vector<PairTruth> per;
        for (const auto& f : m.tri)
            per.push_back(exact_pair(r.o, r.d, m.v[f[0]], m.v[f[1]], m.v[f[2]]));
        t.tests += long(m.tri.size());
        t.mesh.push_back(std::move(per));
    }
    t.tests += long(s.tris.size());
    t.ns = std::chrono::duration<double>(Clock::now() - start).count() * 1e9 / double(t.tests);
    return t;
}

Row exact_triangle_row(const Scenario& s, const TriTruthSet& truth) {
    Row row{"triangle", s.info.key, s.info.mesh, "CGAL (exact)", "exact", {}, truth.ns};
    row.counts.tests = truth.tests;
    row.counts.cases = long(s.tris.size() + s.rays.size());
    for (const auto& per : truth.mesh) {
        std::vector<char> reported;
        for (const PairTruth& p : per) reported.push_back(p.hit);
        if (judge_mesh(per, reported).double_hit) row.counts.double_hit++;
    }
    return row;
}

// ---------------------------------------------------------------------------------------------
// Self-intersection: rays leaving a triangle they were found on, at three scene scales.

constexpr double kFixedEpsilon = 1e-4;  // the "typical" constant of fixed-epsilon renderers

template <typename T>
void self_intersection(std::uint64_t seed, int n, std::vector<SelfRow>& out) {
    const T inf = std::numeric_limits<T>::infinity();
    const char* prec = std::is_same_v<T, float> ? "float" : "double";
    for (double scale : {1.0, 1e2, 1e4}) {
        SelfRow rows[3] = {{"fixed tmin", prec, scale},
                           {"normal offset", prec, scale},
                           {"robust offset", prec, scale}};
        Rng rng(seed * 7919 + std::uint64_t(std::log10(scale)));
        for (int i = 0; i < n; ++i) {
            const V3d offset = rvec(rng, -scale, scale);
            const V3d ad = rvec(rng, -1, 1) * scale + offset,
                      bd = rvec(rng, -1, 1) * scale + offset,
                      cd = rvec(rng, -1, 1) * scale + offset;
            if (glm::length(glm::cross(bd - ad, cd - ad)) < 0.2 * scale * scale) continue;
            const V3<T> a(ad), b(bd), c(cd);
            const double bu = rng.uniform(0.2, 0.5), bv = rng.uniform(0.2, 0.5);
            const V3d target = ad + bu * (bd - ad) + bv * (cd - ad);
            const V3d nd = glm::normalize(glm::cross(bd - ad, cd - ad));
            const V3d from =
                glm::normalize(nd * (rng.integer(0, 1) ? 1.0 : -1.0) + 0.7 * runit(rng));
            const V3<T> o(target + from * 2.0 * scale), d(target - (target + from * 2.0 * scale));
            const Result<T> hit = watertight<T>(o, d, a, b, c, T(0), inf);
            if (!hit.hit) continue;
            const V3<T> n = glm::normalize(glm::cross(b - a, c - a));
            const V3<T> side = glm::dot(n, d) < 0 ? n : -n;  // towards where the ray came from
            // Leaving direction: any angle, down to grazing (cos 1e-3); for the occluder, cos >=
            // 0.3.
            const V3d sided(side);
            const V3d tangent = glm::normalize(glm::cross(sided, runit(rng)));
            const double cos_leave =
                rng.integer(0, 1) ? log_uniform(rng, -3, 0) : rng.uniform(0.3, 1);
            const V3<T> leave(sided * cos_leave + tangent * std::sqrt(1 - cos_leave * cos_leave));
            const V3<T> p_ray = o + hit.t * d;
            V3<T> p_bary, err;
            triangle_surface_point(a, b, c, hit.beta, hit.gamma, p_bary, err);
            V3<T> origin[3] = {p_ray, p_ray + side * T(kFixedEpsilon),
                               offset_ray_origin(p_bary, err, side, leave)};
            const T tmin[3] = {T(kFixedEpsilon), T(0), T(0)};
            for (int k = 0; k < 3; ++k) {
                rows[k].rays++;
                if (watertight<T>(origin[k], leave, a, b, c, tmin[k], inf).hit) rows[k].self_hits++;
            }
            if (cos_leave < 0.3) continue;
            // Occluders: the triangle enlarged 4x about its centroid, lifted by the gap.
            const V3d centroid = (ad + bd + cd) / 3.0;
            for (int k = 0; k < 3; ++k) rows[k].occluder_rays++;
            for (double gap : {1e-2, 1e-4}) {
                const V3d lift = sided * gap * scale;
                const V3<T> oa(centroid + 4.0 * (ad - centroid) + lift),
                    ob(centroid + 4.0 * (bd - centroid) + lift),
                    oc(centroid + 4.0 * (cd - centroid) + lift);
                // The origin for the occluder test leaves towards it, like a shadow ray.
                const V3<T> robust = offset_ray_origin(p_bary, err, side, leave);
                const V3<T> orig[3] = {origin[0], origin[1], robust};
                for (int k = 0; k < 3; ++k)
                    if (!watertight<T>(orig[k], leave, oa, ob, oc, tmin[k], inf).hit)
                        (gap == 1e-2 ? rows[k].missed_gap_1e2 : rows[k].missed_gap_1e4)++;
            }
        }
        for (const SelfRow& r : rows) out.push_back(r);
    }
}

}  // namespace

const std::vector<ScenarioInfo>& scenarios() {
    static const std::vector<ScenarioInfo> list = {
        {"random", "triangle", "random triangles in [-1,1]^3, rays from [-4,4]^3 aimed near them",
         false},
        {"near-edge", "triangle",
         "closed meshes, rays crossing 1e-8..1e-3 (relative) beside a shared edge", true},
        {"through-edge", "triangle", "closed dyadic meshes, rays exactly through a shared edge",
         true},
        {"near-vertex", "triangle",
         "closed meshes, rays crossing 1e-8..1e-3 (relative) from a vertex", true},
        {"through-vertex", "triangle", "closed dyadic meshes, rays exactly through a vertex", true},
        {"sliver", "triangle", "needles and caps 1e-5..1e-3 thin, rays aimed at them", false},
        {"grazing", "triangle", "rays meeting the plane at 1e-5..1e-1 rad", false},
        {"offset-1e3", "triangle",
         "closed meshes moved 1e3 from the origin, rays at faces, edges, vertices", true},
        {"offset-1e5", "triangle",
         "closed meshes moved 1e5 from the origin, rays at faces, edges, vertices", true},
        {"sphere-random", "sphere",
         "radius 0.5..2 in [-5,5]^3, rays from [-10,10]^3 aimed near them", false},
        {"sphere-grazing", "sphere", "lines passing the centre at r (1 +- 1e-7..1e-2)", false},
        {"sphere-offset-1e3", "sphere", "the random scenario moved by up to 1e3", false},
        {"sphere-offset-1e5", "sphere", "the random scenario moved by up to 1e5", false},
        {"far-small", "sphere",
         "radius 1 at distance 1e3..3e4, lines within 0.95 r or beyond 1.05 r", false},
        {"large-near", "sphere", "radius 1e3..1e4, origins 1e-2..1 above the surface", false},
        {"sphere-inside", "sphere",
         "origins inside a sphere of radius 0.5..2, rays in every direction (every ray hits)",
         false},
    };
    return list;
}

AccuracyResults run_accuracy(const AccuracyConfig& config) {
    AccuracyResults res;
    res.config = config;
    const auto start = Clock::now();
    const std::vector<Scenario> all = make_scenarios(config.seed, config.cases);
    for (const Scenario& s : all) {
        if (!config.family.empty() && s.info.family != config.family) continue;
        if (s.info.family == "triangle") {
            const TriTruthSet truth = triangle_truth(s);
            detail::triangle_rows(s, truth, config.timing, res.rows);
            res.rows.push_back(exact_triangle_row(s, truth));
        } else {
            std::vector<SphereTruthLite> truth;
            const auto t0 = Clock::now();
            for (const SphereCase& c : s.spheres) truth.push_back(exact_sphere_case(c));
            const double ns = std::chrono::duration<double>(Clock::now() - t0).count() * 1e9 /
                              double(s.spheres.size());
            detail::sphere_rows(s, truth, config.timing, res.rows);
            Row row{"sphere", s.info.key, false, "CGAL (exact)", "exact", {}, ns};
            row.counts.cases = row.counts.tests = long(s.spheres.size());
            res.rows.push_back(row);
        }
        if (config.progress) config.progress("scenario " + s.info.key);
    }
    if (config.self_intersection) {
        self_intersection<float>(config.seed, config.cases, res.self);
        self_intersection<double>(config.seed, config.cases, res.self);
        if (config.progress) config.progress("self-intersection");
    }
    if (config.rendering) detail::rendering(config, res);
    if (config.textures) {
        res.texture = measure_texture_filters(200, 150, res.texture_note);
        if (config.progress) config.progress("texture filters");
    }
    res.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return res;
}

const Row* find(const AccuracyResults& r, const std::string& scenario, const std::string& method,
                const std::string& precision) {
    for (const Row& row : r.rows)
        if (row.scenario == scenario && row.method == method && row.precision == precision)
            return &row;
    return nullptr;
}

}  // namespace rt::bench
