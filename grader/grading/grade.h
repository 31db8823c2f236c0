// `rt-grade SUBMISSION`: grades a student submission against the instructor's tree.
// Trusted code: student code only ever runs in sandboxed child processes (sandbox.h).
#pragma once

#include <atomic>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "course/manifest.h"
#include "image/compare.h"
#include "image/image.h"

namespace rt::grader {

// The stages' manifests (stage.json, grading.json): ImageThresholds, SceneSpec, UnitGroup,
// StageSpec and load_stage_specs are course/manifest.h's.

// A student file compiled into the stage objects (C++), as opposed to GLSL read at run time.
bool is_compiled_student_file(const std::string& key);

// Every unit test runs as a judge and a worker (framework/remote/remote_call.h): the workspace
// builds <binary>_judge once (it holds no student code, C++ or GLSL) and links rt-worker per
// submission.
inline const char* kWorker = "rt-worker";
inline std::string judge_target(const std::string& binary) {
    return binary + "_judge";
}
inline bool is_judge_target(const std::string& target) {
    return target.ends_with("_judge");
}

struct GradeOptions {
    std::filesystem::path source;      // the instructor's tree
    std::filesystem::path cache;       // grading workspaces (default: <source>/build/grader-cache)
    std::filesystem::path submission;  // folder, .zip, or "." for the working tree
    std::vector<int> stages;           // empty: every stage with a grading.json
    std::filesystem::path results;     // Gradescope results.json (optional)
    std::filesystem::path html;        // HTML report (optional)
    int jobs = 0;                      // parallel test processes (0: hardware threads)
    bool quiet = false;                // no terminal summary
    bool started_only = false;         // no --stages: grade the stages started (self-grading)
    bool reveal_hidden = false;        // terminal summary shows hidden tests (instructor)
    double time_limit = 0;             // > 0: overrides every test's and render's wall/CPU limit
};

struct GradeSummary {
    double score = 0;
    double max_score = 0;
    std::vector<double> stage_scores;  // in the order of the graded stages
    std::vector<int> stage_numbers;
    bool build_failed = false;
    double seconds = 0;
};

// Builds (or reuses) the grading workspace (workspace.h); prints progress to log. Returns false
// on failure.
bool prepare_workspace(const GradeOptions& options, std::ostream& log);

// Grades one submission. Never throws for problems of the submission itself; results.json is
// written whatever happens (placeholder first, final at the end).
GradeSummary grade_submission(const GradeOptions& options, std::ostream& log);

// The grader's image scoring (docs/grading.md, "Image scoring"), shared by grading and
// `rt-grade compare` (calibration).
struct ImageScore {
    double fraction = 0;  // of the scene's points
    double ssim = 0;      // reported, never graded
    CompareResult compare;
    std::string metrics;  // one line for the report
};
ImageScore score_image(const Image8& actual, const Image8& reference, const ImageThresholds& th);

// Reads a rendered EXR (linear) as the grader does; NaN or infinite pixels fail with `why`.
bool read_render(const std::filesystem::path& file, Image& image, std::string& why);

// `rt-grade compare`: scores images with the grader's comparison against reference_images and
// the thresholds of grading.json. Either renders every graded scene with `renderer` (a trusted
// build, e.g. the reference compiled with other flags) or scores `image` as scene `scene`
// ("NN-name/scene"; a PNG is taken as display values, an EXR as linear). Prints one line per
// scene; returns 0 when every scene gets full points, 1 otherwise, 2 on a usage error.
struct CompareRequest {
    std::filesystem::path source;
    std::filesystem::path renderer;
    std::vector<int> stages;
    int threads = 0;
    std::filesystem::path image;
    std::string scene;
};
int run_compare(const CompareRequest& request, std::ostream& log);

// Set by SIGINT/SIGTERM: grading stops starting new children and writes what it has.
extern std::atomic<bool> g_interrupted;

int run_batch(const GradeOptions& base, const std::filesystem::path& dir,
              const std::filesystem::path& out, int jobs, std::ostream& log);

// The Gradescope zip. `stages` (empty: every stage with a grading.json) are the stages its
// run_autograder grades: one assignment per stage or per group of stages.
int run_package(const std::filesystem::path& source, const std::filesystem::path& out,
                const std::vector<int>& stages, std::ostream& log);

}  // namespace rt::grader
