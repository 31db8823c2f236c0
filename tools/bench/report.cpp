// The accuracy report: markdown (a fixed template, every number from the run), SVG plots, CSV,
// and the parser the consistency test uses to read the counts back.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "bench/accuracy.h"

namespace rt::bench {
namespace {

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}
std::string pct(long n, long of) { return fmt("%.2f", of ? 100.0 * double(n) / double(of) : 0.0); }
std::string count_cell(long n, long of) { return std::to_string(n) + " (" + pct(n, of) + "%)"; }
std::string ulps_cell(double u) {
    if (u == 0) return "0";
    if (u < 10) return fmt("%.2g", u);
    return fmt("%.3g", u);
}

std::string cpu_name() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) return line.substr(colon + 2);
        }
    return "unknown CPU";
}

const Row* find(const AccuracyResults& r, const std::string& scenario, const std::string& method,
                const std::string& precision) {
    for (const Row& row : r.rows)
        if (row.scenario == scenario && row.method == method && row.precision == precision)
            return &row;
    return nullptr;
}
const SelfRow* find_self(const AccuracyResults& r, const std::string& strategy,
                         const std::string& precision, double scale) {
    for (const SelfRow& row : r.self)
        if (row.strategy == strategy && row.precision == precision && row.scale == scale) return &row;
    return nullptr;
}

// "n of N (p%)" for one count of one row, or "n/a".
std::string say(const AccuracyResults& r, const std::string& scenario, const std::string& method,
                const std::string& precision, long Counts::*field) {
    const Row* row = find(r, scenario, method, precision);
    if (!row) return "n/a";
    return std::to_string(row->counts.*field) + " of " + std::to_string(row->counts.cases) +
           " rays (" + pct(row->counts.*field, row->counts.cases) + "%)";
}
std::string say_ulps(const AccuracyResults& r, const std::string& scenario, const std::string& method,
                     const std::string& precision, bool max) {
    const Row* row = find(r, scenario, method, precision);
    if (!row) return "n/a";
    return ulps_cell(max ? row->counts.max_ulps : row->counts.median_ulps);
}
std::string say_ns(const AccuracyResults& r, const std::string& scenario, const std::string& method,
                   const std::string& precision) {
    const Row* row = find(r, scenario, method, precision);
    return row ? fmt("%.1f", row->ns_per_test) : "n/a";
}

std::string self_cell(long n, long of) { return count_cell(n, of); }

// Method summaries for the plots: mean ns over the family's scenarios, wrong decisions over all
// its rays.
struct Summary {
    std::string label;
    double ns = 0, wrong_pct = 0, median_ulps = 0;
    bool exact = false;
};
std::vector<Summary> summarize(const AccuracyResults& r, const std::string& family) {
    std::vector<std::pair<std::string, std::string>> keys;
    for (const Row& row : r.rows)
        if (row.family == family &&
            std::find(keys.begin(), keys.end(), std::make_pair(row.method, row.precision)) == keys.end())
            keys.push_back({row.method, row.precision});
    std::vector<Summary> out;
    for (const auto& [method, precision] : keys) {
        Summary s;
        s.label = precision == "exact" ? method : method + " " + precision;
        s.exact = precision == "exact";
        long wrong = 0, rays = 0;
        int n = 0;
        std::vector<double> med;
        for (const Row& row : r.rows) {
            if (row.family != family || row.method != method || row.precision != precision) continue;
            s.ns += row.ns_per_test;
            ++n;
            wrong += row.counts.false_miss + row.counts.false_hit + row.counts.leak;
            rays += row.counts.cases;
            med.push_back(row.counts.median_ulps);
        }
        s.ns /= std::max(n, 1);
        s.wrong_pct = rays ? 100.0 * double(wrong) / double(rays) : 0;
        std::sort(med.begin(), med.end());
        s.median_ulps = med.empty() ? 0 : med[med.size() / 2];
        out.push_back(s);
    }
    return out;
}

// ---------------------------------------------------------------------------------------------
// A small SVG scatter plot with log axes.

struct PlotPoint {
    std::string label;
    double x, y;
    std::string group;  // points of one group (in order) are joined by a line
    std::string colour;
};

