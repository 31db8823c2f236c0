// The timed half of the accuracy lab: every method classified against the exact answers and
// timed, and the renders. No CGAL here (see cases.h).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

#include "bench/cases.h"
#include "camera/camera.h"
#include "core/parallel_for.h"
#include "core/source_dir.h"
#include "scene/scene_loader.h"

namespace rt::bench::detail {
namespace {

using Clock = std::chrono::steady_clock;

// ---------------------------------------------------------------------------------------------
// Classification.

double median(std::vector<double>& v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

void finish_ulps(Counts& c, std::vector<double>& ulps) {
    c.t_samples = long(ulps.size());
    c.median_ulps = median(ulps);
    c.max_ulps = ulps.empty() ? 0 : ulps.back();
}

template <typename T>
using TriFn = Result<T> (*)(const V3<T>&, const V3<T>&, const V3<T>&, const V3<T>&, const V3<T>&, T,
                            T);
template <typename T>
using SphFn = Result<T> (*)(const V3<T>&, const V3<T>&, const V3<T>&, T, T, T);

// A method of methods.h under the name the report gives it.
template <typename Fn>
struct Method {
    const char* name;
    Fn fn;
};
template <typename T>
std::array<Method<TriFn<T>>, 5> tri_methods() {
    return {{{"Cramer", &cramer<T>},
             {"Moeller-Trumbore", &moller_trumbore<T>},
             {"plane + same side (Leeds)", &plane_same_side<T>},
             {"watertight", &watertight<T>},
             {"watertight FMA", &watertight<T, true>}}};
}
template <typename T>
std::array<Method<SphFn<T>>, 4> sphere_methods() {
    return {{{"textbook", &sphere_textbook<T>},
             {"geometric (Arizona)", &sphere_geometric<T>},
             {"q-form", &sphere_qform<T>},
             {"RTG ch. 7", &sphere_rtg<T>}}};
}

// The best of 5 rounds of at least 8 ms each: the minimum is the least disturbed by other load.
template <typename F>
double time_ns_per_test(long tests_per_pass, F&& pass) {
    double best = std::numeric_limits<double>::infinity();
    for (int round = 0; round < 5; ++round) {
        long passes = 0;
        const auto start = Clock::now();
        double elapsed = 0;
        do {
            pass();
            ++passes;
            elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        } while (elapsed < 0.008);
        best = std::min(best, elapsed * 1e9 / double(passes * tests_per_pass));
    }
    return best;
}

volatile double g_sink = 0;  // keeps timed loops from being optimised away

template <typename T>
void triangle_rows_t(const Scenario& s, const TriTruthSet& truth, bool timing,
                     std::vector<Row>& out) {
    const T inf = std::numeric_limits<T>::infinity();
    // Inputs converted once, outside the timed loops.
    struct TC {
        V3<T> o, d, a, b, c;
    };
    std::vector<TC> singles;
    for (const auto& c : s.tris)
        singles.push_back({V3<T>(c.o), V3<T>(c.d), V3<T>(c.a), V3<T>(c.b), V3<T>(c.c)});
    std::vector<std::vector<V3<T>>> mesh_v;
    for (const auto& m : s.meshes) {
        std::vector<V3<T>> v;
        for (const auto& p : m.v) v.push_back(V3<T>(p));
        mesh_v.push_back(std::move(v));
    }
    for (const auto& method : tri_methods<T>()) {
        Row row{"triangle",
                s.info.key,
                s.info.mesh,
                method.name,
                std::is_same_v<T, float> ? "float" : "double",
                {},
                0};
        Counts& c = row.counts;
        std::vector<double> ulps;
        for (std::size_t i = 0; i < singles.size(); ++i) {
            const TC& k = singles[i];
            const Result<T> r = method.fn(k.o, k.d, k.a, k.b, k.c, T(0), inf);
            const PairTruth& e = truth.single[i];
            if (r.hit && !e.hit) c.false_hit++;
            if (!r.hit && e.hit) c.false_miss++;
            if (r.hit && e.hit) ulps.push_back(e.t.ulps(r.t));
        }
        for (std::size_t i = 0; i < s.rays.size(); ++i) {
            const MeshCase& ray = s.rays[i];
            const auto& m = s.meshes[ray.mesh];
            const auto& v = mesh_v[ray.mesh];
            const V3<T> o(ray.o), d(ray.d);
            std::vector<char> reported(m.tri.size());
            for (std::size_t f = 0; f < m.tri.size(); ++f) {
                const Result<T> r =
                    method.fn(o, d, v[m.tri[f][0]], v[m.tri[f][1]], v[m.tri[f][2]], T(0), inf);
                reported[f] = r.hit;
                if (r.hit && truth.mesh[i][f].hit) ulps.push_back(truth.mesh[i][f].t.ulps(r.t));
            }
            const MeshVerdict verdict = judge_mesh(truth.mesh[i], reported);
            c.false_miss += verdict.false_miss;
            c.false_hit += verdict.false_hit;
            c.leak += verdict.leak;
            c.double_hit += verdict.double_hit;
        }
        c.cases = long(singles.size() + s.rays.size());
        c.tests = truth.tests;
        finish_ulps(c, ulps);
        if (timing) {
            row.ns_per_test = time_ns_per_test(c.tests, [&] {
                T acc = 0;
                for (const TC& k : singles) acc += method.fn(k.o, k.d, k.a, k.b, k.c, T(0), inf).t;
                for (const MeshCase& ray : s.rays) {
                    const auto& m = s.meshes[ray.mesh];
                    const auto& v = mesh_v[ray.mesh];
                    const V3<T> o(ray.o), d(ray.d);
                    for (const auto& f : m.tri)
                        acc += method.fn(o, d, v[f[0]], v[f[1]], v[f[2]], T(0), inf).t;
                }
                g_sink = g_sink + double(acc);
            });
        }
        out.push_back(row);
    }
}

template <typename T>
void sphere_rows_t(const Scenario& s, const std::vector<SphereTruthLite>& truth, bool timing,
                   std::vector<Row>& out) {
    const T inf = std::numeric_limits<T>::infinity();
    struct SC {
        V3<T> o, d, c;
        T r;
    };
    std::vector<SC> cases;
    for (const auto& c : s.spheres)
        cases.push_back({V3<T>(c.o), V3<T>(c.d), V3<T>(c.center), T(c.radius)});
    for (const auto& method : sphere_methods<T>()) {
        Row row{
            "sphere", s.info.key, false, method.name, std::is_same_v<T, float> ? "float" : "double",
            {},       0};
        Counts& c = row.counts;
        std::vector<double> ulps;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const SC& k = cases[i];
            const Result<T> r = method.fn(k.o, k.d, k.c, k.r, T(0), inf);
            if (r.hit && !truth[i].hit) c.false_hit++;
            if (!r.hit && truth[i].hit) c.false_miss++;
            if (r.hit && truth[i].hit) ulps.push_back(truth[i].t.ulps(r.t));
        }
        c.cases = c.tests = long(cases.size());
        finish_ulps(c, ulps);
        if (timing)
            row.ns_per_test = time_ns_per_test(c.tests, [&] {
                T acc = 0;
                for (const SC& k : cases) acc += method.fn(k.o, k.d, k.c, k.r, T(0), inf).t;
                g_sink = g_sink + double(acc);
            });
        out.push_back(row);
    }
}
// ---------------------------------------------------------------------------------------------
// Rendering the stage 02 scenes with the bench's methods, in normals mode.

template <typename T>
struct SceneT {
    struct S {
        V3<T> c;
        T r;
    };
    struct P {
        V3<T> p, n;
    };
    struct Bx {
        V3<T> lo, hi;
    };
    struct Tr {
        V3<T> a, b, c;
    };
    std::vector<S> spheres;
    std::vector<P> planes;
    std::vector<Bx> boxes;
    std::vector<Tr> tris;
    Camera cam;
    int width = 0, height = 0;
};

template <typename T>
SceneT<T> convert(const Scene& scene, int divisor) {
    SceneT<T> s;
    for (const auto& x : scene.spheres) s.spheres.push_back({V3<T>(x.center), T(x.radius)});
    for (const auto& x : scene.planes) s.planes.push_back({V3<T>(x.point), V3<T>(x.normal)});
    for (const auto& x : scene.boxes) s.boxes.push_back({V3<T>(x.min), V3<T>(x.max)});
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        Vec3 a, b, c;
        scene.triangle_vertices(i, a, b, c);
        s.tris.push_back({V3<T>(a), V3<T>(b), V3<T>(c)});
    }
    s.cam = scene.camera;
    s.width = std::max(1, scene.image.width / divisor);
    s.height = std::max(1, scene.image.height / divisor);
    return s;
}

// The conventions' camera rays (docs/conventions.md#camera), on T.
template <typename T>
void camera_ray_t(const SceneT<T>& s, T px, T py, V3<T>& o, V3<T>& d) {
    const Camera& cam = s.cam;
    const V3<T> u(cam.u), v(cam.v), w(cam.w), eye(cam.eye);
    const T aspect = T(s.width) / T(s.height);
    const T sx = 2 * px / T(s.width) - 1, sy = 1 - 2 * py / T(s.height);
    if (cam.projection == Projection::Perspective) {
        const T hh = std::tan(T(cam.vertical_fov_degrees) * T(kPi) / 180 / 2);
        o = eye;
        d = glm::normalize(sx * hh * aspect * u + sy * hh * v - w);
    } else {
        const T hh = T(cam.view_height) / 2;
        o = eye + sx * hh * aspect * u + sy * hh * v;
        d = -w;
    }
}

// The displayed normal (0.5 (n + 1), facing the ray) of the nearest hit, black on a miss.
template <typename T>
glm::vec3 shade(const SceneT<T>& s, const V3<T>& o, const V3<T>& d, TriFn<T> tri) {
    T tmax = std::numeric_limits<T>::infinity();
    V3<T> n(0);
    bool found = false;
    for (const auto& x : s.spheres) {
        const Result<T> r = sphere_rtg<T>(o, d, x.c, x.r, T(0), tmax);
        if (r.hit) {
            tmax = r.t;
            n = (o + r.t * d - x.c) / x.r;
            found = true;
        }
    }
    for (const auto& x : s.planes) {
        const T den = glm::dot(x.n, d);
        if (den == 0) continue;
        const T t = glm::dot(x.n, x.p - o) / den;
        if (T(0) < t && t < tmax) {
            tmax = t;
            n = x.n;
            found = true;
        }
    }
    for (const auto& x : s.tris) {
        const Result<T> r = tri(o, d, x.a, x.b, x.c, T(0), tmax);
        if (r.hit) {
            tmax = r.t;
            n = glm::normalize(glm::cross(x.b - x.a, x.c - x.a));
            found = true;
        }
    }
    for (const auto& x : s.boxes) {
        T t0 = 0, t1 = tmax;
        int axis = -1;
        bool miss = false;
        for (int i = 0; i < 3 && !miss; ++i) {
            if (d[i] == 0) {
                miss = o[i] < x.lo[i] || o[i] > x.hi[i];
                continue;
            }
            T a = (x.lo[i] - o[i]) / d[i], b = (x.hi[i] - o[i]) / d[i];
            if (a > b) std::swap(a, b);
            if (a > t0) {
                t0 = a;
                axis = i;
            }
            if (b < t1) t1 = b;
            miss = t0 > t1;
        }
        if (miss || axis < 0 || !(t0 < tmax)) continue;
        tmax = t0;
        n = V3<T>(0);
        n[axis] = 1;
        found = true;
    }
    if (!found) return glm::vec3(0);
    if (glm::dot(n, d) > 0) n = -n;
    return glm::vec3(0.5f) * (glm::vec3(n) + 1.0f);
}

using Pixels = std::vector<glm::vec3>;

// n x n regular samples per pixel (n = 1: the pixel centre). Rows shared by `threads`.
template <typename T>
Pixels render_t(const SceneT<T>& s, int n, TriFn<T> tri, int threads) {
    Pixels px(std::size_t(s.width) * s.height);
    parallel_for(std::size_t(s.height), threads, [&](std::size_t row) {
        const int y = int(row);
        for (int x = 0; x < s.width; ++x) {
            glm::vec3 sum(0);
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    V3<T> o, d;
                    camera_ray_t<T>(s, T(x) + (T(i) + T(0.5)) / T(n), T(y) + (T(j) + T(0.5)) / T(n),
                                    o, d);
                    sum += shade<T>(s, o, d, tri);
                }
            px[std::size_t(y) * s.width + x] = sum / float(n * n);
        }
    });
    return px;
}

