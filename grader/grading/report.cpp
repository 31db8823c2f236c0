#include "grading/report.h"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "util.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

std::string points(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", std::round(v * 100) / 100);
    return text;
}

}  // namespace

void write_results_json(const Report& report, const fs::path& file) {
    GradescopeResults results;
    double score = 0;
    for (const ReportTest& t : report.tests) {
        results.tests.push_back({.name = t.name,
                                 .number = t.number,
                                 .passed = t.status == "passed",
                                 .score = t.score,
                                 .max_score = t.max_score,
                                 .output = t.output,
                                 .tags = t.tags,
                                 .visibility = t.visibility});
        score += t.score;
    }
    results.score = std::round(score * 100) / 100;
    results.execution_time = report.seconds;
    results.output = "Sandbox: " + report.isolation + "\n" + report.general;
    results.leaderboard = report.leaderboard;
    if (file.has_parent_path()) fs::create_directories(file.parent_path());
    write_text_atomically(file, results_json_text(results));
}

namespace {

const char* const kReportStyle =
    "body{font-family:sans-serif;margin:1.5em;background:#fafafa;color:#222}"
    "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:3px 8px;"
    "text-align:left;vertical-align:top}.passed{color:#080}.failed{color:#b00}"
    "pre{white-space:pre-wrap;margin:0;font-size:12px;max-width:70em;max-height:14em;"
    "overflow:auto}"
    ".scene{display:inline-block;margin:0 1em 1.5em 0;padding:.5em;background:#fff;"
    "border:1px solid #ccc;max-width:820px}.scene img{width:256px;image-rendering:pixelated;"
    "border:1px solid #888;margin-right:4px}.trio{display:flex}.trio div{text-align:center;"
    "font-size:12px}.note{background:#fff3cd;padding:.5em;border:1px solid #e0c070}";

// Every row has an anchor made from its test's name ("#Stage-02-Sphere.SmallSphereFarAway"), the
// same in every report, so a link to a test survives the next grading.
std::string anchor(const ReportTest& t) {
    std::string id = t.name;
    for (char& c : id)
        if (std::isspace(static_cast<unsigned char>(c))) c = '-';
    return html_escape(id);
}

// Failures first: what to fix, each with its first line of reason and a link to its row.
std::string failures_html(const Report& report) {
    std::string fails;
    int failed = 0;
    for (const auto& t : report.tests) {
        if (t.status == "passed") continue;
        ++failed;
        std::string first = t.output.substr(0, t.output.find('\n'));
        if (first.size() > 160) first = first.substr(0, 157) + "...";
        fails += "<tr><td><a href=\"#" + anchor(t) + "\">" + html_escape(t.name) + "</a></td><td>" +
                 points(t.score) + " / " + points(t.max_score) + "</td><td><code>" +
                 html_escape(first) + "</code></td></tr>\n";
    }
    if (failed == 0) return "<h2 class=\"passed\">Every test passes.</h2>\n";
    return "<h2 class=\"failed\">" + std::to_string(failed) + " failing test" +
           (failed == 1 ? "" : "s") +
           "</h2>\n<table><tr><th>test</th><th>points</th>"
           "<th>first line of the reason</th></tr>\n" +
           fails + "</table>\n";
}

// The table of one stage's tests (0: notes of no stage); empty when it has none.
std::string tests_table(const Report& report, int stage) {
    std::string rows;
    for (const auto& t : report.tests) {
        if (t.stage != stage) continue;
        const std::string cls = t.status == "passed" ? "passed" : "failed";
        rows += "<tr id=\"" + anchor(t) + "\"><td>" + html_escape(t.number) + "</td><td>" +
                html_escape(t.name) + "</td><td class=\"" + cls + "\">" + cls + "</td><td>" +
                points(t.score) + " / " + points(t.max_score) + "</td><td>" +
                html_escape(t.visibility) + "</td><td>";
        if (!t.output.empty())
            rows += "<details" + std::string(t.status == "passed" ? "" : " open") +
                    "><summary>output</summary><pre>" + html_escape(t.output) + "</pre></details>";
        rows += "</td></tr>\n";
    }
    if (rows.empty()) return std::string();
    return "<table><tr><th>#</th><th>test</th><th>status</th><th>points</th>"
           "<th>visibility</th><th>output</th></tr>\n" +
           rows + "</table>\n";
}

// A graded scene: its points, the student's image, the reference, the difference, the metric.
std::string scene_html(const ReportTest& t) {
    std::string h = "<div class=\"scene\"><b>" + html_escape(t.name) + "</b> <span class=\"" +
                    std::string(t.status == "passed" ? "passed" : "failed") + "\">" +
                    points(t.score) + " / " + points(t.max_score) + "</span><div class=\"trio\">";
    auto img = [&](const std::string& png, const char* label) {
        h += "<div>";
        if (png.empty())
            h += "<div style=\"width:256px;height:64px\">(no image)</div>";
        else
            h += "<img alt=\"" + std::string(label) + "\" src=\"data:image/png;base64," +
                 base64(png) + "\">";
        h += "<br>" + std::string(label) + "</div>";
    };
    img(t.student_png, "your image");
    img(t.reference_png, "reference");
    img(t.diff_png, "difference (red: yours brighter, blue: darker; full strength: failing pixel)");
    return h + "</div><pre>" + html_escape(t.metrics) + "</pre></div>\n";
}

// One stage: its title and points, its scenes, its tests.
std::string stage_html(const Report& report, const ReportStage& s) {
    double got = 0, max = 0;
    for (const auto& t : report.tests)
        if (t.stage == s.number) {
            got += t.score;
            max += t.max_score;
        }
    char title[300];
    std::snprintf(title, sizeof title, "Stage %02d: %s", s.number, s.title.c_str());
    std::string h =
        "<h2>" + html_escape(title) + " &mdash; " + points(got) + " / " + points(max) + "</h2>\n";
    for (const auto& t : report.tests)
        if (t.stage == s.number && t.is_scene) h += scene_html(t);
    return h + tests_table(report, s.number);
}

}  // namespace

