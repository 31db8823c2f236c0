// The accuracy lab (`rt-bench accuracy`): ray/primitive cases by scenario, their exact answers
// from CGAL/GMP/MPFR, every method in float and double classified against them and timed; the
// self-intersection experiment; and time against image error for the stage 02 scenes.
// Never links student code: the methods are the bench's own (bench/methods.h).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bench/mis_strategies.h"
#include "bench/sampling_error.h"
#include "bench/texture_filters.h"

namespace rt::bench {

struct AccuracyConfig {
    std::uint64_t seed = 1;
    int cases = 10000;   // rays per scenario
    bool timing = true;  // measure ns per test (off: classification only, for tests)
    std::string family;  // "triangle" or "sphere": only those scenarios ("": all)
    bool self_intersection = true;
    bool rendering = true;
    bool textures = true;    // the texture-filter rows (needs the OpenImageIO module for all)
    bool sampling = true;    // stage 10's rows (rt-bench fills them: they need the renderer)
    bool mis = true;         // stage 11's light strategies (the same)
    int render_divisor = 2;  // stage scenes are rendered at 1/divisor of their size
    std::function<void(const std::string&)> progress;  // one line per finished part
};

// Classification counts of one method on one scenario. `cases` is rays (a single-triangle or
// sphere scenario: one test each; a mesh scenario: one test per triangle of the mesh).
struct Counts {
    long cases = 0, tests = 0;
    long false_miss = 0, false_hit = 0, leak = 0, double_hit = 0;
    long t_samples = 0;
    double median_ulps = 0, max_ulps = 0;
};

struct Row {
    std::string family;     // "triangle" or "sphere"
    std::string scenario;   // key, e.g. "through-edge"
    bool mesh = false;      // leak and double-hit are defined
    std::string method;     // e.g. "watertight", or "CGAL (exact)"
    std::string precision;  // "float", "double" or "exact"
    Counts counts;
    double ns_per_test = 0;
};

struct SelfRow {
    std::string strategy, precision;
    double scale = 1;
    long rays = 0, self_hits = 0;
    long occluder_rays = 0, missed_gap_1e2 = 0, missed_gap_1e4 = 0;  // gaps 1e-2, 1e-4 x scale
};

struct RenderPoint {
    std::string series;  // e.g. "watertight float" or "supersampling"
    int spp = 1;
    double ms = 0;           // summed over the scenes, one thread
    double rmse = 0;         // 8-bit units against the 256-sample reference, mean over scenes
    double center_diff = 0;  // % pixels off by > 2/255 from the double pixel-centre image
};

struct AccuracyResults {
    AccuracyConfig config;
    std::vector<Row> rows;
    std::vector<SelfRow> self;
    std::vector<RenderPoint> render;
    std::vector<std::string> render_scenes;
    int render_width_sum = 0, render_height_sum = 0;
    std::vector<TexturePoint> texture;
    std::string texture_note;
    SamplingSeries sampling;  // filled by rt-bench's main, not run_accuracy (see sampling_error.h)
    MisSeries mis;            // the same (see mis_strategies.h)
    double seconds = 0;
};

// The row of (scenario, method, precision), or null.
const Row* find(const AccuracyResults& r, const std::string& scenario, const std::string& method,
                const std::string& precision);

// The scenario keys in table order, and one line describing each.
struct ScenarioInfo {
    std::string key, family, description;
    bool mesh;
};
const std::vector<ScenarioInfo>& scenarios();

AccuracyResults run_accuracy(const AccuracyConfig& config);

// Report writers. The markdown is a fixed template with every number from `results`;
// svg_dir_in_markdown is how the markdown links the plots.
std::string markdown_report(const AccuracyResults& results, const std::string& svg_dir_in_markdown,
                            const std::string& command);
void write_svgs(const AccuracyResults& results, const std::string& dir);
std::string csv_report(const AccuracyResults& results);

// The classification counts stored in a report's tables, for the consistency test.
struct ReportCounts {
    std::uint64_t seed = 0;
    int cases = 0;
    std::vector<Row> rows;  // counts only (times are not compared)
    std::vector<SelfRow> self;
};
ReportCounts parse_report(const std::string& markdown);

// a * b + c in a separately compiled file: with -ffp-contract=off it rounds twice.
float multiply_add(float a, float b, float c);
double multiply_add(double a, double b, double c);

}  // namespace rt::bench
