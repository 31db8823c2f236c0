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
#include <thread>

#include <sys/resource.h>

#include "accel/bvh_input.h"
#include "bench/machine.h"
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
    out << "machine: " << cores << " cores (" << cpu_model("unknown processor")
        << "), load average " << load_average() << " at the start\n";
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
        Timing bvh_build{"bvh",     threads,   "build",
                         triangles, kInfinity, "builder: root's two subtrees on 2 threads"};
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
    out << "  bvh build: bvh_primitives + build_bvh (the reference builder splits the root, then "
           "builds its two "
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
