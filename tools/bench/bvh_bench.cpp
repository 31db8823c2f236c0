// The BVH benchmark run (rt-bench bvh): the correctness check across back-ends, the timed runs,
// and the report (throughput table, ratios to Embree, CSV).
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

#include <sys/resource.h>

#include "bench/machine.h"
#include "core/parallel_for.h"
#include "scene/bvh_primitives.h"
#include "stage_api/stage02.h"
#include "stage_api/stage06.h"

namespace rt::bench {

namespace {

using Clock = std::chrono::steady_clock;

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

std::string load_average() {
    double load[3];
    if (getloadavg(load, 3) != 3) return "unknown";
    return format("%.2f %.2f %.2f", load[0], load[1], load[2]);
}

// What the BVH does per ray (BvhStats), in a separate untimed pass: where its time goes.
std::string bvh_traversal_summary(const PreparedScene& scene, const BenchRays& rays, int threads) {
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

// ---------------------------------------------------------------------------------------------
// The benchmark

namespace {

// One run of the benchmark: its mesh, back-ends and rays, then the correctness check, the timed
// runs and the report, in that order (run_bvh_bench).
class BvhBench {
  public:
    BvhBench(const BvhBenchConfig& config, std::ostream& out)
        : config_(config),
          out_(out),
          cores_(default_thread_count()),
          all_threads_(config.threads > 0 ? config.threads : cores_),
          repeat_(std::max(1, config.repeat)),
          mesh_(load_bench_mesh(config)),
          triangles_(mesh_.scene.triangles.size()) {
        thread_counts_.push_back(1);
        if (all_threads_ > 1) thread_counts_.push_back(all_threads_);
    }

    // The back-ends. The BVH is built once here (untimed) so that rays can be generated.
    void set_up() {
        PreparedScene& scene = mesh_.scene;
        out_ << "rt-bench bvh: stage 02 brute force, stage 06 BVH (the reference, plain, and the "
                "tuned back-end) and Embree 3 on the same rays\n";
        out_ << "machine: " << cores_ << " cores (" << cpu_model("unknown processor")
             << "), load average " << load_average() << " at the start\n";
        out_ << "mesh: " << mesh_.description << ", " << grouped(triangles_) << " triangles, "
             << grouped(scene.vertices.size()) << " vertices\n";
        bvh_ = make_bvh_backend(scene);
        bvh_->build();
        const std::string problem = validate_bvh(scene.bvh, bvh_primitives(scene));
        if (!problem.empty())
            throw std::runtime_error("build_bvh gave an invalid tree: " + problem +
                                     " (stages/06-bvh/README.md)");
        if (config_.inject_error_period > 0)
            bvh_ = make_faulty_backend(std::move(bvh_), config_.inject_error_period);
        tuned_ = make_tuned_bvh_backend(scene);
        tuned_->build();
        brute_ = make_brute_force_backend(scene);
        brute_timed_ = triangles_ <= config_.brute_force_max_triangles;
        brute_rays_ = brute_timed_ ? config_.brute_force_rays
                                   : std::min<std::size_t>(config_.brute_force_rays, 1024);
        have_embree_ = embree_built_in();
        if (have_embree_)
            for (int t : thread_counts_) embree_.push_back(make_embree_backend(scene, t));
        if (have_embree_) embree_.back()->build();
        rays_ = make_bench_rays(scene, config_, all_threads_);
        out_ << "rays: " << grouped(rays_.batch[0].size()) << " primary (" << config_.width << "x"
             << config_.height << ", " << grouped(rays_.primary_hits) << " hit the mesh), "
             << grouped(rays_.batch[1].size()) << " shadow (any-hit, to a point light), "
             << grouped(rays_.batch[2].size()) << " diffuse (cosine-weighted, seed " << config_.seed
             << ")\n";
    }

    // Correctness, before anything is timed: false (and the reason printed) when two back-ends
    // disagree on more rays than allowed.
    bool check() {
        out_ << "\ncorrectness check (untimed): rays on which two back-ends disagree; allowed: "
             << format("%g%%", 100 * config_.max_disagreement) << " of a kind's rays, t within "
             << format("%g", config_.t_tolerance) << " relative\n";
        out_ << format("  %-24s %-8s %10s %9s %10s %7s %8s  %s\n", "pair", "rays", "compared",
                       "hit/miss", "primitive", "t", "total", "verdict");
        Backend* embree_all = have_embree_ ? embree_.back().get() : nullptr;
        for (const RayBatch& batch : rays_.batch) {
            const std::vector<RayResult> bvh_results = trace_all(*bvh_, batch, all_threads_);
            report("bvh vs bvh-tuned", batch.kind,
                   compare(bvh_results, trace_all(*tuned_, batch, all_threads_), batch));
            std::vector<RayResult> embree_results;
            if (embree_all) {
                embree_results = trace_all(*embree_all, batch, all_threads_);
                report("bvh vs embree", batch.kind, compare(bvh_results, embree_results, batch));
            }
            std::vector<std::size_t> indices;
            const RayBatch sub = subset(batch, brute_rays_, indices);
            const std::vector<RayResult> brute_results = trace_all(*brute_, sub, all_threads_);
            report("brute-force vs bvh", batch.kind,
                   compare(brute_results, pick(bvh_results, indices), batch));
            if (embree_all)
                report("brute-force vs embree", batch.kind,
                       compare(brute_results, pick(embree_results, indices), batch));
        }
        if (!embree_all)
            out_
                << "  (Embree was not built in: nothing to compare the BVH with but brute force)\n";
        if (first_failure_.empty()) {
            out_ << bvh_traversal_summary(mesh_.scene, rays_, all_threads_);
            return true;
        }
        out_ << "\nrt-bench: error: " << first_failure_
             << "; a back-end computes wrong hits, so nothing was timed\n";
        out_.flush();
        std::fprintf(stderr, "rt-bench: error: %s; nothing was timed\n", first_failure_.c_str());
        return false;
    }

    // Timing. Runs of the different back-ends alternate, so that a change in the machine's load
    // disturbs all of them alike; the fastest of `repeat` runs counts.
    void time_all() {
        for (std::size_t ti = 0; ti < thread_counts_.size(); ++ti) {
            time_builds(ti);
            for (const RayBatch& batch : rays_.batch) time_traces(ti, batch);
        }
    }

    // Throughput and build times, a row per back-end and thread count.
    void print_table() {
        out_ << "\nthroughput in Mrays/s (single-ray queries, best of " << repeat_
             << " runs); build: from the scene's arrays to a traversable structure, in ms\n";
        out_ << format("  %-12s %7s %10s %10s %10s %10s %9s\n", "back-end", "threads", "build ms",
                       "primary", "shadow", "diffuse", "cpu share");
        for (int threads : thread_counts_) {
            for (const char* backend : {"brute-force", "bvh", "bvh-tuned", "embree"}) {
                if (std::string(backend) == "embree" && !have_embree_) continue;
                if (std::string(backend) == "brute-force" && !brute_timed_) continue;
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
                out_ << line << "\n";
            }
        }
        if (!brute_timed_)
            out_ << "  brute-force: not timed, " << grouped(triangles_) << " triangles > "
                 << "--brute-force-max-triangles " << config_.brute_force_max_triangles
                 << " (checked for correctness on " << grouped(brute_rays_)
                 << " rays of each kind)\n";
        else if (const Timing* t = find("brute-force", 1, "primary"); t && !t->note.empty())
            out_ << "  brute-force: timed on at most " << grouped(brute_rays_)
                 << " rays of each kind (evenly spread; --brute-force-rays)\n";
        out_ << "  bvh build: bvh_primitives + build_bvh (the reference: one thread, the steps of "
                "the handout); bvh-tuned build: the same tree on every core whatever --threads "
                "says (the top levels split side by side, then subtrees of up to 16384 "
                "primitives as parallel jobs; tools/bench/tuned_bvh.cpp)";
        if (have_embree_)
            out_ << "; embree build: buffers + rtcCommitScene, default quality, on `threads` build "
                    "threads";
        out_ << "\n  cpu share: CPU time the process got during the fastest run / (wall time x "
                "threads),"
                " lowest of the row; well below 100% means other work on the machine took cores\n";
        if (!have_embree_)
            out_ << "  embree: not built in (install libembree-dev, scripts/install-deps.sh, and "
                    "configure again): no ratios\n";
    }

    // Against Embree, and the goals set for it; then the load, to judge the figures by.
    void print_ratios() {
        if (have_embree_) out_ << "\n";
        for (int threads : have_embree_ ? thread_counts_ : std::vector<int>{}) {
            for (const char* backend : {"bvh", "bvh-tuned"}) print_ratio(backend, threads);
        }
        out_ << "load average " << load_average() << " at the end\n";
    }

    // One back-end against Embree at `threads`, and issue 27's goals.
    void print_ratio(const char* backend, int threads) {
        auto ratio = [&](const char* measure) {
            const Timing* a = find(backend, threads, measure);
            const Timing* e = find("embree", threads, measure);
            return a && e && a->mrays() > 0 && e->mrays() > 0 ? a->mrays() / e->mrays() : 0.0;
        };
        const double build =
            find(backend, threads, "build")->seconds / find("embree", threads, "build")->seconds;
        out_ << format(
            "ratios %s/embree, %d thread%s: primary %.2fx, shadow %.2fx, diffuse %.2fx "
            "throughput; build time %.2fx Embree's\n",
            backend, threads, threads == 1 ? "" : "s", ratio("primary"), ratio("shadow"),
            ratio("diffuse"), build);
        // Issue 27's goals (set for the Stanford bunny, 1024x768), at 1 and 2 threads.
        auto verdict = [](bool met) { return met ? "met" : "NOT met"; };
        out_ << format(
            "goals of issue 27 for %s at %d thread%s: primary >= 0.6x %s, shadow >= 0.5x %s, "
            "diffuse >= 0.35x %s, build <= 1.3x %s\n",
            backend, threads, threads == 1 ? "" : "s", verdict(ratio("primary") >= 0.6),
            verdict(ratio("shadow") >= 0.5), verdict(ratio("diffuse") >= 0.35),
            verdict(build <= 1.3));
    }

    // Every timing as CSV (--csv FILE, or - to print it).
    void write_csv() {
        if (config_.csv.empty()) return;
        std::string csv =
            "mesh,triangles,backend,threads,measure,rays,best_seconds,mrays_per_s,cpu_share,repeat,"
            "note\n";
        for (const Timing& t : timings_) {
            const bool build = t.measure == "build";
            csv +=
                format("\"%s\",%zu,%s,%d,%s,%zu,%.6f,%s,%s,%d,\"%s\"\n", mesh_.description.c_str(),
                       triangles_, t.backend.c_str(), t.threads, t.measure.c_str(),
                       build ? std::size_t(0) : t.rays, t.seconds,
                       build ? "" : format("%.4f", t.mrays()).c_str(),
                       build ? "" : format("%.3f", t.cpu_share).c_str(), repeat_, t.note.c_str());
        }
        if (config_.csv == "-") {
            out_ << "\n" << csv;
        } else {
            std::ofstream file(config_.csv);
            if (!file) throw std::runtime_error("cannot write " + config_.csv);
            file << csv;
            out_ << "CSV written to " << config_.csv << "\n";
        }
    }

  private:
    // One timed cell of a trace: a back-end on its rays.
    struct Entry {
        Backend* backend;
        const RayBatch* rays;
        Timing timing;
    };

    Disagreements compare(const std::vector<RayResult>& a, const std::vector<RayResult>& b,
                          const RayBatch& batch) const {
        return compare_results(a, b, batch.any_hit, config_.t_tolerance);
    }

    void report(const std::string& pair, RayKind kind, const Disagreements& d) {
        const std::size_t allowed = allowed_disagreements(d.rays, config_.max_disagreement);
        const bool ok = d.total() <= allowed;
        out_ << format("  %-24s %-8s %10zu %9zu %10zu %7zu %8zu  %s\n", pair.c_str(),
                       to_string(kind), d.rays, d.hit_miss, d.primitive, d.t, d.total(),
                       ok ? "ok" : "TOO MANY");
        if (!ok && first_failure_.empty())
            first_failure_ = pair + " disagree on " + std::to_string(d.total()) + " of " +
                             std::to_string(d.rays) + " " + to_string(kind) + " rays (" +
                             format("%.4f%%", 100 * d.fraction()) + ", allowed " +
                             std::to_string(allowed) + ")";
    }

    void time_builds(std::size_t ti) {
        const int threads = thread_counts_[ti];
        Timing bvh_build{"bvh", threads, "build", triangles_, kInfinity, "builder: one thread"};
        Timing tuned_build{"bvh-tuned", threads,   "build",
                           triangles_,  kInfinity, "builder: every core"};
        Timing embree_build{"embree", threads, "build", triangles_, kInfinity, ""};
        for (int r = 0; r < repeat_; ++r) {
            bvh_build.seconds = std::min(bvh_build.seconds, bvh_->build() / 1000);
            tuned_build.seconds = std::min(tuned_build.seconds, tuned_->build() / 1000);
            if (have_embree_)
                embree_build.seconds = std::min(embree_build.seconds, embree_[ti]->build() / 1000);
        }
        timings_.push_back(bvh_build);
        timings_.push_back(tuned_build);
        if (have_embree_) timings_.push_back(embree_build);
    }

    void time_traces(std::size_t ti, const RayBatch& batch) {
        const int threads = thread_counts_[ti];
        std::vector<std::size_t> indices;
        const RayBatch sub = subset(batch, brute_rays_, indices);
        const std::string kind = to_string(batch.kind);
        std::vector<Entry> entries;
        if (brute_timed_)
            entries.push_back(
                {brute_.get(),
                 &sub,
                 {"brute-force", threads, kind, sub.size(), kInfinity,
                  sub.size() < batch.size() ? "on a subset of " + grouped(sub.size()) + " rays"
                                            : ""}});
        entries.push_back(
            {bvh_.get(), &batch, {"bvh", threads, kind, batch.size(), kInfinity, ""}});
        entries.push_back(
            {tuned_.get(), &batch, {"bvh-tuned", threads, kind, batch.size(), kInfinity, ""}});
        if (have_embree_)
            entries.push_back({embree_[ti].get(),
                               &batch,
                               {"embree", threads, kind, batch.size(), kInfinity, ""}});
        std::vector<RayResult> results(batch.size());
        for (int r = 0; r < repeat_; ++r)
            for (Entry& e : entries) {
                const Run run = time_trace(*e.backend, *e.rays, threads, results);
                if (run.seconds < e.timing.seconds) {
                    e.timing.seconds = run.seconds;
                    e.timing.cpu_share = run.cpu_share;
                }
            }
        for (Entry& e : entries) timings_.push_back(e.timing);
    }

    const Timing* find(const std::string& backend, int threads, const std::string& measure) const {
        for (const Timing& t : timings_)
            if (t.backend == backend && t.threads == threads && t.measure == measure) return &t;
        return nullptr;
    }

    const BvhBenchConfig& config_;
    std::ostream& out_;
    const int cores_, all_threads_, repeat_;
    BenchMesh mesh_;
    const std::size_t triangles_;
    std::vector<int> thread_counts_;
    std::unique_ptr<Backend> bvh_, tuned_, brute_;
    std::vector<std::unique_ptr<Backend>> embree_;  // one device per thread count
    bool brute_timed_ = false, have_embree_ = false;
    std::size_t brute_rays_ = 0;
    BenchRays rays_;
    std::string first_failure_;
    std::vector<Timing> timings_;
};

}  // namespace

int run_bvh_bench(const BvhBenchConfig& config, std::ostream& out) {
    BvhBench bench(config, out);
    bench.set_up();
    if (!bench.check()) return 2;
    bench.time_all();
    bench.print_table();
    bench.print_ratios();
    bench.write_csv();
    return 0;
}

}  // namespace rt::bench
