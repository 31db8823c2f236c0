// `rt-bench` / `rt-bench bvh` (issue 5): build time and ray throughput of stage 02's brute-force
// loop, the stage 06 BVH and Embree 3, on the very same rays, with the hits checked equal across
// back-ends before any timing counts. Unlike the accuracy lab, this links student code
// (rt_stages): it measures the students' BVH.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "scene/prepared_scene.h"

namespace rt::bench {

// ---------------------------------------------------------------------------------------------
// Rays and what a back-end reports for each.

enum class RayKind { Primary, Shadow, Diffuse };
inline constexpr RayKind kRayKinds[] = {RayKind::Primary, RayKind::Shadow, RayKind::Diffuse};
const char* to_string(RayKind kind);

// One kind of rays, generated once before timing; every back-end traces these arrays.
struct RayBatch {
    RayKind kind = RayKind::Primary;
    bool any_hit = false;  // shadow rays: occlusion only, the first hit found ends the query
    std::vector<Ray> rays;
    std::vector<Interval> ranges;  // open t-range of each ray
    std::size_t size() const { return rays.size(); }
};

// The answer for one ray. Nearest-hit queries: t and primitive of the nearest hit, or
// (inf, -1) on a miss. Any-hit queries: t = 0 and primitive = -1 when occluded, (inf, -1) if not.
struct RayResult {
    Real t = kInfinity;
    std::int32_t primitive = -1;
    bool hit() const { return t != kInfinity; }
};

// How two back-ends' answers to the same rays differ. Each ray counts in at most one column:
// one hit and the other missed; else both hit but different primitives; else the same
// primitive at t values further apart than the relative tolerance.
struct Disagreements {
    std::size_t rays = 0;
    std::size_t hit_miss = 0;
    std::size_t primitive = 0;
    std::size_t t = 0;
    std::size_t total() const { return hit_miss + primitive + t; }
    double fraction() const { return rays == 0 ? 0.0 : double(total()) / double(rays); }
};

// Compares a[i] with b[i] for every i (the vectors must have the same size). For any-hit rays
// only hit/miss is compared. |ta - tb| <= t_tolerance * max(|ta|, |tb|) counts as equal.
Disagreements compare_results(const std::vector<RayResult>& a, const std::vector<RayResult>& b,
                              bool any_hit, double t_tolerance);

// The largest number of disagreements accepted among `rays` rays when at most `max_fraction`
// of them may disagree (rounded down: below 1/max_fraction rays, none may).
std::size_t allowed_disagreements(std::size_t rays, double max_fraction);

// ---------------------------------------------------------------------------------------------
// Back-ends.

class Backend {
  public:
    virtual ~Backend() = default;
    virtual std::string name() const = 0;
    // Builds the acceleration structure from the scene's arrays and returns the milliseconds
    // taken; a back-end without one (brute force) returns a negative number. May be called
    // repeatedly; the structure of the last call is the one traced.
    virtual double build() = 0;
    // Traces rays [begin, end) of `batch`, writing results[begin, end). Called concurrently by
    // several threads on disjoint ranges.
    virtual void trace(const RayBatch& batch, std::size_t begin, std::size_t end,
                       RayResult* results) const = 0;
};

// Stage 02's intersect_nearest over every primitive (any-hit rays use it too: stage 02 has no
// early exit).
std::unique_ptr<Backend> make_brute_force_backend(const PreparedScene& scene);
// Stage 06: bvh_primitives + build_bvh into scene.bvh, then bvh_intersect_nearest /
// bvh_intersect_any.
std::unique_ptr<Backend> make_bvh_backend(PreparedScene& scene);
// The former reference's speed tricks on the same tree (tuned_bvh.h): its own build and
// traversal, the scene's planes and primitives.
std::unique_ptr<Backend> make_tuned_bvh_backend(const PreparedScene& scene);
// A back-end that answers like `inner` except on every `period`-th ray that `inner` reports a
// hit for, where it names another primitive (nearest-hit) or reports a miss (any-hit). For the
// test that proves the correctness check catches a wrong back-end.
std::unique_ptr<Backend> make_faulty_backend(std::unique_ptr<Backend> inner, std::size_t period);

// Whether Embree 3 was found when the project was configured (RT_HAVE_EMBREE).
bool embree_built_in();
// One RTC_GEOMETRY_TYPE_TRIANGLE geometry from scene.vertices and scene.triangles, default
// build quality, on a device limited to `threads` build threads; rtcIntersect1 / rtcOccluded1
// one ray at a time. Throws std::runtime_error when Embree is not built in or reports an error.
std::unique_ptr<Backend> make_embree_backend(const PreparedScene& scene, int threads);

// Runs body(begin, end) over [0, n) in chunks of `chunk` items, handed out in order to
// `threads` threads (the calling thread is one of them) as each finishes its previous chunk.
void parallel_for_chunks(std::size_t n, std::size_t chunk, int threads,
                         const std::function<void(std::size_t, std::size_t)>& body);

// ---------------------------------------------------------------------------------------------
// The benchmark.

struct BvhBenchConfig {
    std::string mesh_file;             // an OBJ file; empty: the procedural mesh below
    std::string procedural = "torus";  // make_procedural_mesh shape
    std::size_t triangles = 100000;    // at least this many triangles (procedural only)
    std::uint64_t seed = 1;            // procedural mesh and diffuse directions
    int threads = 0;                   // 0: every core; 1 thread is always measured too
    int width = 1024, height = 768;    // primary rays: one per pixel centre
    int repeat = 3;                    // timed runs per measurement; the best (fastest) counts
    // Brute force traces an evenly spread subset of at most `brute_force_rays` rays of each kind,
    // timed when the mesh has at most `brute_force_max_triangles` triangles; above that it is
    // only checked for correctness, on at most 1024 rays of each kind, and not timed.
    std::size_t brute_force_max_triangles = 5000;
    std::size_t brute_force_rays = 16384;
    double max_disagreement = 1e-4;       // fraction of rays per pair and kind before failing
    double t_tolerance = 1e-4;            // relative tolerance on t
    std::string csv;                      // write CSV here ("-": standard output)
    std::size_t inject_error_period = 0;  // > 0: the BVH answers wrongly on some rays (tests)
};

// The mesh of the benchmark as a scene of triangles only (one default material): the OBJ file
// config.mesh_file, or else config.procedural with at least config.triangles triangles.
struct BenchMesh {
    PreparedScene scene;      // prepared without a BVH: each back-end builds its own
    std::string description;  // for the report
};
BenchMesh load_bench_mesh(const BvhBenchConfig& config);

// The rays of the benchmark, the same for any thread count: config.width x config.height
// primary rays from a camera framing the mesh's bounding box; from each primary hit (found with
// the stage 06 BVH, so scene.bvh must be built) one shadow ray to a point light outside the box
// and one cosine-weighted diffuse ray (seeded by config.seed and the pixel), both starting at
// offset_ray_origin (framework/geometry/offset.h).
struct BenchRays {
    RayBatch batch[3];  // in the order of kRayKinds
    std::size_t primary_hits = 0;
};
BenchRays make_bench_rays(const PreparedScene& scene, const BvhBenchConfig& config, int threads);

// Runs the benchmark, printing the report on `out`. Returns the process exit code: 0, or 2 when
// the back-ends disagree on more rays than allowed (nothing is then timed). Throws
// std::runtime_error for unusable input (a mesh that cannot be loaded, an invalid tree).
int run_bvh_bench(const BvhBenchConfig& config, std::ostream& out);

}  // namespace rt::bench
