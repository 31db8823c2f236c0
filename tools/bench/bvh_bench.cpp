#include "bench/bvh_bench.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <thread>

#include <sys/resource.h>

#include "accel/bvh_input.h"
#include "geometry/offset.h"
#include "geometry/procedural_mesh.h"
#include "scene/obj_loader.h"
#include "student/stage02.h"
#include "student/stage06.h"

namespace rt::bench {

// ---------------------------------------------------------------------------------------------
// Comparison and work splitting

const char* to_string(RayKind kind) {
    switch (kind) {
        case RayKind::Primary:
            return "primary";
        case RayKind::Shadow:
            return "shadow";
        case RayKind::Diffuse:
            return "diffuse";
    }
    return "?";
}

Disagreements compare_results(const std::vector<RayResult>& a, const std::vector<RayResult>& b,
                              bool any_hit, double t_tolerance) {
    if (a.size() != b.size()) throw std::logic_error("compare_results: sizes differ");
    Disagreements d;
    d.rays = a.size();
    for (std::size_t i = 0; i < a.size(); ++i) {
        const RayResult& x = a[i];
        const RayResult& y = b[i];
        if (x.hit() != y.hit()) {
            ++d.hit_miss;
        } else if (!x.hit() || any_hit) {
            continue;
        } else if (x.primitive != y.primitive) {
            ++d.primitive;
        } else {
            const double tx = double(x.t), ty = double(y.t);
            // Written so that a NaN t disagrees with everything.
            if (!(std::abs(tx - ty) <= t_tolerance * std::max(std::abs(tx), std::abs(ty)))) ++d.t;
        }
    }
    return d;
}

std::size_t allowed_disagreements(std::size_t rays, double max_fraction) {
    if (!(max_fraction > 0)) return 0;
    return std::size_t(std::floor(double(rays) * max_fraction));
}

void parallel_for_chunks(std::size_t n, std::size_t chunk, int threads,
                         const std::function<void(std::size_t, std::size_t)>& body) {
    if (chunk == 0) chunk = 1;
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (;;) {
            const std::size_t begin = next.fetch_add(chunk, std::memory_order_relaxed);
            if (begin >= n) return;
            body(begin, std::min(n, begin + chunk));
        }
    };
    std::vector<std::thread> helpers;
    for (int i = 1; i < threads; ++i) helpers.emplace_back(work);
    work();
    for (std::thread& t : helpers) t.join();
}

// ---------------------------------------------------------------------------------------------
// Back-ends

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

class BruteForceBackend final : public Backend {
  public:
    explicit BruteForceBackend(const Scene& scene) : scene_(scene) {}
    std::string name() const override { return "brute-force"; }
    double build() override { return -1; }
    void trace(const RayBatch& batch, std::size_t begin, std::size_t end,
               RayResult* results) const override {
        for (std::size_t i = begin; i < end; ++i) {
            Hit hit;
            RayResult r;
            if (intersect_nearest(batch.rays[i], scene_, batch.ranges[i], hit)) {
                r.t = batch.any_hit ? Real(0) : hit.t;
                r.primitive = batch.any_hit ? -1 : hit.primitive;
            }
            results[i] = r;
        }
    }

  private:
    const Scene& scene_;
};

class BvhBackend final : public Backend {
  public:
    explicit BvhBackend(Scene& scene) : scene_(scene) {}
    std::string name() const override { return "bvh"; }
    // Timed: bvh_primitives (the boxes, from the scene's arrays) and build_bvh.
    double build() override {
        const auto start = Clock::now();
        std::vector<BvhPrimitive> prims = bvh_primitives(scene_);
        Bvh bvh;
        build_bvh(std::move(prims), BvhBuildOptions{}, bvh);
        const double ms = ms_since(start);
        scene_.bvh = std::move(bvh);
        return ms;
    }
    void trace(const RayBatch& batch, std::size_t begin, std::size_t end,
               RayResult* results) const override {
        if (batch.any_hit) {
            for (std::size_t i = begin; i < end; ++i) {
                RayResult r;
                if (bvh_intersect_any(scene_, batch.rays[i], batch.ranges[i])) r.t = 0;
                results[i] = r;
            }
            return;
        }
        for (std::size_t i = begin; i < end; ++i) {
            Hit hit;
            RayResult r;
            if (bvh_intersect_nearest(scene_, batch.rays[i], batch.ranges[i], hit)) {
                r.t = hit.t;
                r.primitive = hit.primitive;
            }
            results[i] = r;
        }
    }