double rmse8(const Pixels& a, const Pixels& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int k = 0; k < 3; ++k) sum += std::pow(255.0 * (a[i][k] - b[i][k]), 2);
    return std::sqrt(sum / double(3 * a.size()));
}
double percent_off(const Pixels& a, const Pixels& b) {
    long off = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int k = 0; k < 3; ++k)
            if (std::abs(std::lround(255.0 * a[i][k]) - std::lround(255.0 * b[i][k])) > 2) {
                ++off;
                break;
            }
    return 100.0 * double(off) / double(a.size());
}

template <typename F>
double time_ms(F&& f) {
    const auto start = Clock::now();
    f();
    return std::chrono::duration<double>(Clock::now() - start).count() * 1e3;
}

}  // namespace

// Crossings are told apart by the exact sign of n.d: for a convex mesh and an outside origin, the
// ray enters through front faces and leaves through back faces.
MeshVerdict judge_mesh(const std::vector<PairTruth>& truth, const std::vector<char>& reported) {
    MeshVerdict v;
    for (int side : {-1, 1}) {
        int exact_count = 0, reported_count = 0;
        bool on_edge = false;
        for (std::size_t i = 0; i < truth.size(); ++i) {
            if (truth[i].facing != side) continue;
            if (truth[i].hit) {
                exact_count++;
                on_edge = on_edge || truth[i].region > 0;
            }
            if (reported[i]) reported_count++;
        }
        if (exact_count > 1) on_edge = true;
        if (exact_count > 0 && reported_count == 0) (on_edge ? v.leak : v.false_miss) = true;
        if (exact_count == 0 && reported_count > 0) v.false_hit = true;
        if (reported_count > 1) v.double_hit = true;
    }
    for (std::size_t i = 0; i < truth.size(); ++i)
        if (truth[i].facing == 0 && reported[i]) v.false_hit = true;  // parallel: never a hit
    return v;
}

