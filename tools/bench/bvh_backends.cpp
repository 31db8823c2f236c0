// The BVH benchmark's back-ends (brute force, the students' BVH, the tuned BVH, a faulty wrapper
// for the tests), how their answers are compared, and the chunked parallel loop every back-end is
// run with.
#include "bench/bvh_bench.h"
#include "bench/tuned_bvh.h"

#include <atomic>
#include <chrono>
#include <thread>

#include "core/parallel_for.h"
#include "scene/bvh_primitives.h"
#include "stage_api/stage02.h"
#include "stage_api/stage06.h"

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
    parallel_for((n + chunk - 1) / chunk, threads,
                 [&](std::size_t c) { body(c * chunk, std::min(n, (c + 1) * chunk)); });
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
    explicit BruteForceBackend(const PreparedScene& scene) : scene_(scene) {}
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
    const PreparedScene& scene_;
};

class BvhBackend final : public Backend {
  public:
    explicit BvhBackend(PreparedScene& scene) : scene_(scene) {}
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
    PreparedScene& scene_;
};

// The former reference's tricks (tuned_bvh.h), on a tree of its own over the same scene.
class TunedBvhBackend final : public Backend {
  public:
    explicit TunedBvhBackend(const PreparedScene& scene) : scene_(scene) {}
    std::string name() const override { return "bvh-tuned"; }
    double build() override {
        const auto start = Clock::now();
        std::vector<BvhPrimitive> prims = bvh_primitives(scene_);
        Bvh bvh;
        tuned::build(std::move(prims), BvhBuildOptions{}, bvh);
        const double ms = ms_since(start);
        bvh_ = std::move(bvh);
        return ms;
    }
    void trace(const RayBatch& batch, std::size_t begin, std::size_t end,
               RayResult* results) const override {
        for (std::size_t i = begin; i < end; ++i) {
            Hit hit;
            RayResult r;
            if (batch.any_hit && tuned::any(scene_, bvh_, batch.rays[i], batch.ranges[i])) r.t = 0;
            if (!batch.any_hit &&
                tuned::nearest(scene_, bvh_, batch.rays[i], batch.ranges[i], hit)) {
                r.t = hit.t;
                r.primitive = hit.primitive;
            }
            results[i] = r;
        }
    }

  private:
    const PreparedScene& scene_;
    Bvh bvh_;
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

std::unique_ptr<Backend> make_brute_force_backend(const PreparedScene& scene) {
    return std::make_unique<BruteForceBackend>(scene);
}
std::unique_ptr<Backend> make_bvh_backend(PreparedScene& scene) {
    return std::make_unique<BvhBackend>(scene);
}
std::unique_ptr<Backend> make_tuned_bvh_backend(const PreparedScene& scene) {
    return std::make_unique<TunedBvhBackend>(scene);
}
std::unique_ptr<Backend> make_faulty_backend(std::unique_ptr<Backend> inner, std::size_t period) {
    return std::make_unique<FaultyBackend>(std::move(inner), period);
}

}  // namespace rt::bench