  private:
    Scene& scene_;
};

class FaultyBackend final : public Backend {
  public:
    FaultyBackend(std::unique_ptr<Backend> inner, std::size_t period)
        : inner_(std::move(inner)), period_(period == 0 ? 1 : period) {}
    std::string name() const override { return inner_->name(); }
    double build() override { return inner_->build(); }
    void trace(const RayBatch& batch, std::size_t begin, std::size_t end,
               RayResult* results) const override {
        inner_->trace(batch, begin, end, results);
        for (std::size_t i = begin; i < end; ++i) {
            if (i % period_ != 0 || !results[i].hit()) continue;
            if (batch.any_hit)
                results[i] = RayResult{};
            else
                results[i].primitive += 1;
        }
    }

  private:
    std::unique_ptr<Backend> inner_;
    std::size_t period_;
};

}  // namespace

std::unique_ptr<Backend> make_brute_force_backend(const Scene& scene) {
    return std::make_unique<BruteForceBackend>(scene);
}
std::unique_ptr<Backend> make_bvh_backend(Scene& scene) {
    return std::make_unique<BvhBackend>(scene);
}
std::unique_ptr<Backend> make_faulty_backend(std::unique_ptr<Backend> inner, std::size_t period) {
    return std::make_unique<FaultyBackend>(std::move(inner), period);
}

// ---------------------------------------------------------------------------------------------
// The mesh, the camera and the rays

namespace {

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...) {
    va_list args, again;
    va_start(args, fmt);
    va_copy(again, args);
    const int length = std::vsnprintf(nullptr, 0, fmt, args);
    va_end(args);
    std::string text(length > 0 ? std::size_t(length) : 0, '\0');
    if (length > 0) std::vsnprintf(text.data(), text.size() + 1, fmt, again);
    va_end(again);
    return text;
}

// 1234567 -> "1,234,567"
std::string grouped(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

}  // namespace

BenchMesh load_bench_mesh(const BvhBenchConfig& config) {
    BenchMesh m;
    Scene& s = m.scene;
    if (!config.mesh_file.empty()) {
        ObjMesh obj =
            load_obj(config.mesh_file, config.mesh_file, Vec3(1), Vec3(0), std::size_t(1) << 26);
        for (const std::string& warning : obj.warnings) std::fprintf(stderr, "rt-bench: warning: %s\n", warning.c_str());
        s.vertices = std::move(obj.vertices);
        s.triangles.reserve(obj.triangles.size());
        for (const auto& t : obj.triangles) s.triangles.push_back(Triangle{t, 0});
        m.description = config.mesh_file;
    } else {
        TriangleMesh mesh = make_procedural_mesh(config.procedural, config.triangles, config.seed);
        s.vertices = std::move(mesh.vertices);
        s.triangles.reserve(mesh.triangles.size());
        for (const auto& t : mesh.triangles) s.triangles.push_back(Triangle{t, 0});
        m.description =
            "procedural " + config.procedural + " (seed " + std::to_string(config.seed) + ")";
    }
    s.source = m.description;
    s.materials.push_back(Material{});
    s.update_features();
    return m;
}

