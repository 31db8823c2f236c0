// The accuracy report's SVG plots: speed against wrong decisions (triangles, spheres) and
// rendering time against image error, as small scatter plots with log axes.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "bench/accuracy.h"
#include "bench/report_format.h"

namespace rt::bench {
namespace {

using detail::fmt;

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
            std::find(keys.begin(), keys.end(), std::make_pair(row.method, row.precision)) ==
                keys.end())
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
            if (row.family != family || row.method != method || row.precision != precision)
                continue;
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
    std::string color;
};

// The ranges of two log axes: whole decades around the points, which are first clamped to
// y_floor and x >= 1e-3 (a log axis has no zero).
struct LogRanges {
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
};

LogRanges log_ranges(std::vector<PlotPoint>& pts, double y_floor) {
    for (auto& p : pts) {
        p.y = std::max(p.y, y_floor);
        p.x = std::max(p.x, 1e-3);
    }
    LogRanges r;
    for (const auto& p : pts) {
        r.x0 = std::min(r.x0, p.x);
        r.x1 = std::max(r.x1, p.x);
        r.y0 = std::min(r.y0, p.y);
        r.y1 = std::max(r.y1, p.y);
    }
    r.x0 = std::pow(10, std::floor(std::log10(r.x0)));
    r.x1 = std::pow(10, std::ceil(std::log10(r.x1)));
    r.y0 = std::pow(10, std::floor(std::log10(r.y0)));
    r.y1 = std::pow(10, std::ceil(std::log10(r.y1)));
    if (r.x1 <= r.x0) r.x1 = r.x0 * 10;
    if (r.y1 <= r.y0) r.y1 = r.y0 * 10;
    return r;
}

std::string svg_plot(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                     std::vector<PlotPoint> pts, double y_floor, const std::string& note) {
    const double W = 640, H = 400, L = 70, R = 20, T = 40, B = 55;
    const auto [x0, x1, y0, y1] = log_ranges(pts, y_floor);
    auto X = [&](double x) {
        return L +
               (W - L - R) * (std::log10(x) - std::log10(x0)) / (std::log10(x1) - std::log10(x0));
    };
    auto Y = [&](double y) {
        return H - B -
               (H - T - B) * (std::log10(y) - std::log10(y0)) / (std::log10(y1) - std::log10(y0));
    };
    std::ostringstream s;
    s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n";
    s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    s << "<text x=\"" << W / 2 << "\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">" << title
      << "</text>\n";
    for (double v = x0; v <= x1 * 1.0001; v *= 10) {
        s << "<line x1=\"" << fmt("%.1f", X(v)) << "\" y1=\"" << T << "\" x2=\""
          << fmt("%.1f", X(v)) << "\" y2=\"" << H - B << "\" stroke=\"#ddd\"/>\n";
        s << "<text x=\"" << fmt("%.1f", X(v)) << "\" y=\"" << H - B + 15
          << "\" text-anchor=\"middle\">" << fmt("%g", v) << "</text>\n";
    }
    for (double v = y0; v <= y1 * 1.0001; v *= 10) {
        s << "<line x1=\"" << L << "\" y1=\"" << fmt("%.1f", Y(v)) << "\" x2=\"" << W - R
          << "\" y2=\"" << fmt("%.1f", Y(v)) << "\" stroke=\"#ddd\"/>\n";
        s << "<text x=\"" << L - 5 << "\" y=\"" << fmt("%.1f", Y(v) + 4)
          << "\" text-anchor=\"end\">" << fmt("%g", v) << "</text>\n";
    }
    s << "<rect x=\"" << L << "\" y=\"" << T << "\" width=\"" << W - L - R << "\" height=\""
      << H - T - B << "\" fill=\"none\" stroke=\"black\"/>\n";
    s << "<text x=\"" << (L + W - R) / 2 << "\" y=\"" << H - 22 << "\" text-anchor=\"middle\">"
      << xlabel << "</text>\n";
    s << "<text x=\"15\" y=\"" << (T + H - B) / 2
      << "\" text-anchor=\"middle\" transform=\"rotate(-90 15 " << (T + H - B) / 2 << ")\">"
      << ylabel << "</text>\n";
    if (!note.empty())
        s << "<text x=\"" << L << "\" y=\"" << H - 6 << "\" font-size=\"10\" fill=\"#555\">" << note
          << "</text>\n";
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
    // otherwise write their names over each other). Unlabelled points (the later points of a
    // labelled series) get neither.
    int legend = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const PlotPoint& p = pts[i];
        s << "<circle cx=\"" << fmt("%.1f", X(p.x)) << "\" cy=\"" << fmt("%.1f", Y(p.y))
          << "\" r=\"4\" fill=\"" << p.color << "\"/>\n";
        if (p.label.empty()) continue;
        ++legend;
        s << "<text x=\"" << fmt("%.1f", X(p.x) + 5) << "\" y=\"" << fmt("%.1f", Y(p.y) - 5)
          << "\" font-size=\"10\">" << legend << "</text>\n";
        const double lx = W - R - 175, ly = T + 14 + 13 * double(legend - 1);
        s << "<circle cx=\"" << lx << "\" cy=\"" << fmt("%.1f", ly - 4) << "\" r=\"4\" fill=\""
          << p.color << "\"/>\n<text x=\"" << lx + 8 << "\" y=\"" << fmt("%.1f", ly) << "\">"
          << legend << "  " << p.label << "</text>\n";
    }
    s << "</svg>\n";
    return s.str();
}

