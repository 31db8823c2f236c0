// The accuracy report as data: the CSV of every row, and parse_report, which reads the counts
// back from the markdown for the consistency test (Report.CountsMatchAFreshRun).
#include <cctype>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "bench/accuracy.h"
#include "bench/mis_strategies.h"
#include "bench/sampling_error.h"

namespace rt::bench {

double rmse_slope(const std::vector<SamplingPoint>& points, const std::string& scene) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const SamplingPoint& p : points) {
        if (p.scene != scene || !(p.rmse > 0)) continue;
        const double x = std::log(double(p.spp)), y = std::log(p.rmse);
        n += 1;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    return n < 2 ? 0 : (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

double rmse_at_time(const std::vector<MisPoint>& points, const std::string& strategy, double ms) {
    std::vector<const MisPoint*> line;
    for (const MisPoint& p : points)
        if (p.strategy == strategy && p.ms > 0 && p.rmse > 0) line.push_back(&p);
    if (line.empty()) return -1;
    if (ms <= line.front()->ms) return line.front()->rmse;
    for (std::size_t i = 1; i < line.size(); ++i) {
        const MisPoint &a = *line[i - 1], &b = *line[i];
        if (ms > b.ms) continue;
        const double t = std::log(ms / a.ms) / std::log(b.ms / a.ms);
        return std::exp(std::log(a.rmse) + t * std::log(b.rmse / a.rmse));
    }
    return line.back()->rmse;
}

std::string csv_report(const AccuracyResults& r) {
    std::ostringstream s;
    s << "section,scenario,method,precision,ns_per_test,rays,tests,false_miss,false_hit,leak,"
         "double_hit,"
         "median_ulps,max_ulps\n";
    for (const Row& row : r.rows)
        s << row.family << ',' << row.scenario << ',' << row.method << ',' << row.precision << ','
          << row.ns_per_test << ',' << row.counts.cases << ',' << row.counts.tests << ','
          << row.counts.false_miss << ',' << row.counts.false_hit << ',' << row.counts.leak << ','
          << row.counts.double_hit << ',' << row.counts.median_ulps << ',' << row.counts.max_ulps
          << '\n';
    s << "\nsection,strategy,precision,scale,rays,self_hits,occluder_rays,missed_gap_1e-2,missed_"
         "gap_1e-4\n";
    for (const SelfRow& x : r.self)
        s << "self," << x.strategy << ',' << x.precision << ',' << x.scale << ',' << x.rays << ','
          << x.self_hits << ',' << x.occluder_rays << ',' << x.missed_gap_1e2 << ','
          << x.missed_gap_1e4 << '\n';
    s << "\nsection,series,spp,ms,rmse,center_diff_percent\n";
    for (const RenderPoint& p : r.render)
        s << "render," << p.series << ',' << p.spp << ',' << p.ms << ',' << p.rmse << ','
          << p.center_diff << '\n';
    return s.str();
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
long leading(const std::string& cell) {
    return cell.empty() || !std::isdigit(cell[0]) ? 0 : std::stol(cell);
}
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
            row.scenario = c[0];
            row.method = c[1];
            row.precision = c[2];
            row.counts.cases = leading(c[4]);
            row.counts.false_miss = leading(c[5]);
            row.counts.false_hit = leading(c[6]);
            row.counts.leak = leading(c[7]);
            row.counts.double_hit = leading(c[8]);
            out.rows.push_back(row);
        } else if (section == "self" && c.size() >= 8) {
            SelfRow s;
            s.strategy = c[0];
            s.precision = c[1];
            s.scale = std::stod(c[2]);
            s.rays = leading(c[3]);
            s.self_hits = leading(c[4]);
            s.occluder_rays = leading(c[5]);
            s.missed_gap_1e2 = leading(c[6]);
            s.missed_gap_1e4 = leading(c[7]);
            out.self.push_back(s);
        }
    }
    return out;
}

}  // namespace rt::bench