std::string svg_plot(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                     std::vector<PlotPoint> pts, double y_floor, const std::string& note) {
    const double W = 640, H = 400, L = 70, R = 20, T = 40, B = 55;
    for (auto& p : pts) p.y = std::max(p.y, y_floor), p.x = std::max(p.x, 1e-3);  // log axes
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& p : pts) {
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    x0 = std::pow(10, std::floor(std::log10(x0))), x1 = std::pow(10, std::ceil(std::log10(x1)));
    y0 = std::pow(10, std::floor(std::log10(y0))), y1 = std::pow(10, std::ceil(std::log10(y1)));
    if (x1 <= x0) x1 = x0 * 10;
    if (y1 <= y0) y1 = y0 * 10;
    auto X = [&](double x) { return L + (W - L - R) * (std::log10(x) - std::log10(x0)) / (std::log10(x1) - std::log10(x0)); };
    auto Y = [&](double y) { return H - B - (H - T - B) * (std::log10(y) - std::log10(y0)) / (std::log10(y1) - std::log10(y0)); };
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
    s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s << "<text x=\"" << W / 2 << "\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">" << title << "</text>\n";
    for (double v = x0; v <= x1 * 1.0001; v *= 10) {
        s << "<line x1=\"" << fmt("%.1f", X(v)) << "\" y1=\"" << T << "\" x2=\"" << fmt("%.1f", X(v)) << "\" y2=\""
          << H - B << "\" stroke=\"#ddd\"/>\n";
        s << "<text x=\"" << fmt("%.1f", X(v)) << "\" y=\"" << H - B + 15 << "\" text-anchor=\"middle\">"
          << fmt("%g", v) << "</text>\n";
    }
    for (double v = y0; v <= y1 * 1.0001; v *= 10) {
        s << "<line x1=\"" << L << "\" y1=\"" << fmt("%.1f", Y(v)) << "\" x2=\"" << W - R << "\" y2=\""
          << fmt("%.1f", Y(v)) << "\" stroke=\"#ddd\"/>\n";
        s << "<text x=\"" << L - 5 << "\" y=\"" << fmt("%.1f", Y(v) + 4) << "\" text-anchor=\"end\">"
          << fmt("%g", v) << "</text>\n";
    }
    s << "<rect x=\"" << L << "\" y=\"" << T << "\" width=\"" << W - L - R << "\" height=\"" << H - T - B
      << "\" fill=\"none\" stroke=\"black\"/>\n";
    s << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 22 << "\" text-anchor=\"middle\">" << xlabel << "</text>\n";
    s << "<text x=\"15\" y=\"" << (T + H - B) / 2 << "\" text-anchor=\"middle\" transform=\"rotate(-90 15 "
      << (T + H - B) / 2 << ")\">" << ylabel << "</text>\n";
    if (!note.empty())
        s << "<text x=\"" << L << "\" y=\"" << H - 6 << "\" font-size=\"10\" fill=\"#555\">" << note << "</text>\n";
    std::map<std::string, std::string> lines;
    for (const auto& p : pts) {
        if (p.group.empty()) continue;
        std::string& line = lines[p.group];
        if (!line.empty()) line += ' ';
        line += fmt("%.1f", X(p.x));
        line += ',';
        line += fmt("%.1f", Y(p.y));
    }
    for (const auto& [g, path] : lines)
        s << "<polyline points=\"" << path << "\" fill=\"none\" stroke=\"#888\"/>\n";
    // Points carry numbers; the names are in a legend in the top right corner (close points would
    // otherwise write their names over each other).
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const PlotPoint& p = pts[i];
        s << "<circle cx=\"" << fmt("%.1f", X(p.x)) << "\" cy=\"" << fmt("%.1f", Y(p.y)) << "\" r=\"4\" fill=\""
          << p.colour << "\"/>\n";
        s << "<text x=\"" << fmt("%.1f", X(p.x) + 5) << "\" y=\"" << fmt("%.1f", Y(p.y) - 5)
          << "\" font-size=\"10\">" << i + 1 << "</text>\n";
        const double lx = W - R - 175, ly = T + 14 + 13 * double(i);
        s << "<circle cx=\"" << lx << "\" cy=\"" << fmt("%.1f", ly - 4) << "\" r=\"4\" fill=\"" << p.colour
          << "\"/>\n<text x=\"" << lx + 8 << "\" y=\"" << fmt("%.1f", ly) << "\">" << i + 1 << "  " << p.label
          << "</text>\n";
    }
    s << "</svg>\n";
    return s.str();
}

