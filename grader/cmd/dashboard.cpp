// The class dashboard's page (cmd/dashboard.h): OUT/index.html, self-contained but for the
// failing images and reports it links, which sit beside it in OUT.
#include "cmd/dashboard.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>
#include <string_view>

#include "grading/report.h"
#include "util.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

const char* const kDashboardStyle =
    ".hist{display:inline-block;margin:0 1em 1em 0;padding:.5em;background:#fff;"
    "border:1px solid #ccc}.bar{fill:#4a7ebb}.bar.full{fill:#080}svg text{font-size:11px;"
    "fill:#222}.rate{display:inline-block;height:10px;background:#b00;vertical-align:middle}"
    ".thumb{width:128px;image-rendering:pixelated;border:1px solid #888}td.num{text-align:right}";

std::string format(const char* how, double v) {
    char text[64];
    std::snprintf(text, sizeof text, how, v);
    return text;
}

std::string rate_cell(int failed, int graded) {
    const double rate = graded ? 100.0 * failed / graded : 0;
    return "<td class=\"num\">" + std::to_string(failed) + " of " + std::to_string(graded) +
           "</td><td><span class=\"rate\" style=\"width:" + format("%.0f", rate) + "px\"></span> " +
           format("%.0f", rate) + "%</td>";
}

// One stage's scores as an SVG bar chart: a bar per bin with its count above, the bin's lowest
// percentage below; the full-marks bin in green.
std::string histogram_svg(const StageHistogram& h) {
    constexpr int kBar = 24, kGap = 4, kTall = 110, kTop = 16, kBelow = 18;
    const int width = kHistogramBins * (kBar + kGap) + kGap,
              most = std::max(1, *std::max_element(h.counts.begin(), h.counts.end()));
    std::string svg = "<svg width=\"" + std::to_string(width) + "\" height=\"" +
                      std::to_string(kTop + kTall + kBelow) + "\" role=\"img\">";
    for (int bin = 0; bin < kHistogramBins; ++bin) {
        const int count = h.counts[std::size_t(bin)];
        const int tall = count ? std::max(2, count * kTall / most) : 0;
        const int x = kGap + bin * (kBar + kGap), y = kTop + kTall - tall;
        const bool full = bin == kHistogramBins - 1;
        const std::string range =
            full ? "100%" : std::to_string(bin * 10) + "-" + std::to_string(bin * 10 + 9) + "%";
        svg += "<rect class=\"bar" + std::string(full ? " full" : "") + "\" data-bin=\"" +
               std::to_string(bin) + "\" data-count=\"" + std::to_string(count) + "\" x=\"" +
               std::to_string(x) + "\" y=\"" + std::to_string(y) + "\" width=\"" +
               std::to_string(kBar) + "\" height=\"" + std::to_string(tall) + "\"><title>" +
               std::to_string(count) + " at " + range + "</title></rect>";
        const std::string mid = std::to_string(x + kBar / 2);
        if (count)
            svg += "<text x=\"" + mid + "\" y=\"" + std::to_string(y - 3) +
                   "\" text-anchor=\"middle\">" + std::to_string(count) + "</text>";
        svg += "<text x=\"" + mid + "\" y=\"" + std::to_string(kTop + kTall + 13) +
               "\" text-anchor=\"middle\">" + std::to_string(bin * 10) + "</text>";
    }
    return svg + "</svg>";
}

std::string stages_html(const ClassResults& results) {
    std::string h =
        "<h2>Scores per stage</h2>\n<p>Submissions per 10% of the stage's points; "
        "the last, green bar is full marks.</p>\n";
    for (const auto& s : stage_histograms(results)) {
        char title[160];
        std::snprintf(title, sizeof title, "Stage %02d: %d graded, mean %.0f%%, median %.0f%%",
                      s.stage, s.graded, s.mean, s.median);
        h += "<div class=\"hist\" id=\"stage" + two_digits(s.stage) + "\"><b>" + title +
             "</b><br>" + histogram_svg(s) + "</div>\n";
    }
    return h;
}

// A test's handout sections, most named first: what to go over again with the class.
std::string handout_links(const TestFailures& f, const std::string& base) {
    std::string h;
    for (const auto& [section, count] : f.hints) {
        if (!h.empty()) h += "<br>";
        h += "<a href=\"" + html_escape(base + section) + "\">" + html_escape(section) + "</a>";
        if (count != f.failed) h += " (" + std::to_string(count) + ")";
    }
    return h;
}

std::string tests_html(const ClassResults& results, const std::string& base) {
    std::string rows;
    int clean = 0;
    for (const auto& f : test_failures(results, false)) {
        if (f.failed == 0) {
            ++clean;
            continue;
        }
        rows += "<tr><td>" + html_escape(f.name) + "</td>" + rate_cell(f.failed, f.graded) +
                "<td>" + handout_links(f, base) + "</td></tr>\n";
    }
    std::string h = "<h2>Tests by failure rate</h2>\n";
    if (!rows.empty())
        h += "<table><tr><th>test</th><th>failed</th><th>rate</th><th>handout sections its "
             "output names (failures naming it)</th></tr>\n" +
             rows + "</table>\n";
    return h + "<p>" + std::to_string(clean) + " tests passed by every submission.</p>\n";
}

