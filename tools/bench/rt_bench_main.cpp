// rt-bench: measurements for the course. Without a subcommand, or as `rt-bench bvh`: the BVH
// benchmark (issue 5, bvh_bench.h). `rt-bench accuracy`: the accuracy lab (issue 6).
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "apps/cli_parse.h"
#include "bench/accuracy.h"
#include "bench/bvh_bench.h"
#include "bench/gpu_bench.h"
#include "core/parallel_for.h"
#ifdef RT_BENCH_HAVE_VIEW
#include "bench/view_latency.h"
#endif

namespace {

void write_file(const std::string& path, const std::string& text) {
    const std::filesystem::path p(path);
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    std::ofstream out(p);
    if (!out) throw std::runtime_error("cannot write " + path);
    out << text;
}

int run_accuracy(const rt::bench::AccuracyConfig& base, const std::string& markdown,
                 const std::string& svg_dir, const std::string& csv) {
    rt::bench::AccuracyConfig cfg = base;
    const auto start = std::chrono::steady_clock::now();
    cfg.progress = [&](const std::string& what) {
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "[%6.1f s] %s\n", s, what.c_str());
    };
    rt::bench::AccuracyResults res = rt::bench::run_accuracy(cfg);
    if (cfg.sampling) res.sampling = rt::bench::measure_sampling_error(48, 36, 1024, cfg.progress);
    if (cfg.mis) res.mis = rt::bench::measure_mis_strategies(cfg.progress);
    if (cfg.sampling || cfg.mis)
        res.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string link_dir = svg_dir;
    if (!markdown.empty() && !svg_dir.empty()) {
        const auto md_dir = std::filesystem::absolute(markdown).parent_path();
        link_dir =
            std::filesystem::relative(std::filesystem::absolute(svg_dir), md_dir).generic_string();
    }
    std::string command = "build/bin/rt-bench accuracy";
    if (cfg.seed != 1) command += " --seed " + std::to_string(cfg.seed);
    if (cfg.cases != rt::bench::AccuracyConfig{}.cases)
        command += " --cases " + std::to_string(cfg.cases);
    if (!markdown.empty()) command += " --markdown " + markdown;
    if (!svg_dir.empty()) command += " --svg-dir " + svg_dir;
    const std::string md =
        rt::bench::markdown_report(res, svg_dir.empty() ? "" : link_dir, command);
    if (!svg_dir.empty()) rt::bench::write_svgs(res, svg_dir);
    if (!csv.empty()) write_file(csv, rt::bench::csv_report(res));
    if (!markdown.empty())
        write_file(markdown, md);
    else
        std::cout << md;
    std::fprintf(stderr, "done in %.1f s\n", res.seconds);
    return 0;
}

// The BVH benchmark's options belong to the top level, so that they work both without a
// subcommand and after `bvh` (which lets unknown options fall through to here).
void add_bvh_options(CLI::App& app, rt::bench::BvhBenchConfig& bench) {
    app.add_option("--mesh", bench.mesh_file, "an OBJ mesh (default: a procedural mesh)")
        ->check(CLI::ExistingFile);
    app.add_option("--procedural", bench.procedural,
                   "procedural mesh when no --mesh: icosphere, torus, terrain, soup")
        ->capture_default_str();
    app.add_option("--triangles", bench.triangles, "procedural mesh: at least this many triangles")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t(1), std::size_t(1) << 26));
    app.add_option("--seed", bench.seed, "seed of the procedural mesh and the diffuse rays")
        ->capture_default_str();
    app.add_option("--threads", bench.threads,
                   "threads of the parallel run (default: every core, " +
                       std::to_string(rt::default_thread_count()) + "); 1 thread is always run too")
        ->check(CLI::Range(1, 256));
    app.add_option("--width", bench.width, "primary rays: image width")
        ->capture_default_str()
        ->check(CLI::Range(1, 16384));
    app.add_option("--height", bench.height, "primary rays: image height")
        ->capture_default_str()
        ->check(CLI::Range(1, 16384));
    app.add_option("--repeat", bench.repeat, "timed runs of each measurement; the fastest counts")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    app.add_option("--brute-force-max-triangles", bench.brute_force_max_triangles,
                   "time brute force only up to this many triangles (above: correctness only)")
        ->capture_default_str();
    app.add_option("--brute-force-rays", bench.brute_force_rays,
                   "brute force traces at most this many rays of each kind (an even subset)")
        ->capture_default_str()
        ->check(CLI::Range(std::size_t(1), std::size_t(1) << 30));
    app.add_option("--max-disagreement", bench.max_disagreement,
                   "fraction of a kind's rays on which two back-ends may disagree before the "
                   "run fails (edge and vertex hits legitimately differ)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1.0));
    app.add_option("--csv", bench.csv, "write the timings as CSV to this file (\"-\": print them)");
    // Hidden (empty group): makes the BVH answer wrongly on every N-th hit, for the test that
    // the correctness check fails the run.
    app.add_option("--inject-error", bench.inject_error_period)->group("");
}

struct AccuracyArgs {
    rt::bench::AccuracyConfig config;
    std::string markdown, svg_dir, csv;
};

