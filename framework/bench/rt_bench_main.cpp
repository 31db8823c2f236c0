// rt-bench: measurements for the course. Subcommands: `accuracy` (issue 6); BVH benchmarks
// will join as further subcommands.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "bench/accuracy.h"

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
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "[%6.1f s] %s\n", s, what.c_str());
    };
    const rt::bench::AccuracyResults res = rt::bench::run_accuracy(cfg);
    std::string link_dir = svg_dir;
    if (!markdown.empty() && !svg_dir.empty()) {
        const auto md_dir = std::filesystem::absolute(markdown).parent_path();
        link_dir = std::filesystem::relative(std::filesystem::absolute(svg_dir), md_dir).generic_string();
    }
    std::string command = "build/bin/rt-bench accuracy";
    if (cfg.seed != 1) command += " --seed " + std::to_string(cfg.seed);
    if (cfg.cases != rt::bench::AccuracyConfig{}.cases) command += " --cases " + std::to_string(cfg.cases);
    if (!markdown.empty()) command += " --markdown " + markdown;
    if (!svg_dir.empty()) command += " --svg-dir " + svg_dir;
    const std::string md = rt::bench::markdown_report(res, svg_dir.empty() ? "" : link_dir, command);
    if (!svg_dir.empty()) rt::bench::write_svgs(res, svg_dir);
    if (!csv.empty()) write_file(csv, rt::bench::csv_report(res));
    if (!markdown.empty()) write_file(markdown, md);
    else std::cout << md;
    std::fprintf(stderr, "done in %.1f s\n", res.seconds);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rt-bench: measurements for the ray-tracing course"};
    app.require_subcommand(1);

    rt::bench::AccuracyConfig cfg;
    std::string markdown, svg_dir, csv;
    CLI::App* acc = app.add_subcommand(
        "accuracy", "speed against error of the intersection methods, measured against exact arithmetic");
    acc->add_option("--seed", cfg.seed, "random seed of every scenario")->capture_default_str();
    acc->add_option("--cases", cfg.cases, "rays per scenario")->capture_default_str()->check(CLI::Range(10, 10000000));
    acc->add_option("--markdown", markdown, "write the report here (default: print it)");
    acc->add_option("--svg-dir", svg_dir, "write the plots (SVG) into this folder");
    acc->add_option("--csv", csv, "write every table row as CSV");
    acc->add_flag("!--no-render", cfg.rendering, "skip the rendering section");
    acc->add_flag("!--no-timing", cfg.timing, "classification only");

    CLI11_PARSE(app, argc, argv);
    try {
        if (acc->parsed()) return run_accuracy(cfg, markdown, svg_dir, csv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rt-bench: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