std::string colour_of(const std::string& label) {
    if (label.find("CGAL") != std::string::npos) return "#000000";
    if (label.find("float") != std::string::npos) return "#d62728";
    return "#1f77b4";
}

std::vector<PlotPoint> family_points(const AccuracyResults& r, const std::string& family) {
    std::vector<PlotPoint> pts;
    for (const Summary& s : summarize(r, family))
        pts.push_back({s.label, s.ns, s.wrong_pct, "", colour_of(s.label)});
    return pts;
}

std::string render_svg(const AccuracyResults& r) {
    std::vector<PlotPoint> pts;
    for (const RenderPoint& p : r.render)
        if (p.series == "supersampling")
            pts.push_back({std::to_string(p.spp) + " spp", p.ms, p.rmse, "ss", "#2ca02c"});
    for (const RenderPoint& p : r.render)
        if (p.series == "watertight double") pts.push_back({"double, 1 spp", p.ms, p.rmse, "", "#1f77b4"});
    return svg_plot("Rendering: time against image error", "ms for all scenes (one thread)",
                    "RMSE vs 256 spp (8-bit units)", pts, 1e-3,
                    "green: watertight float with n x n samples per pixel; blue: the same in double, 1 spp");
}

constexpr double kFloor = 1e-3;  // 0 % is drawn here on the log axis

}  // namespace

void write_svgs(const AccuracyResults& r, const std::string& dir) {
    std::filesystem::create_directories(dir);
    auto put = [&](const std::string& name, const std::string& text) {
        std::ofstream out(std::filesystem::path(dir) / name);
        if (!out) throw std::runtime_error("cannot write " + dir + "/" + name);
        out << text;
    };
    put("triangles.svg", svg_plot("Triangles: speed against wrong decisions", "ns per ray-triangle test",
                                  "wrong decisions, % of rays", family_points(r, "triangle"), kFloor,
                                  "wrong = false miss + false hit + leak over all triangle scenarios; 0 drawn at 0.001"));
    put("spheres.svg", svg_plot("Spheres: speed against wrong decisions", "ns per ray-sphere test",
                                "wrong decisions, % of rays", family_points(r, "sphere"), kFloor,
                                "wrong = false miss + false hit over all sphere scenarios; 0 drawn at 0.001"));
    if (!r.render.empty()) put("render.svg", render_svg(r));
}

std::string csv_report(const AccuracyResults& r) {
    std::ostringstream s;
    s << "section,scenario,method,precision,ns_per_test,rays,tests,false_miss,false_hit,leak,double_hit,"
         "median_ulps,max_ulps\n";
    for (const Row& row : r.rows)
        s << row.family << ',' << row.scenario << ',' << row.method << ',' << row.precision << ','
          << row.ns_per_test << ',' << row.counts.cases << ',' << row.counts.tests << ','
          << row.counts.false_miss << ',' << row.counts.false_hit << ',' << row.counts.leak << ','
          << row.counts.double_hit << ',' << row.counts.median_ulps << ',' << row.counts.max_ulps << '\n';
    s << "\nsection,strategy,precision,scale,rays,self_hits,occluder_rays,missed_gap_1e-2,missed_gap_1e-4\n";
    for (const SelfRow& x : r.self)
        s << "self," << x.strategy << ',' << x.precision << ',' << x.scale << ',' << x.rays << ','
          << x.self_hits << ',' << x.occluder_rays << ',' << x.missed_gap_1e2 << ',' << x.missed_gap_1e4 << '\n';
    s << "\nsection,series,spp,ms,rmse,centre_diff_percent\n";
    for (const RenderPoint& p : r.render)
        s << "render," << p.series << ',' << p.spp << ',' << p.ms << ',' << p.rmse << ',' << p.centre_diff << '\n';
    return s.str();
}