CLI::App* add_accuracy_command(CLI::App& app, AccuracyArgs& a) {
    CLI::App* acc = app.add_subcommand(
        "accuracy",
        "speed against error of the intersection methods, measured against exact arithmetic");
    acc->add_option("--seed", a.config.seed, "random seed of every scenario")
        ->capture_default_str();
    acc->add_option("--cases", a.config.cases, "rays per scenario")
        ->capture_default_str()
        ->check(CLI::Range(10, 10000000));
    acc->add_option("--markdown", a.markdown, "write the report here (default: print it)");
    acc->add_option("--svg-dir", a.svg_dir, "write the plots (SVG) into this folder");
    acc->add_option("--csv", a.csv, "write every table row as CSV");
    acc->add_flag("!--no-render", a.config.rendering, "skip the rendering section");
    acc->add_flag("!--no-textures", a.config.textures, "skip the texture-filter section");
    acc->add_flag("!--no-sampling", a.config.sampling,
                  "skip stage 10's error against samples per pixel");
    acc->add_flag("!--no-mis", a.config.mis,
                  "skip stage 11's light strategies (NEE, BSDF, MIS) against time");
    acc->add_flag("!--no-timing", a.config.timing, "classification only");

    return acc;
}

#ifdef RT_BENCH_HAVE_VIEW
CLI::App* add_view_command(CLI::App& app, rt::bench::ViewLatencyConfig& view_cfg) {
    CLI::App* view = app.add_subcommand(
        "view", "the lecture viewer's latency: camera change to first coarse and to full frame");
    view->add_option("scene", view_cfg.scene, "scene file (default: stage 05's whitted.json)")
        ->check(CLI::ExistingFile);
    view->add_option("--width", view_cfg.width)->capture_default_str()->check(CLI::Range(16, 8192));
    view->add_option("--height", view_cfg.height)
        ->capture_default_str()
        ->check(CLI::Range(16, 8192));
    view->add_option("--threads", view_cfg.threads)
        ->capture_default_str()
        ->check(CLI::Range(1, 256));
    view->add_flag("--gpu", view_cfg.gpu, "the viewer's GPU path (stage 09's shader)");
    view->add_option("--changes", view_cfg.changes, "camera changes timed")
        ->capture_default_str()
        ->check(CLI::Range(1, 10000));
    return view;
}
#endif

struct GpuArgs {
    rt::bench::GpuBenchConfig config;
    std::string gl = "egl";
};

CLI::App* add_gpu_command(CLI::App& app, GpuArgs& a) {
    CLI::App* gpu_cmd = app.add_subcommand(
        "gpu",
        "stage 09's compute shader (specialised and uber) against the CPU on 1 and 2 threads");
    gpu_cmd->add_option("--scene", a.config.scenes,
                        "scene files (default: whitted, large_icosphere, soft_shadows)");
    gpu_cmd->add_option("--width", a.config.width, "image width")
        ->capture_default_str()
        ->check(CLI::Range(1, 4096));
    gpu_cmd->add_option("--height", a.config.height, "image height")
        ->capture_default_str()
        ->check(CLI::Range(1, 4096));
    gpu_cmd->add_option("--repeat", a.config.repeat, "timed runs of each; the fastest counts")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    gpu_cmd->add_option("--gl", a.gl, "the OpenGL context (default: egl)")
        ->check(CLI::IsMember({"egl", "osmesa"}));

    return gpu_cmd;
}

// The BVH benchmark's options belong to it: given with another subcommand, they are an error.
bool no_bvh_options_given(const CLI::App& app, const std::string& sub) {
    for (const CLI::Option* option : app.get_options())
        if (option->count() > 0 && option->get_name() != "--help") {
            std::fprintf(stderr,
                         "rt-bench: error: %s is an option of the BVH benchmark, not of `%s`; "
                         "give it after `%s`, if there\n",
                         option->get_name().c_str(), sub.c_str(), sub.c_str());
            return false;
        }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "rt-bench: measurements for the ray-tracing course. Without a subcommand: the "
        "BVH benchmark (as `rt-bench bvh`)"};
    app.require_subcommand(0, 1);
    rt::bench::BvhBenchConfig bench;
    add_bvh_options(app, bench);
    CLI::App* bvh = app.add_subcommand("bvh",
                                       "the BVH benchmark (the default): brute force, "
                                       "stage 06 BVH and Embree on the same rays");
    bvh->fallthrough();
    AccuracyArgs accuracy;
    CLI::App* acc = add_accuracy_command(app, accuracy);
#ifdef RT_BENCH_HAVE_VIEW
    rt::bench::ViewLatencyConfig view_cfg;
    CLI::App* view = add_view_command(app, view_cfg);
#endif
    GpuArgs gpu;
    CLI::App* gpu_cmd = add_gpu_command(app, gpu);
    if (const auto stop = rt::parse_command_line(app, argc, argv, "rt-bench", "`rt-bench --help`"))
        return *stop;
    try {
#ifdef RT_BENCH_HAVE_VIEW
        if (view->parsed()) return rt::bench::run_view_latency(view_cfg, std::cout) ? 0 : 1;
#endif
        if (acc->parsed() || gpu_cmd->parsed()) {
            if (!no_bvh_options_given(app, acc->parsed() ? "accuracy" : "gpu")) return 2;
            if (gpu_cmd->parsed()) {
                gpu.config.context = *rt::parse_gl_kind(gpu.gl);
                return rt::bench::run_gpu_bench(gpu.config, std::cout);
            }
            return run_accuracy(accuracy.config, accuracy.markdown, accuracy.svg_dir, accuracy.csv);
        }
        return rt::bench::run_bvh_bench(bench, std::cout);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rt-bench: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