std::string scenes_html(const ClassResults& results) {
    std::string rows;
    int clean = 0;
    for (const auto& f : test_failures(results, true)) {
        if (f.failed == 0) {
            ++clean;
            continue;
        }
        rows += "<tr><td>" + html_escape(f.name) + "</td>" + rate_cell(f.failed, f.graded) + "<td>";
        if (f.common_count > 0)
            rows += "<img class=\"thumb\" alt=\"most common failing image\" src=\"" +
                    html_escape(f.common_render) + "\"><br>" + std::to_string(f.common_count) +
                    " of " + std::to_string(f.failed) + " failing renders";
        else
            rows += "(no image kept: the render failed)";
        rows += "</td></tr>\n";
    }
    if (rows.empty() && clean == 0) return "";
    std::string h = "<h2>Image tests by failure rate</h2>\n";
    if (!rows.empty())
        h += "<table><tr><th>scene</th><th>failed</th><th>rate</th><th>most common failing "
             "image (identical renders)</th></tr>\n" +
             rows + "</table>\n";
    return h + "<p>" + std::to_string(clean) + " image tests passed by every submission.</p>\n";
}

std::string run_times_html(const ClassResults& results) {
    const auto [min, median, max] = run_time_summary(results);
    return "<p>Run time per submission: min " + format("%g", min) + " s, median " +
           format("%g", median) + " s, max " + format("%g", max) + " s.</p>\n";
}

std::string submissions_html(const ClassResults& results) {
    std::set<int> stages;
    for (const auto& s : results.submissions)
        for (const auto& [stage, points] : s.stages) stages.insert(stage);
    const bool named = std::any_of(results.submissions.begin(), results.submissions.end(),
                                   [](const DashSubmission& s) { return !s.students.empty(); });
    std::string h = "<h2>Submissions</h2>\n" + run_times_html(results) + "<table><tr>" +
                    (named ? "<th>students</th>" : "") +
                    "<th>submission (its report)</th><th>points</th>";
    for (const int n : stages) h += "<th>stage " + two_digits(n) + "</th>";
    h += "<th>failed tests</th><th>seconds</th></tr>\n";
    for (const auto& s : results.submissions) {
        const auto failed = std::count_if(s.tests.begin(), s.tests.end(),
                                          [](const DashTest& t) { return !t.passed; });
        h += "<tr>" + (named ? "<td>" + html_escape(s.students) + "</td>" : std::string()) +
             "<td><a href=\"" + html_escape(s.name) + "/report.html\">" + html_escape(s.name) +
             "</a></td><td class=\"num\">" + format("%g", s.score) + " / " +
             format("%g", s.max_score) + "</td>";
        for (const int n : stages) {
            const auto it = s.stages.find(n);
            h += "<td class=\"num\">" +
                 (it == s.stages.end() ? std::string("-") : format("%g", it->second.first)) +
                 "</td>";
        }
        h += "<td class=\"num\">" + std::to_string(failed) + "</td><td class=\"num\">" +
             format("%g", s.seconds) + "</td></tr>\n";
    }
    return h + "</table>\n";
}

std::string problems_html(const ClassResults& results) {
    if (results.problems.empty()) return "";
    std::string h = "<pre class=\"note\">Left out of this page:\n";
    for (const auto& p : results.problems) h += html_escape(p) + "\n";
    return h + "</pre>\n";
}

}  // namespace

int write_dashboard(const fs::path& out, const std::string& handout_base, std::ostream& log) {
    const ClassResults results = read_class_results(out, log);
    // Not a batch's folder (a mistyped path): leave it as it is.
    if (results.submissions.empty()) return 0;
    std::string h =
        html_page_start("rt-grade: class dashboard", std::string(report_style()) + kDashboardStyle);
    h += "<h1>rt-grade: " + std::to_string(results.submissions.size()) + " submissions</h1>\n";
    h += "<p>Built from the results.json files in this folder; <code>rt-grade dashboard "
         "FOLDER</code> rebuilds it after a regrade. Scores for a gradebook: "
         "<a href=\"scores.csv\">scores.csv</a>.</p>\n";
    // The long list of tests last: the overview and every report's link stay near the top.
    h += problems_html(results) + stages_html(results) + submissions_html(results) +
         scenes_html(results) + tests_html(results, handout_base);
    h += kHtmlPageEnd;
    write_text_atomically(out / "index.html", h);
    return int(results.submissions.size());
}

void write_batch_dashboard(const fs::path& out, const std::string& handout_base,
                           std::ostream& log) {
    try {
        if (write_dashboard(out, handout_base, log) > 0)
            log << "dashboard: " << (out / "index.html").string() << "\n";
    } catch (const std::exception& e) {
        log << "rt-grade: warning: no dashboard (" << e.what() << ")\n";
    }
}

std::string file_url(const fs::path& dir) {
    std::string url = "file://";
    for (const char c : fs::absolute(dir).lexically_normal().string()) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u) || std::string_view("/._-~").find(c) != std::string_view::npos) {
            url += c;
        } else {
            char escaped[4];
            std::snprintf(escaped, sizeof escaped, "%%%02X", u);
            url += escaped;
        }
    }
    return url.ends_with('/') ? url : url + "/";
}

}  // namespace rt::grader