namespace {

struct Framing {
    Camera camera;
    Vec3 light{0};
};

// A perspective camera looking at the mesh from the front, a little from the right and above,
// just far enough away that all eight corners of its bounding box are in the picture; and a point
// light above, right of and in front of the mesh, outside the box.
Framing frame_mesh(const Scene& scene, int width, int height) {
    Vec3 lo(kInfinity), hi(-kInfinity);
    for (const Vec3& p : scene.vertices) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const Vec3 centre = (lo + hi) * Real(0.5);
    Real radius = Real(0.5) * glm::length(hi - lo);
    if (!(radius > 0)) radius = 1;
    constexpr Real fov = 40;
    const Real tan_v = std::tan(glm::radians(fov / 2));
    const Real tan_h = tan_v * Real(width) / Real(height);
    // The frame first (it does not depend on the distance), then the distance each corner needs.
    const Vec3 view = glm::normalize(Vec3(0.3, 0.25, 1));
    const Camera frame =
        make_look_at_camera(Projection::Perspective, centre + view, centre, Vec3(0, 1, 0), fov, 2);
    Real distance = 0;
    for (int k = 0; k < 8; ++k) {
        const Vec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
        const Vec3 c = corner - centre;
        const Real depth = glm::dot(c, frame.w);  // towards the eye
        distance = std::max({distance, depth + std::abs(glm::dot(c, frame.u)) / tan_h,
                             depth + std::abs(glm::dot(c, frame.v)) / tan_v});
    }
    if (!(distance > 0)) distance = radius / tan_v;
    Framing f;
    f.camera = make_look_at_camera(Projection::Perspective, centre + Real(1.02) * distance * view,
                                   centre, Vec3(0, 1, 0), fov, 2);
    f.light = centre + radius * Vec3(1.5, 2.5, 2.0);
    return f;
}

// Embree intersects in float. So that every back-end traces the very same rays, and none of
// them starts within float rounding of its surface, a double build (RT_DOUBLE) rounds every ray
// to float and offsets secondary origins by the error bound of float arithmetic (twice the
// double bound scaled by the ratio of the unit roundoffs, so that the rounding to float cannot
// undo it). In a float build both are no-ops.
Vec3 as_float(const Vec3& v) {
    return Vec3(glm::vec3(v));
}
#ifdef RT_DOUBLE
constexpr Real kErrorScale =
    2 * Real(std::numeric_limits<float>::epsilon()) / std::numeric_limits<double>::epsilon();
#else
constexpr Real kErrorScale = 1;
#endif

// The primary ray through the centre of pixel (i, j), as docs/conventions.md#camera defines it
// (computed here so that the benchmark does not depend on stage 01).
Ray pixel_ray(const Camera& c, int i, int j, int width, int height) {
    const Real half_height = std::tan(glm::radians(c.vertical_fov_degrees) / 2);
    const Real half_width = half_height * Real(width) / Real(height);
    const Real x = (2 * (Real(i) + Real(0.5)) / Real(width) - 1) * half_width;
    const Real y = (1 - 2 * (Real(j) + Real(0.5)) / Real(height)) * half_height;
    return Ray{as_float(c.eye), as_float(glm::normalize(x * c.u + y * c.v - c.w))};
}

// SplitMix64: a counter-based generator, so ray i's random numbers depend on (seed, i) only.
std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}
Real uniform(std::uint64_t bits) {
    return Real(bits >> 40) * Real(1.0 / 16777216.0);
}  // [0, 1)

// A cosine-weighted direction about the unit vector n. The tangent frame is the branch-free
// construction of Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017).
Vec3 cosine_direction(const Vec3& n, Real u1, Real u2) {
    const Real sign = std::copysign(Real(1), n.z);
    const Real a = -1 / (sign + n.z);
    const Real b = n.x * n.y * a;
    const Vec3 t(1 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const Vec3 s(b, sign + n.y * n.y * a, -n.y);
    const Real r = std::sqrt(u1), phi = 2 * kPi * u2;
    const Real z = std::sqrt(std::max(Real(0), 1 - u1));
    return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * s + z * n);
}