std::string color_of(const std::string& label) {
    if (label.find("CGAL") != std::string::npos) return "#000000";
    if (label.find("float") != std::string::npos) return "#d62728";
    return "#1f77b4";
}

std::vector<PlotPoint> family_points(const AccuracyResults& r, const std::string& family) {
    std::vector<PlotPoint> pts;
    for (const Summary& s : summarize(r, family))
        pts.push_back({s.label, s.ns, s.wrong_pct, "", color_of(s.label)});
    return pts;
}

std::string render_svg(const AccuracyResults& r) {
    std::vector<PlotPoint> pts;
    for (const RenderPoint& p : r.render)
        if (p.series == "supersampling")
            pts.push_back({std::to_string(p.spp) + " spp", p.ms, p.rmse, "ss", "#2ca02c"});
    for (const RenderPoint& p : r.render)
        if (p.series == "watertight double")
            pts.push_back({"double, 1 spp", p.ms, p.rmse, "", "#1f77b4"});
    return svg_plot(
        "Rendering: time against image error", "ms for all scenes (one thread)",
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
    put("triangles.svg",
        svg_plot(
            "Triangles: speed against wrong decisions", "ns per ray-triangle test",
            "wrong decisions, % of rays", family_points(r, "triangle"), kFloor,
            "wrong = false miss + false hit + leak over all triangle scenarios; 0 drawn at 0.001"));
    put("spheres.svg",
        svg_plot("Spheres: speed against wrong decisions", "ns per ray-sphere test",
                 "wrong decisions, % of rays", family_points(r, "sphere"), kFloor,
                 "wrong = false miss + false hit over all sphere scenarios; 0 drawn at 0.001"));
    if (!r.render.empty()) put("render.svg", render_svg(r));
    if (!r.sampling.points.empty()) {
        static const char* const colors[] = {"#1f77b4", "#ff7f0e", "#2ca02c",
                                             "#d62728", "#9467bd", "#8c564b"};
        std::vector<PlotPoint> pts;
        std::vector<std::string> scenes;
        double top = 0;
        for (const SamplingPoint& p : r.sampling.points) {
            if (scenes.empty() || scenes.back() != p.scene) scenes.push_back(p.scene);
            pts.push_back({p.spp == 1 ? p.scene : "", double(p.spp), p.rmse, p.scene,
                           colors[(scenes.size() - 1) % 6]});
            top = std::max(top, p.rmse);
        }
        // The 1/sqrt(N) line from the largest error at 1 sample.
        for (int spp : {1, 256})
            pts.push_back({spp == 256 ? "1/sqrt(N)" : "", double(spp), top / std::sqrt(double(spp)),
                           "slope", "#000000"});
        put("sampling.svg",
            svg_plot("Stage 10: error against samples per pixel", "samples per pixel",
                     "RMSE vs 1024 spp (8-bit units)", pts, 1e-3,
                     "one line per scene; black: slope -1/2 (time grows as the samples)"));
    }
    if (!r.mis.points.empty()) {
        std::vector<PlotPoint> pts;
        for (const MisPoint& p : r.mis.points) {
            const char* color = p.strategy == "MIS"   ? "#2ca02c"
                                : p.strategy == "NEE" ? "#1f77b4"
                                                      : "#d62728";
            pts.push_back({p.spp == 1 ? p.strategy : "", p.ms, p.rmse, p.strategy, color});
        }
        put("mis.svg", svg_plot("Stage 11, Veach's scene: error against time", "ms for the image",
                                "RMSE vs 2048 spp (8-bit units)", pts, 1e-3,
                                "blue: NEE only; red: BSDF sampling only; green: MIS (power); "
                                "points at 1, 4, 16, 64, 256 spp"));
    }
    if (!r.texture.empty()) {
        std::vector<PlotPoint> pts;
        for (const TexturePoint& p : r.texture)
            pts.push_back({p.filter, p.ms, p.rmse, "",
                           p.filter.find("OIIO") != std::string::npos ? "#2ca02c" : "#d62728"});
        put("textures.svg",
            svg_plot(
                "Texture filtering: time against image error", "ms for the image (one thread)",
                "RMSE vs 16x16 supersampling (8-bit units)", pts, 1e-3,
                "red: one nearest or bilinear lookup per pixel; green: OpenImageIO mip-mapped"));
    }
}

}  // namespace rt::bench
