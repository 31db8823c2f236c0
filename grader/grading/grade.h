// `rt-grade SUBMISSION`: grades a student submission against the instructor's tree.
// Trusted code: student code only ever runs in sandboxed child processes (sandbox/sandbox.h).
#pragma once

#include <atomic>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace rt::grader {

struct GradeOptions {
    std::filesystem::path source;      // the instructor's tree
    std::filesystem::path cache;       // grading workspaces (default: <source>/build/grader-cache)
    std::filesystem::path submission;  // folder, .zip, or "." for the working tree
    // Why the submission could not be unpacked (a batch's export, cmd/batch_input.h): graded as
    // unreadable with this reason, like a broken zip; "" when it was.
    std::string refused;
    std::vector<int> stages;        // empty: every stage with a grading.json
    std::filesystem::path results;  // Gradescope results.json (optional)
    std::filesystem::path html;     // HTML report (optional)
    std::filesystem::path renders;  // failing scenes' images, for the dashboard (optional)
    int jobs = 0;                   // parallel test processes (0: hardware threads)
    bool quiet = false;             // no terminal summary
    bool started_only = false;      // no --stages: grade the stages started (self-grading)
    bool reveal_hidden = false;     // terminal summary shows hidden tests (instructor)
    double time_limit = 0;          // > 0: overrides every test's and render's wall/CPU limit
    // The platforms besides Gradescope (grading/platform_results.h):
    std::filesystem::path prairielearn_results;  // PrairieLearn's results.json (optional)
    bool autolab_scores = false;  // Autolab: a score line on stdout at the start, after each test
    std::map<int, std::string> problem_names;  // Autolab's problem of a stage (default: folder)
};

struct GradeSummary {
    double score = 0;
    double max_score = 0;
    std::vector<double> stage_scores;  // in the order of the graded stages
    std::vector<int> stage_numbers;
    bool build_failed = false;
    double seconds = 0;
};

// Grades one submission. Never throws for problems of the submission itself; results.json is
// written whatever happens (placeholder first, final at the end).
GradeSummary grade_submission(const GradeOptions& options, std::ostream& log);

// Set by SIGINT/SIGTERM: grading stops starting new children and writes what it has.
extern std::atomic<bool> g_interrupted;

}  // namespace rt::grader