// Primary rays, one per pixel centre; then, from each primary hit (found with the stage 06 BVH),
// one shadow ray to the light and one cosine-weighted diffuse ray, both starting at
// offset_ray_origin. Deterministic: the same for any thread count.
BenchRays make_rays(const Scene& scene, const Framing& framing, const BvhBenchConfig& config,
                    int threads) {
    BenchRays out;
    RayBatch& primary = out.batch[0];
    primary.kind = RayKind::Primary;
    const std::size_t n = std::size_t(config.width) * std::size_t(config.height);
    primary.rays.resize(n);
    primary.ranges.assign(n, Interval{0, kInfinity});
    for (int j = 0; j < config.height; ++j)
        for (int i = 0; i < config.width; ++i)
            primary.rays[std::size_t(j) * std::size_t(config.width) + std::size_t(i)] =
                pixel_ray(framing.camera, i, j, config.width, config.height);

    std::vector<Hit> hits(n);
    std::vector<char> found(n, 0);
    parallel_for_chunks(n, 1024, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            found[i] = bvh_intersect_nearest(scene, primary.rays[i], primary.ranges[i], hits[i]);
    });

    RayBatch& shadow = out.batch[1];
    RayBatch& diffuse = out.batch[2];
    shadow.kind = RayKind::Shadow;
    shadow.any_hit = true;
    diffuse.kind = RayKind::Diffuse;
    for (std::size_t i = 0; i < n; ++i) {
        if (!found[i]) continue;
        ++out.primary_hits;
        const SurfacePoint sp = surface_point(scene, primary.rays[i], hits[i]);

        const Vec3 error = sp.error * kErrorScale;

        const Vec3 l = as_float(glm::normalize(framing.light - sp.point));
        const Vec3 shadow_origin = as_float(offset_ray_origin(sp.point, error, sp.normal, l));
        shadow.rays.push_back(Ray{shadow_origin, l});
        shadow.ranges.push_back(Interval{0, glm::length(framing.light - shadow_origin)});

        const std::uint64_t key = mix(config.seed ^ mix(std::uint64_t(i)));
        const Vec3 d = as_float(cosine_direction(sp.normal, uniform(key), uniform(mix(key))));
        diffuse.rays.push_back(Ray{as_float(offset_ray_origin(sp.point, error, sp.normal, d)), d});
        diffuse.ranges.push_back(Interval{0, kInfinity});
    }
    return out;
}

// Rays floor(k n / m) for k < m: an evenly spread subset of at most m rays.
RayBatch subset(const RayBatch& batch, std::size_t m, std::vector<std::size_t>& indices) {
    RayBatch sub;
    sub.kind = batch.kind;
    sub.any_hit = batch.any_hit;
    const std::size_t n = batch.size();
    if (m > n) m = n;
    indices.resize(m);
    for (std::size_t k = 0; k < m; ++k) {
        indices[k] = std::size_t((unsigned long long)k * n / m);
        sub.rays.push_back(batch.rays[indices[k]]);
        sub.ranges.push_back(batch.ranges[indices[k]]);
    }
    return sub;
}

std::vector<RayResult> pick(const std::vector<RayResult>& all,
                            const std::vector<std::size_t>& indices) {
    std::vector<RayResult> out;
    out.reserve(indices.size());
    for (std::size_t i : indices) out.push_back(all[i]);
    return out;
}

constexpr std::size_t kChunk = 1024;  // rays per work item, the same for every back-end

std::vector<RayResult> trace_all(const Backend& backend, const RayBatch& batch, int threads) {
    std::vector<RayResult> results(batch.size());
    parallel_for_chunks(batch.size(), kChunk, threads, [&](std::size_t begin, std::size_t end) {
        backend.trace(batch, begin, end, results.data());
    });
    return results;
}

// CPU time (user + system) used by the whole process so far, in seconds.
double process_cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// One timed run: wall-clock seconds, and the share of `threads` cores the process got meanwhile
// (CPU time / (wall time x threads)): well below 1 means other work on the machine took cores.
struct Run {
    double seconds = 0;
    double cpu_share = 0;
};