void triangle_rows(const Scenario& s, const TriTruthSet& truth, bool timing,
                   std::vector<Row>& out) {
    triangle_rows_t<float>(s, truth, timing, out);
    triangle_rows_t<double>(s, truth, timing, out);
}

void sphere_rows(const Scenario& s, const std::vector<SphereTruthLite>& truth, bool timing,
                 std::vector<Row>& out) {
    sphere_rows_t<float>(s, truth, timing, out);
    sphere_rows_t<double>(s, truth, timing, out);
}

void rendering(const AccuracyConfig& cfg, AccuracyResults& res) {
    const std::vector<std::string> files = {"spheres_normals",     "triangles_normals",
                                            "mesh_normals",        "plane_depth",
                                            "boxes_primitive_ids", "orthographic_mixed"};
    struct Series {
        std::string name;
        int n;
        bool is_double;
        bool watertight;
    };
    const std::vector<Series> series = {
        {"Cramer float", 1, false, false},    {"Cramer double", 1, true, false},
        {"watertight float", 1, false, true}, {"watertight double", 1, true, true},
        {"supersampling", 2, false, true},    {"supersampling", 4, false, true},
        {"supersampling", 8, false, true}};
    std::vector<RenderPoint> points(series.size());
    for (std::size_t k = 0; k < series.size(); ++k)
        points[k] = {series[k].name, series[k].n * series[k].n, 0, 0, 0};
    for (const std::string& name : files) {
        const Scene scene = load_scene(rt::source_dir().string() +
                                       "/stages/02-intersections/scenes/" + name + ".json");
        const SceneT<float> sf = convert<float>(scene, cfg.render_divisor);
        const SceneT<double> sd = convert<double>(scene, cfg.render_divisor);
        res.render_scenes.push_back(name);
        res.render_width_sum += sf.width;
        res.render_height_sum += sf.height;
        const Pixels reference = render_t<double>(sd, 16, &watertight<double>, 2);
        const Pixels center = render_t<double>(sd, 1, &watertight<double>, 2);
        for (std::size_t k = 0; k < series.size(); ++k) {
            const Series& s = series[k];
            Pixels img;
            double ms = std::numeric_limits<double>::infinity();
            for (int round = 0; round < (s.n == 1 ? 3 : 1); ++round)  // cheap ones: best of 3
                ms = std::min(
                    ms, time_ms([&] {
                        img = s.is_double
                                  ? render_t<double>(
                                        sd, s.n,
                                        s.watertight ? &watertight<double> : &cramer<double>, 1)
                                  : render_t<float>(
                                        sf, s.n, s.watertight ? &watertight<float> : &cramer<float>,
                                        1);
                    }));
            points[k].ms += ms;
            points[k].rmse += rmse8(img, reference) / double(files.size());
            points[k].center_diff += percent_off(img, center) / double(files.size());
        }
        if (cfg.progress) cfg.progress("rendered " + name);
    }
    // The 1-sample point of the supersampling curve is the watertight float point.
    RenderPoint one = points[2];
    one.series = "supersampling";
    points.insert(points.begin() + 4, one);
    res.render = points;
}
}  // namespace rt::bench::detail