std::string markdown_report(const AccuracyResults& r, const std::string& svg, const std::string& command) {
    std::ostringstream m;
    const AccuracyConfig& c = r.config;
    m << "# Accuracy lab: speed against error\n\n"
      << "<!-- Generated by rt-bench accuracy; do not edit by hand. config: seed=" << c.seed
      << " cases=" << c.cases << " -->\n\n"
      << "Every number on this page was measured by one run of one command, from the repository root "
         "after a release build:\n\n"
      << "```sh\ncmake --preset release && cmake --build build\n" << command << "\n```\n\n"
      << "| | |\n|---|---|\n"
      << "| machine | " << cpu_name() << ", " << std::thread::hardware_concurrency() << " hardware threads |\n"
      << "| compiler | " << RT_BENCH_COMPILER << " |\n"
      << "| flags | `" << RT_BENCH_FLAGS << "` (the files doing exact arithmetic also get CGAL's "
         "`-frounding-math`; the timed methods do not) |\n"
      << "| seed, rays per scenario | " << c.seed << ", " << c.cases << " |\n"
      << "| run time | " << fmt("%.0f", r.seconds) << " s |\n\n";

    m << "## What is measured\n\n"
         "Triangle methods: Cramer's rule as taught in stage 02, Moeller-Trumbore, the watertight test of Woop, "
         "Benthin and Wald (as in `framework/geometry/watertight.cpp`), and that test with fused multiply-adds "
         "in its edge functions. Sphere methods: the textbook quadratic, the q-form (roots q/a and c/q), and "
         "Ray Tracing Gems ch. 7 (q-form with the discriminant as r^2 - |l|^2, the stage 02 solution). All are "
         "the bench's own copies (`tools/bench/methods.h`), each in float and double. "
         "Each scenario generates rays and surfaces from a fixed seed, **in float**; the double methods get "
         "the same floats, so both precisions solve the very same problem and CGAL decides it exactly once "
         "(`framework/testing/exact_reference.h`: exact predicates, rationals, 256-bit MPFR). Columns:\n\n"
         "- **ns/test**: time per ray-primitive test, one thread, the best of 5 rounds of at least 8 ms over "
         "the whole scenario (CGAL: one pass of the exact decision with its filters, including the exact t).\n"
         "- **false miss**: the exact ray hits, the method reports nothing. On closed meshes this is per "
         "surface crossing at an interior point of a face (a ray enters through front faces and leaves "
         "through back faces).\n"
         "- **false hit**: the method reports a hit where there is none (on meshes: a crossing that does not "
         "exist, or a hit on a face parallel to the ray).\n"
         "- **leak**: closed meshes only. The ray crosses the surface exactly through a shared edge or vertex, "
         "and the method reports none of the faces meeting there: it slips through the mesh.\n"
         "- **double hit**: closed meshes only. One crossing reported by two or more faces. Exact arithmetic "
         "does this for every ray through an edge (closed faces share their edges); it matters when hits "
         "are counted (inside/outside parity), not for the nearest hit.\n"
         "- **median / max ulps**: error of t in units in the last place of the method's own precision, over "
         "the tests that both the method and CGAL call a hit.\n\n"
         "Counts are `n (% of rays)`. The scenarios:\n\n| scenario | what |\n|---|---|\n";
    for (const ScenarioInfo& s : scenarios()) m << "| " << s.key << " | " << s.description << " |\n";

    auto table = [&](const std::string& family) {
        m << "\n<!-- table:" << family << " -->\n"
          << "| scenario | method | precision | ns/test | rays | false miss | false hit | leak | double hit | "
             "median ulps | max ulps |\n|---|---|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
        for (const Row& row : r.rows) {
            if (row.family != family) continue;
            const Counts& k = row.counts;
            const bool exact = row.precision == "exact";
            m << "| " << row.scenario << " | " << row.method << " | " << row.precision << " | "
              << fmt("%.1f", row.ns_per_test) << " | " << k.cases << " | " << count_cell(k.false_miss, k.cases)
              << " | " << count_cell(k.false_hit, k.cases) << " | "
              << (row.mesh ? count_cell(k.leak, k.cases) : "—") << " | "
              << (row.mesh ? count_cell(k.double_hit, k.cases) : "—") << " | "
              << (exact ? "0" : ulps_cell(k.median_ulps)) << " | " << (exact ? "0" : ulps_cell(k.max_ulps))
              << " |\n";
        }
        m << "<!-- end table -->\n";
    };

    using F = long Counts::*;
    const F leak = &Counts::leak, fmiss = &Counts::false_miss, fhit = &Counts::false_hit;
    m << "\n## Triangles\n\n";
    if (!svg.empty()) m << "![speed against wrong decisions, triangles](" << svg << "/triangles.svg)\n";
    table("triangle");
    m << "\n**Reading.**\n\n"
      << "- *Why float Cramer leaks at edges.* A ray exactly through a shared edge has barycentric weight 0 "
         "for that edge in both faces. Cramer computes it in each face from that face's own determinants "
         "(its own `a - b`, `a - c`, `a - o`), rounded differently, so one face may see a tiny negative value "
         "and the other one too: the ray falls between them. Float Cramer leaks on "
      << say(r, "through-edge", "Cramer", "float", leak) << " exactly through an edge and "
      << say(r, "through-vertex", "Cramer", "float", leak) << " through a vertex; Moeller-Trumbore "
      << say(r, "through-edge", "Moeller-Trumbore", "float", leak) << " and "
      << say(r, "through-vertex", "Moeller-Trumbore", "float", leak)
      << ". Double makes the gap narrower, not closed: Cramer double leaks on "
      << say(r, "through-edge", "Cramer", "double", leak) << " and "
      << say(r, "through-vertex", "Cramer", "double", leak) << ".\n"
      << "- *Why the watertight test does not.* It moves the ray to the z axis and decides with 2D edge "
         "functions that depend only on the edge's two vertices, so the two faces of an edge compute the same "
         "products and get exactly negated values (exact zeros are recomputed in higher precision). Watertight "
         "float leaks on " << say(r, "through-edge", "watertight", "float", leak) << " and "
      << say(r, "through-vertex", "watertight", "float", leak) << ", and on "
      << say(r, "offset-1e5", "watertight", "float", leak) << " at offset 1e5, at "
      << say_ns(r, "through-edge", "watertight", "float") << " ns per test against "
      << say_ns(r, "through-edge", "Cramer", "float") << " for Cramer.\n"
      << "- *Why FMA contraction matters.* With `-ffp-contract=fast` (and an FMA unit) the compiler may turn "
         "`x*y - z*w` into `fma(x, y, -(z*w))`: one rounding of the first product is skipped, but not of the "
         "second, so the neighbour's `z*w - x*y` is no longer the exact negation, and the argument above breaks. "
         "The row *watertight FMA* is the same code with the three edge functions written that way: it leaks on "
      << say(r, "through-edge", "watertight FMA", "float", leak) << " in float and "
      << say(r, "through-edge", "watertight FMA", "double", leak)
      << " in double exactly through an edge (float Cramer: " << say(r, "through-edge", "Cramer", "float", leak)
      << "; its time is that of a library call: "
         "the default x86-64 target has no FMA instruction). The project compiles everything with "
         "`-ffp-contract=off`; the test `Accuracy.Build.ContractionIsOff` proves it on this build (see the last "
         "section).\n"
      << "- *Far from the origin.* At 1e5 floats are 2^-7 apart, so the meshes themselves are stored that "
         "coarsely; inside the tests, differences of nearby coordinates are then exact (Sterbenz's lemma), so "
         "moving the camera along costs little more: float Cramer leaks on "
      << say(r, "offset-1e5", "Cramer", "float", leak) << " at 1e5 and "
      << say(r, "offset-1e3", "Cramer", "float", leak) << " at 1e3, with a median t error of "
      << say_ulps(r, "offset-1e5", "Cramer", "float", false) << " ulps (max "
      << say_ulps(r, "offset-1e5", "Cramer", "float", true)
      << "). The damage is done when positions are stored: keep them relative to a nearby origin, or in double.\n"
      << "- *Grazing rays and slivers* are ill-conditioned for every method: a rounding error across the "
         "ray moves the hit point along the plane by (rounding)/cos, and a sliver is thinner than that. "
         "Watertight float wrongly misses "
      << say(r, "sliver", "watertight", "float", fmiss) << " on slivers and "
      << say(r, "grazing", "watertight", "float", fmiss) << " on grazing rays (Cramer float: "
      << say(r, "sliver", "Cramer", "float", fmiss) << " and " << say(r, "grazing", "Cramer", "float", fmiss)
      << "). Watertight means no gaps between neighbours, not exact answers for one triangle: the 2D test is "
         "exact only for the rounded, sheared vertices. Double removes these: "
      << say(r, "sliver", "watertight", "double", fmiss) << " and "
      << say(r, "grazing", "watertight", "double", fmiss) << ".\n";

    m << "\n## Spheres\n\n";
    if (!svg.empty()) m << "![speed against wrong decisions, spheres](" << svg << "/spheres.svg)\n";
    table("sphere");
    m << "\n**Reading.**\n\n"
      << "- *Why the far sphere fails without the reformulation.* For a sphere of radius r at distance D the "
         "textbook discriminant b^2 - 4ac subtracts two numbers of size D^4 to get one of size r^2 D^2: at "
         "D = 1e4 and r = 1 in float the difference is below the rounding of either term, and the answer is "
         "noise. Textbook float gets "
      << say(r, "far-small", "textbook", "float", fhit) << " false hits and "
      << say(r, "far-small", "textbook", "float", fmiss)
      << " false misses although every ray passes at least 5% of the radius inside or outside the silhouette. "
         "The q-form fixes the roots, not the discriminant: "
      << say(r, "far-small", "q-form", "float", fhit) << " false hits. Ray Tracing Gems' form r^2 - |l|^2, "
         "with l the vector from the centre to the closest point of the line, subtracts numbers of size r^2 "
         "instead: " << say(r, "far-small", "RTG ch. 7", "float", fhit) << " false hits and "
      << say(r, "far-small", "RTG ch. 7", "float", fmiss) << " false misses, at "
      << say_ns(r, "far-small", "RTG ch. 7", "float") << " ns against "
      << say_ns(r, "far-small", "textbook", "float") << " ns.\n"
      << "- *Large sphere seen from just above.* c = |o - c|^2 - r^2 cancels when the origin is close to a "
         "big sphere, for every form; the textbook root (-b - sqrt(disc)) / 2a cancels a second time. Median t "
         "error in float: textbook " << say_ulps(r, "large-near", "textbook", "float", false) << " ulps, q-form "
      << say_ulps(r, "large-near", "q-form", "float", false) << ", RTG "
      << say_ulps(r, "large-near", "RTG ch. 7", "float", false) << " (max "
      << say_ulps(r, "large-near", "textbook", "float", true) << ", "
      << say_ulps(r, "large-near", "q-form", "float", true) << ", "
      << say_ulps(r, "large-near", "RTG ch. 7", "float", true) << ").\n"
      << "- *Near-tangent rays* are a tie within rounding for every method (sphere-grazing): RTG float "
      << say(r, "sphere-grazing", "RTG ch. 7", "float", fhit) << " false hits, textbook float "
      << say(r, "sphere-grazing", "textbook", "float", fhit) << ".\n";

    m << "\n## Self-intersection\n\n"
         "A ray hits a triangle (watertight test), and a new ray leaves the hit point in a random direction "
         "on the same side (cosine to the normal from 1e-3 to 1). *fixed tmin*: origin o + t d, accepted "
         "t > 1e-4. *normal offset*: origin o + t d + 1e-4 n. *robust offset*: the hit point rebuilt from the "
         "barycentrics with its rounding-error bound, moved past that bound along the normal and rounded "
         "away (pbrt-v4's OffsetRayOrigin; the bench's copy in `tools/bench/methods.h`, the renderer's in "
         "`framework/geometry/offset.h`). Self-hit: the new ray hits the triangle it left. Missed occluder: "
         "a larger copy of the triangle lifted by a gap of 1e-2 or 1e-4 times the scene scale is not hit "
         "(rays with cosine >= 0.3).\n\n"
         "<!-- table:self -->\n| strategy | precision | scale | rays | self-hits | occluder rays | missed, gap 1e-2 | "
         "missed, gap 1e-4 |\n|---|---|--:|--:|--:|--:|--:|--:|\n";
    for (const SelfRow& x : r.self)
        m << "| " << x.strategy << " | " << x.precision << " | " << fmt("%g", x.scale) << " | " << x.rays
          << " | " << self_cell(x.self_hits, x.rays) << " | " << x.occluder_rays << " | "
          << self_cell(x.missed_gap_1e2, x.occluder_rays) << " | " << self_cell(x.missed_gap_1e4, x.occluder_rays)
          << " |\n";
    m << "<!-- end table -->\n\n**Reading.** A fixed epsilon is a length, so it is right at one scale only. "
         "At scale 1e4 in float the hit point is off the surface by about one float spacing there (0.001), "
         "more than 1e-4: fixed tmin self-hits on ";
    {
        const SelfRow* f = find_self(r, "fixed tmin", "float", 1e4);
        const SelfRow* nf = find_self(r, "normal offset", "float", 1e4);
        const SelfRow* f1 = find_self(r, "fixed tmin", "float", 1);
        const SelfRow* n1 = find_self(r, "normal offset", "float", 1);
        const SelfRow* rb = find_self(r, "robust offset", "float", 1e4);
        m << (f ? count_cell(f->self_hits, f->rays) : "n/a") << " of the rays and the normal offset on "
          << (nf ? count_cell(nf->self_hits, nf->rays) : "n/a")
          << ". At scale 1 the same 1e-4 is as large as a gap of 1e-4: the normal offset starts the shadow ray "
             "at or beyond such an occluder and misses "
          << (n1 ? count_cell(n1->missed_gap_1e4, n1->occluder_rays) : "n/a") << " of them, fixed tmin "
          << (f1 ? count_cell(f1->missed_gap_1e4, f1->occluder_rays) : "n/a")
          << " (light leaks through thin objects). Fixed tmin also self-hits at scale 1 on "
          << (f1 ? count_cell(f1->self_hits, f1->rays) : "n/a")
          << " of the rays: grazing rays travel rounding/cos before they clear the surface. The robust offset "
             "scales with the "
             "numbers themselves: "
          << (rb ? count_cell(rb->self_hits, rb->rays) : "n/a") << " self-hits at scale 1e4, and "
          << (rb ? count_cell(rb->missed_gap_1e4, rb->occluder_rays) : "n/a") << " missed occluders at gap 1e-4.\n";
    }

    if (!r.render.empty()) {
        m << "\n## Rendering: what each millisecond buys\n\n";
        if (!svg.empty()) m << "![time against image error](" << svg << "/render.svg)\n\n";
        m << "The " << r.render_scenes.size() << " stage 02 scenes (";
        for (std::size_t i = 0; i < r.render_scenes.size(); ++i) m << (i ? ", " : "") << r.render_scenes[i];
        m << ") in normals mode at 1/" << c.render_divisor << " of their size, with the bench's methods "
             "(spheres: RTG form), one thread. Time is summed over the scenes; errors are means over them. "
             "RMSE is in 8-bit units against a 256-sample (16x16) double reference; the last column is the share "
             "of pixels off by more than 2/255 from the double pixel-centre image (the precision error alone).\n\n"
             "<!-- table:render -->\n| series | samples per pixel | ms | RMSE vs 256 spp | pixels off the double "
             "centre image |\n|---|--:|--:|--:|--:|\n";
        for (const RenderPoint& p : r.render)
            m << "| " << p.series << " | " << p.spp << " | " << fmt("%.1f", p.ms) << " | " << fmt("%.3f", p.rmse)
              << " | " << (p.spp == 1 ? fmt("%.3f", p.centre_diff) + "%" : "—") << " |\n";
        const RenderPoint* wf = nullptr;
        const RenderPoint* wd = nullptr;
        const RenderPoint* s4 = nullptr;
        for (const RenderPoint& p : r.render) {
            if (p.series == "watertight float") wf = &p;
            if (p.series == "watertight double") wd = &p;
            if (p.series == "supersampling" && p.spp == 4) s4 = &p;
        }
        m << "<!-- end table -->\n\n**Reading.** ";
        if (wf && wd && s4)
            m << "Float takes " << fmt("%.1f", wf->ms) << " ms, double " << fmt("%.1f", wd->ms)
              << " ms; float changes " << fmt("%.3f", wf->centre_diff)
              << "% of the pixels of the double image, and the RMSE against the converged image moves from "
              << fmt("%.2f", wf->rmse) << " to " << fmt("%.2f", wd->rmse)
              << ". Spending " << fmt("%.1f", s4->ms - wf->ms) << " ms on 4 samples per pixel instead lowers it to "
              << fmt("%.2f", s4->rmse)
              << ". At these scales the image error is aliasing, not rounding: precision buys robustness "
                 "(the tables above), samples buy image quality.\n";
    }

    m << "\n## Contraction is off\n\n"
         "`Accuracy.Build.ContractionIsOff` computes `a*b + c` in a separately compiled file of the project "
         "for a = 1 + 2^-30, b = 1 - 2^-30, c = -1 (and the float analogue with 2^-13). Rounded twice the result "
         "is 0; fused it is -2^-60. The test asserts 0, so it fails if the project is ever built with contraction "
         "on a machine with FMA.\n";
    return m.str();
}