Run time_trace(const Backend& backend, const RayBatch& batch, int threads,
               std::vector<RayResult>& results) {
    const double cpu_start = process_cpu_seconds();
    const auto start = Clock::now();
    parallel_for_chunks(batch.size(), kChunk, threads, [&](std::size_t begin, std::size_t end) {
        backend.trace(batch, begin, end, results.data());
    });
    Run run;
    run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    run.cpu_share = (process_cpu_seconds() - cpu_start) / (run.seconds * threads);
    return run;
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            const std::size_t colon = line.find(':');
            if (colon != std::string::npos) return line.substr(colon + 2);
        }
    return "unknown processor";
}

std::string load_average() {
    double load[3];
    if (getloadavg(load, 3) != 3) return "unknown";
    return format("%.2f %.2f %.2f", load[0], load[1], load[2]);
}

// What the BVH does per ray (BvhStats), in a separate untimed pass: where its time goes.
std::string bvh_traversal_summary(const Scene& scene, const BenchRays& rays, int threads) {
    std::string text = "\nbvh traversal per ray (untimed, BvhStats):";
    for (const RayBatch& batch : rays.batch) {
        std::atomic<std::uint64_t> nodes{0}, prims{0};
        parallel_for_chunks(batch.size(), 1024, threads, [&](std::size_t begin, std::size_t end) {
            BvhStats stats;
            for (std::size_t i = begin; i < end; ++i) {
                if (batch.any_hit) {
                    bvh_intersect_any(scene, batch.rays[i], batch.ranges[i], &stats);
                } else {
                    Hit hit;
                    bvh_intersect_nearest(scene, batch.rays[i], batch.ranges[i], hit, &stats);
                }
            }
            nodes += stats.nodes_visited;
            prims += stats.primitives_tested;
        });
        const double n = batch.size() > 0 ? double(batch.size()) : 1.0;
        text +=
            format("%s %s %.1f nodes, %.1f triangles", batch.kind == RayKind::Primary ? "" : ";",
                   to_string(batch.kind), double(nodes) / n, double(prims) / n);
    }
    const std::size_t depth = std::size_t(bvh_depth(scene.bvh));
    return text + format("\n  (%zu nodes, depth %zu)\n", scene.bvh.nodes.size(), depth);
}

// One timed cell of the table.
struct Timing {
    std::string backend;
    int threads = 1;
    std::string measure;  // "build" or a ray kind
    std::size_t rays = 0;
    double seconds = 0;  // best of the runs
    std::string note;
    double cpu_share = 0;  // of the best run (time_trace); 0 for builds
    double mrays() const { return seconds > 0 ? double(rays) / seconds / 1e6 : 0; }
};

}  // namespace

BenchRays make_bench_rays(const Scene& scene, const BvhBenchConfig& config, int threads) {
    return make_rays(scene, frame_mesh(scene, config.width, config.height), config, threads);
}

// ---------------------------------------------------------------------------------------------
// The benchmark

