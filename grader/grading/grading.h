// One grading's state and its phases. grade_submission (grade.cpp) runs the phases in order:
// choose the stages, plan the tests, take in the submission, build (grade_build.cpp), run the
// tests and score the scenes (grade_run.cpp), summarise. Internal to rt-grade.
#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "course/manifest.h"
#include "grading/grade.h"
#include "grading/intake.h"
#include "grading/report.h"
#include "sandbox/sandbox.h"
#include "workspace/workspace.h"

namespace rt::grader {

// One line of results.json: a unit test, a scene, or a 0-point note (build, missing file).
struct TestOutcome {
    std::string name, number, status = "failed", output, visibility = "visible";
    std::vector<std::string> tags;
    double score = 0, max_score = 0;
    int stage = 0;
    bool is_scene = false;
    // Scenes: images for the HTML report (PNG bytes), metrics.
    std::string student_png, reference_png, diff_png;
    std::string metrics;
};

// What one sandboxed run does: a unit test of `binary`, or the scene `scene`.
struct GradeTask {
    std::size_t outcome;       // index into Grading::outcomes
    std::string binary, test;  // unit test
    const SceneSpec* scene = nullptr;
    const StageSpec* stage = nullptr;
};

struct Grading {
    explicit Grading(const GradeOptions& options) : o(options) {}

    const GradeOptions& o;
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    Workspace w;
    std::vector<StageSpec> all_specs, graded;
    Isolation isolation = Isolation::None;
    std::vector<TestOutcome> outcomes;  // every test of the graded stages, 0 until run
    std::vector<GradeTask> tasks;
    std::vector<TestOutcome> notes;  // 0-point entries: build, file checks
    std::string general;             // top-level output
    BuildPlan plan;
    std::filesystem::path scratch;       // this grading's folder in /tmp, removed at the end
    std::filesystem::path reference_rt;  // the reference renderer (unseen views)
    Intake in;
    std::string digest;  // of the submitted files: picks the unseen view
    std::map<int, std::filesystem::path> stage_bins;  // stage -> its linked binaries
    // A GPU stage -> the folder of its GLSL as graded (submitted files, stubs for the missing),
    // which its tests and renders load at run time (RT_GPU_STUDENT_DIR).
    std::map<int, std::filesystem::path> glsl_dirs;
    std::atomic<int> survivors{0};  // processes the sandbox could not kill
    GradeSummary summary;
    std::vector<LeaderboardEntry> leaderboard;  // time_leaderboard's, when a stage asks for one
    std::mutex progress_mutex;                  // guards finished (run phase, Autolab's lines)
    std::vector<bool> finished;                 // outcomes whose task has run

    Report to_report() const;
};

// Autolab's running total (--autolab-scores): one line on stdout with the points of the tests
// that have finished, so that a timeout still leaves a score as the last line. `task`: the
// outcome just finished (none: the line before the first test, or after the last).
void print_autolab_scores(Grading& g, std::optional<std::size_t> task = std::nullopt);

// The phases that live in files of their own.
void build_stages(Grading& g);          // grade_build.cpp: compile, check, link per stage
void run_tests_and_scenes(Grading& g);  // grade_run.cpp: every task in its own sandbox
// grade_run.cpp: Gradescope's leaderboard of the graded stages that ask for one (grading.json
// "leaderboard"), after the scenes are scored; it never changes a score.
void time_leaderboard(Grading& g);

}  // namespace rt::grader