// ---------------------------------------------------------------------------------------------
// Reading the counts back.

namespace {
std::vector<std::string> cells(const std::string& line) {
    std::vector<std::string> out;
    std::string cur;
    for (std::size_t i = 1; i < line.size(); ++i) {
        if (line[i] == '|') {
            const auto b = cur.find_first_not_of(' '), e = cur.find_last_not_of(' ');
            out.push_back(b == std::string::npos ? "" : cur.substr(b, e - b + 1));
            cur.clear();
        } else {
            cur += line[i];
        }
    }
    return out;
}
long leading(const std::string& cell) { return cell.empty() || !std::isdigit(cell[0]) ? 0 : std::stol(cell); }
}  // namespace

ReportCounts parse_report(const std::string& md) {
    ReportCounts out;
    const auto cfg = md.find("config: seed=");
    if (cfg == std::string::npos) throw std::runtime_error("report has no config line");
    std::sscanf(md.c_str() + cfg, "config: seed=%lu cases=%d", &out.seed, &out.cases);
    std::istringstream in(md);
    std::string line, section;
    while (std::getline(in, line)) {
        if (line.rfind("<!-- table:", 0) == 0) {
            section = line.substr(11, line.find(' ', 11) - 11);
            std::getline(in, line);  // header
            std::getline(in, line);  // rule
            continue;
        }
        if (line.rfind("<!-- end table", 0) == 0) section.clear();
        if (section.empty() || line.empty() || line[0] != '|') continue;
        const auto c = cells(line);
        if ((section == "triangle" || section == "sphere") && c.size() >= 11) {
            Row row;
            row.family = section;
            row.scenario = c[0], row.method = c[1], row.precision = c[2];
            row.counts.cases = leading(c[4]);
            row.counts.false_miss = leading(c[5]);
            row.counts.false_hit = leading(c[6]);
            row.counts.leak = leading(c[7]);
            row.counts.double_hit = leading(c[8]);
            out.rows.push_back(row);
        } else if (section == "self" && c.size() >= 8) {
            SelfRow s;
            s.strategy = c[0], s.precision = c[1], s.scale = std::stod(c[2]);
            s.rays = leading(c[3]), s.self_hits = leading(c[4]), s.occluder_rays = leading(c[5]);
            s.missed_gap_1e2 = leading(c[6]), s.missed_gap_1e4 = leading(c[7]);
            out.self.push_back(s);
        }
    }
    return out;
}

}  // namespace rt::bench