int run_bvh_bench(const BvhBenchConfig& config, std::ostream& out) {
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const int all_threads = config.threads > 0 ? config.threads : cores;
    std::vector<int> thread_counts{1};
    if (all_threads > 1) thread_counts.push_back(all_threads);
    const int repeat = std::max(1, config.repeat);

    BenchMesh mesh = load_bench_mesh(config);
    Scene& scene = mesh.scene;
    const std::size_t triangles = scene.triangles.size();
    out << "rt-bench bvh: stage 02 brute force, stage 06 BVH and Embree 3 on the same rays\n";
    out << "machine: " << cores << " cores (" << cpu_model() << "), load average " << load_average()
        << " at the start\n";
    out << "mesh: " << mesh.description << ", " << grouped(triangles) << " triangles, "
        << grouped(scene.vertices.size()) << " vertices\n";

    // The back-ends. The BVH is built once here (untimed) so that rays can be generated.
    std::unique_ptr<Backend> bvh = make_bvh_backend(scene);
    bvh->build();
    {
        const std::string problem = validate_bvh(scene.bvh, bvh_primitives(scene));
        if (!problem.empty())
            throw std::runtime_error("build_bvh gave an invalid tree: " + problem +
                                     " (stages/06-bvh/README.md)");
    }
    if (config.inject_error_period > 0)
        bvh = make_faulty_backend(std::move(bvh), config.inject_error_period);
    std::unique_ptr<Backend> brute = make_brute_force_backend(scene);
    const bool brute_timed = triangles <= config.brute_force_max_triangles;
    const std::size_t brute_rays = brute_timed
                                       ? config.brute_force_rays
                                       : std::min<std::size_t>(config.brute_force_rays, 1024);
    const bool have_embree = embree_built_in();
    std::vector<std::unique_ptr<Backend>> embree;  // one device per thread count
    if (have_embree)
        for (int t : thread_counts) embree.push_back(make_embree_backend(scene, t));
    Backend* embree_all = have_embree ? embree.back().get() : nullptr;
    if (embree_all) embree_all->build();

    const BenchRays rays = make_bench_rays(scene, config, all_threads);
    out << "rays: " << grouped(rays.batch[0].size()) << " primary (" << config.width << "x"
        << config.height << ", " << grouped(rays.primary_hits) << " hit the mesh), "
        << grouped(rays.batch[1].size()) << " shadow (any-hit, to a point light), "
        << grouped(rays.batch[2].size()) << " diffuse (cosine-weighted, seed " << config.seed
        << ")\n";

    // Correctness, before anything is timed.
    out << "\ncorrectness check (untimed): rays on which two back-ends disagree; allowed: "
        << format("%g%%", 100 * config.max_disagreement) << " of a kind's rays, t within "
        << format("%g", config.t_tolerance) << " relative\n";
    out << format("  %-24s %-8s %10s %9s %10s %7s %8s  %s\n", "pair", "rays", "compared",
                  "hit/miss", "primitive", "t", "total", "verdict");
    bool failed = false;
    std::string first_failure;
    auto report = [&](const std::string& pair, RayKind kind, const Disagreements& d) {
        const std::size_t allowed = allowed_disagreements(d.rays, config.max_disagreement);
        const bool ok = d.total() <= allowed;
        out << format("  %-24s %-8s %10zu %9zu %10zu %7zu %8zu  %s\n", pair.c_str(),
                      to_string(kind), d.rays, d.hit_miss, d.primitive, d.t, d.total(),
                      ok ? "ok" : "TOO MANY");
        if (!ok && !failed) {
            failed = true;
            first_failure = pair + " disagree on " + std::to_string(d.total()) + " of " +
                            std::to_string(d.rays) + " " + to_string(kind) + " rays (" +
                            format("%.4f%%", 100 * d.fraction()) + ", allowed " +
                            std::to_string(allowed) + ")";
        }
    };
    for (const RayBatch& batch : rays.batch) {
        const std::vector<RayResult> bvh_results = trace_all(*bvh, batch, all_threads);
        std::vector<RayResult> embree_results;
        if (embree_all) {
            embree_results = trace_all(*embree_all, batch, all_threads);
            report("bvh vs embree", batch.kind,
                   compare_results(bvh_results, embree_results, batch.any_hit, config.t_tolerance));
        }
        std::vector<std::size_t> indices;
        const RayBatch sub = subset(batch, brute_rays, indices);
        const std::vector<RayResult> brute_results = trace_all(*brute, sub, all_threads);
        report("brute-force vs bvh", batch.kind,
               compare_results(brute_results, pick(bvh_results, indices), batch.any_hit,
                               config.t_tolerance));
        if (embree_all)
            report("brute-force vs embree", batch.kind,
                   compare_results(brute_results, pick(embree_results, indices), batch.any_hit,
                                   config.t_tolerance));
    }
    if (!embree_all)
        out << "  (Embree was not built in: nothing to compare the BVH with but brute force)\n";
    if (!failed) out << bvh_traversal_summary(scene, rays, all_threads);
    if (failed) {
        out << "\nrt-bench: error: " << first_failure
            << "; a back-end computes wrong hits, so nothing was timed\n";
        out.flush();
        std::fprintf(stderr, "rt-bench: error: %s; nothing was timed\n", first_failure.c_str());
        return 2;
    }

    // Timing. Runs of the different back-ends alternate, so that a change in the machine's load
    // disturbs all of them alike; the fastest of `repeat` runs counts.
    std::vector<Timing> timings;
    for (std::size_t ti = 0; ti < thread_counts.size(); ++ti) {
        const int threads = thread_counts[ti];
        Timing bvh_build{"bvh", threads, "build", triangles, kInfinity, "builder: root's two subtrees on 2 threads"};
        Timing embree_build{"embree", threads, "build", triangles, kInfinity, ""};
        for (int r = 0; r < repeat; ++r) {
            bvh_build.seconds = std::min(bvh_build.seconds, bvh->build() / 1000);
            if (have_embree)
                embree_build.seconds = std::min(embree_build.seconds, embree[ti]->build() / 1000);
        }
        timings.push_back(bvh_build);
        if (have_embree) timings.push_back(embree_build);

        for (const RayBatch& batch : rays.batch) {
            std::vector<std::size_t> indices;
            const RayBatch sub = subset(batch, brute_rays, indices);
            struct Entry {
                Backend* backend;
                const RayBatch* rays;
                Timing timing;
            };
            std::vector<Entry> entries;
            if (brute_timed)
                entries.push_back(
                    {brute.get(),
                     &sub,
                     {"brute-force", threads, to_string(batch.kind), sub.size(), kInfinity,
                      sub.size() < batch.size() ? "on a subset of " + grouped(sub.size()) + " rays"
                                                : ""}});
            entries.push_back(
                {bvh.get(),
                 &batch,
                 {"bvh", threads, to_string(batch.kind), batch.size(), kInfinity, ""}});
            if (have_embree)
                entries.push_back(
                    {embree[ti].get(),
                     &batch,
                     {"embree", threads, to_string(batch.kind), batch.size(), kInfinity, ""}});
            std::vector<RayResult> results(batch.size());
            for (int r = 0; r < repeat; ++r)
                for (Entry& e : entries) {
                    const Run run = time_trace(*e.backend, *e.rays, threads, results);
                    if (run.seconds < e.timing.seconds) {
                        e.timing.seconds = run.seconds;
                        e.timing.cpu_share = run.cpu_share;
                    }
                }
            for (Entry& e : entries) timings.push_back(e.timing);
        }
    }

    auto find = [&](const std::string& backend, int threads,
                    const std::string& measure) -> const Timing* {
        for (const Timing& t : timings)
            if (t.backend == backend && t.threads == threads && t.measure == measure) return &t;
        return nullptr;
    };

    out << "\nthroughput in Mrays/s (single-ray queries, best of " << repeat
        << " runs); build: from the scene's arrays to a traversable structure, in ms\n";
    out << format("  %-12s %7s %10s %10s %10s %10s %9s\n", "back-end", "threads", "build ms",
                  "primary", "shadow", "diffuse", "cpu share");
    for (int threads : thread_counts) {
        for (const char* backend : {"brute-force", "bvh", "embree"}) {
            if (std::string(backend) == "embree" && !have_embree) continue;
            if (std::string(backend) == "brute-force" && !brute_timed) continue;
            std::string line = format("  %-12s %7d", backend, threads);
            const Timing* b = find(backend, threads, "build");
            line += b ? format(" %10.1f", b->seconds * 1000) : format(" %10s", "-");
            double share = kInfinity;
            for (RayKind kind : kRayKinds) {
                const Timing* t = find(backend, threads, to_string(kind));
                line += t ? format(" %10.3f", t->mrays()) : format(" %10s", "-");
                if (t) share = std::min(share, t->cpu_share);
            }
            line += share < kInfinity ? format(" %8.0f%%", 100 * share) : format(" %9s", "-");
            out << line << "\n";
        }
    }
    if (!brute_timed)
        out << "  brute-force: not timed, " << grouped(triangles) << " triangles > "
            << "--brute-force-max-triangles " << config.brute_force_max_triangles
            << " (checked for correctness on " << grouped(brute_rays) << " rays of each kind)\n";
    else if (const Timing* t = find("brute-force", 1, "primary"); t && !t->note.empty())
        out << "  brute-force: timed on at most " << grouped(brute_rays)
            << " rays of each kind (evenly spread; --brute-force-rays)\n";
    out << "  bvh build: bvh_primitives + build_bvh (the reference builder splits the root, then builds its two "
           "subtrees on two threads whatever --threads says)";
    if (have_embree)
        out << "; embree build: buffers + rtcCommitScene, default quality, on `threads` build "
               "threads";
    out << "\n  cpu share: CPU time the process got during the fastest run / (wall time x threads),"
           " lowest of the row; well below 100% means other work on the machine took cores\n";
    if (!have_embree)
        out << "  embree: not built in (install libembree-dev, scripts/install-deps.sh, and "
               "configure again): no ratios\n";

    if (have_embree) {
        out << "\n";
        for (int threads : thread_counts) {
            auto ratio = [&](const char* measure) {
                const Timing* a = find("bvh", threads, measure);
                const Timing* e = find("embree", threads, measure);
                return a && e && a->mrays() > 0 && e->mrays() > 0 ? a->mrays() / e->mrays() : 0.0;
            };
            const double build =
                find("bvh", threads, "build")->seconds / find("embree", threads, "build")->seconds;
            out << format(
                "ratios bvh/embree, %d thread%s: primary %.2fx, shadow %.2fx, diffuse "
                "%.2fx throughput; build time %.2fx Embree's\n",
                threads, threads == 1 ? "" : "s", ratio("primary"), ratio("shadow"),
                ratio("diffuse"), build);
            if (threads == all_threads) {
                auto verdict = [](bool met) { return met ? "met" : "NOT met"; };
                out << format(
                    "goals of issue 5 (set for the Stanford bunny, 1024x768, 2 threads), "
                    "at %d thread%s: primary >= 0.5x %s, diffuse >= 0.4x %s, build <= 2x %s\n",
                    threads, threads == 1 ? "" : "s", verdict(ratio("primary") >= 0.5),
                    verdict(ratio("diffuse") >= 0.4), verdict(build <= 2.0));
            }
        }
    }
    out << "load average " << load_average() << " at the end\n";

    if (!config.csv.empty()) {
        std::string csv =
            "mesh,triangles,backend,threads,measure,rays,best_seconds,mrays_per_s,cpu_share,repeat,"
            "note\n";
        for (const Timing& t : timings) {
            const bool build = t.measure == "build";
            csv += format("\"%s\",%zu,%s,%d,%s,%zu,%.6f,%s,%s,%d,\"%s\"\n",
                          mesh.description.c_str(), triangles, t.backend.c_str(), t.threads,
                          t.measure.c_str(), build ? std::size_t(0) : t.rays, t.seconds,
                          build ? "" : format("%.4f", t.mrays()).c_str(),
                          build ? "" : format("%.3f", t.cpu_share).c_str(), repeat, t.note.c_str());
        }
        if (config.csv == "-") {
            out << "\n" << csv;
        } else {
            std::ofstream file(config.csv);
            if (!file) throw std::runtime_error("cannot write " + config.csv);
            file << csv;
            out << "CSV written to " << config.csv << "\n";
        }
    }
    return 0;
}

}  // namespace rt::bench
