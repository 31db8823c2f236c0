// What a grading produced, and its three renderings: Gradescope's results.json, a
// self-contained HTML report, and the terminal summary for students grading themselves.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "grading/gradescope_results.h"

namespace rt::grader {

struct ReportTest {
    int stage = 0;  // 0: not a stage test (the build)
    std::string name, number, status, output, visibility;
    std::vector<std::string> tags;
    double score = 0, max_score = 0;
    bool is_scene = false;
    std::string student_png, reference_png, diff_png;  // PNG bytes (scenes)
    std::string metrics;
};

struct ReportStage {
    int number = 0;
    std::string title, folder;
};

struct Report {
    std::string isolation;
    std::string general;  // top-level notes: ignored files, interruptions, sandbox degradation
    double seconds = 0;
    std::vector<ReportStage> stages;
    std::vector<ReportTest> tests;
    std::vector<LeaderboardEntry> leaderboard;  // empty: no "leaderboard" in results.json
};

// Gradescope's results.json of the grading (gradescope_results.h), written atomically.
void write_results_json(const Report& report, const std::filesystem::path& file);
void write_html_report(const Report& report, const std::filesystem::path& file);
void write_terminal_summary(const Report& report, std::ostream& out, bool reveal_hidden);

// The student's image of each failing scene, as `dir`/render_png_name(test's name) (batch: for
// the class dashboard, cmd/dashboard.h). Passing scenes' images are the reference: not kept.
void write_failing_renders(const Report& report, const std::filesystem::path& dir);
// "Stage 02 image spheres_normals" -> "Stage-02-image-spheres_normals.png": one name per test.
std::string render_png_name(const std::string& test_name);
// The reports' CSS, shared by the class dashboard.
const char* report_style();

}  // namespace rt::grader
