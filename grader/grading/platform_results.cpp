// PrairieLearn's results.json and Autolab's score line (platform_results.h).
#include "grading/platform_results.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

#include "util.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt::grader {
namespace {

// PrairieLearn refuses a results file over 1 MiB; the budget leaves room for the JSON around.
constexpr std::size_t kMaxResultsBytes = 1 << 20;
constexpr std::size_t kOutputBytesPerTest = 4000;
constexpr std::size_t kShortOutputBytesPerTest = 600;

std::string first_line(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

std::string capped(const std::string& text, std::size_t bytes) {
    if (text.size() <= bytes) return text;
    return text.substr(0, bytes) + "\n... (shortened; the full output is in the report)\n";
}

json prairielearn_tests(const Report& report, std::size_t output_bytes) {
    json tests = json::array();
    for (const auto& t : report.tests) {
        const std::string output = clean_output(t.output);
        tests.push_back({{"name", t.name},
                         {"points", t.score},
                         {"max_points", t.max_score},
                         {"message", t.status == "passed" ? "passed" : first_line(output)},
                         {"output", capped(output, output_bytes)}});
    }
    return tests;
}

// Failing scenes' images, in test order, while they fit in `budget` bytes of base64.
json prairielearn_images(const Report& report, std::size_t budget) {
    json images = json::array();
    for (const auto& t : report.tests) {
        if (!t.is_scene || t.status == "passed" || t.student_png.empty()) continue;
        std::string url = "data:image/png;base64," + base64(t.student_png);
        if (url.size() > budget) break;
        budget -= url.size();
        images.push_back({{"label", t.name + " (your image)"}, {"url", std::move(url)}});
    }
    return images;
}

// "12 of 18 points": what the student reads first (the sandbox and notes are in "output").
std::string points_text(double score, double max_score) {
    char text[64];
    std::snprintf(text, sizeof text, "%g of %g points", std::round(score * 100) / 100, max_score);
    return text;
}

}  // namespace

void write_prairielearn_results(const Report& report, const fs::path& file, bool gradable,
                                const std::string& why) {
    double score = 0;
    double max_score = 0;
    for (const auto& t : report.tests) {
        score += t.score;
        max_score += t.max_score;
    }
    json results = {
        {"gradable", gradable},
        {"score", gradable && max_score > 0 ? score / max_score : 0.0},
        {"message", gradable ? points_text(score, max_score) : why},
        {"output", clean_output("Sandbox: " + report.isolation + "\n" + report.general)},
        {"tests", prairielearn_tests(report, kOutputBytesPerTest)},
    };
    std::string text = results.dump(1);
    // Outputs shortened first, then images only in the room that leaves.
    if (text.size() > kMaxResultsBytes / 2) {
        results["tests"] = prairielearn_tests(report, kShortOutputBytesPerTest);
        text = results.dump(1);
    }
    if (text.size() < kMaxResultsBytes) {
        results["images"] = prairielearn_images(report, kMaxResultsBytes - text.size() - 1024);
        text = results.dump(1);
    }
    if (text.size() > kMaxResultsBytes) {
        results["tests"] = prairielearn_tests(report, 0);
        results.erase("images");
        text = results.dump(1);
    }
    if (file.has_parent_path()) fs::create_directories(file.parent_path());
    write_text_atomically(file, text + "\n");
}

std::string autolab_scores_line(const std::map<int, double>& stage_scores,
                                const std::map<int, std::string>& names) {
    json scores = json::object();
    json scoreboard = json::array({0.0});
    double total = 0;
    for (const auto& [stage, points] : stage_scores) {
        const auto it = names.find(stage);
        const double rounded = std::round(points * 100) / 100;
        scores[it != names.end() ? it->second : "stage" + two_digits(stage)] = rounded;
        scoreboard.push_back(rounded);
        total += rounded;
    }
    scoreboard[0] = std::round(total * 100) / 100;
    return json{{"scores", scores}, {"scoreboard", scoreboard}}.dump();
}

}  // namespace rt::grader