const char* report_style() {
    return kReportStyle;
}

std::string render_png_name(const std::string& test_name) {
    std::string name = test_name;
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.') c = '-';
    return name + ".png";
}

void write_failing_renders(const Report& report, const fs::path& dir) {
    for (const auto& t : report.tests)
        if (t.is_scene && t.status != "passed" && !t.student_png.empty())
            write_text_atomically(dir / render_png_name(t.name), t.student_png);
}

void write_html_report(const Report& report, const fs::path& file) {
    double score = 0, max_score = 0;
    for (const auto& t : report.tests) {
        score += t.score;
        max_score += t.max_score;
    }
    std::string h = html_page_start("rt-grade report", kReportStyle);
    h += "<h1>rt-grade: " + points(score) + " / " + points(max_score) + " points</h1>\n";
    h += "<p>Sandbox: " + html_escape(report.isolation) + ". Graded in " + points(report.seconds) +
         " s.</p>\n";
    h += failures_html(report);
    if (!report.general.empty())
        h += "<pre class=\"note\">" + html_escape(report.general) + "</pre>\n";
    h += tests_table(report, 0);
    // The newest stage first: a student grading stage 10 reads stage 10, not stage 01.
    for (auto s = report.stages.rbegin(); s != report.stages.rend(); ++s)
        h += stage_html(report, *s);
    h += kHtmlPageEnd;
    if (file.has_parent_path()) fs::create_directories(file.parent_path());
    write_text_atomically(file, h);
}

void write_terminal_summary(const Report& report, std::ostream& out, bool reveal_hidden) {
    double score = 0, max_score = 0;
    std::vector<std::string> hints;
    for (const auto& t : report.tests) {
        if (t.stage == 0 && t.status != "passed") {
            out << t.name << ": FAILED\n" << t.output << "\n";
        }
    }
    for (const auto& s : report.stages) {
        double got = 0, max = 0;
        int hidden = 0;
        std::string failures;
        for (const auto& t : report.tests) {
            if (t.stage != s.number) continue;
            got += t.score;
            max += t.max_score;
            if (t.visibility != "visible" && !reveal_hidden) {
                ++hidden;
                continue;
            }
            if (t.status == "passed") continue;
            std::string first = t.output.substr(0, t.output.find('\n'));
            if (first.size() > 110) first = first.substr(0, 107) + "...";
            failures += "    " + t.name + " (" + points(t.score) + "/" + points(t.max_score) +
                        "): " + first + "\n";
            std::size_t p = 0;
            while ((p = t.output.find("Read the handout: ", p)) != std::string::npos) {
                const auto end = t.output.find('\n', p);
                const std::string hint = t.output.substr(p + 18, end - p - 18);
                if (std::find(hints.begin(), hints.end(), hint) == hints.end())
                    hints.push_back(hint);
                p = end;
            }
        }
        score += got;
        max_score += max;
        char line[300];
        std::snprintf(line, sizeof line, "Stage %02d %-28s %6s / %s points%s\n", s.number,
                      s.title.c_str(), points(got).c_str(), points(max).c_str(),
                      hidden ? (" (" + std::to_string(hidden) + " tests not shown)").c_str() : "");
        out << line << failures;
    }
    if (!hints.empty()) {
        out << "Handout sections to read:\n";
        for (const auto& h : hints) out << "    " << h << "\n";
    }
    if (!report.general.empty()) out << report.general;
    out << "Total: " << points(score) << " / " << points(max_score) << " points ("
        << points(report.seconds) << " s)\n";
}

}  // namespace rt::grader
