// The course manifest: each stage folder's stage.json (number, title, student files) and
// grading.json (what a grade covers: unit-test groups, graded scenes and their image thresholds,
// time limits). One reader for every program that needs it: the grader, the release tool, the
// image tests, the gallery (docs/grading.md#gradingjson).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/compare.h"

namespace rt {

// A graded image's thresholds: grading.json's "image_defaults", the scene's own keys over them.
struct ImageThresholds {
    int tolerance = 2;          // 8-bit steps a channel may differ
    double pass_percent = 0.1;  // failing pixels at or below this: full points
    double fail_percent = 2.0;  // at or above this: no points; linear in between
    bool neighbourhood = true;  // forgive anti-aliased edges (3x3 reference neighbourhood)
    int block = 0;  // > 0: compare means over block x block squares (Monte Carlo renders)

    // The comparison that decides full points (image/compare.h).
    CompareOptions compare_options() const;
};

struct SceneSpec {
    std::string name;    // <folder>/scenes/<name>.json, reference_images/<folder's name>/<name>.png
    std::string folder;  // stages/NN-name: the grading stage's own, or another's ("from")
    double points = 1;
    std::string visibility = "visible";
    ImageThresholds thresholds;
};

struct UnitGroup {
    std::string binary;                     // a GoogleTest target of the instructor's build
    std::vector<std::string> include{"*"};  // gtest-style patterns over Suite.Test
    std::vector<std::string> exclude;
    std::vector<std::string> hidden_sources;  // relative to the stage folder; never released
    double points = 1;                        // each test
    std::string visibility = "visible";
};

// stage.json alone (every stage has one; a stage without grading.json is not graded).
struct StageInfo {
    int number = 0;
    std::string title;
    std::vector<std::string> student_files;  // relative to the stage folder
    std::string problem;                     // why stage.json is unusable; empty when it is fine
};

struct StageSpec {
    int number = 0;
    std::string folder;  // stages/NN-name
    std::string title;
    std::vector<std::string> student_files;  // relative to the folder
    std::vector<UnitGroup> groups;
    std::vector<SceneSpec> scenes;
    ImageThresholds image_defaults;  // for a scene grading.json does not list
    double test_seconds = 10;
    double render_seconds = 30;
    // "renderer": "gpu" (stage 09): the student files are GLSL, loaded by the test binaries and
    // `rt render --gpu` at run time (RT_GPU_STUDENT_DIR), never compiled into objects.
    bool gpu = false;
    // "leaderboard": {"scene": NAME}: Gradescope's leaderboard times the student's renderer on
    // this graded scene against the reference's, in the same grading (never part of the score).
    std::string leaderboard_scene;
    // "rank_by": "traversal_cost" (stage 06): ranked by node visits plus 10 x primitive tests per
    // primary ray through the student's tree, counted by the reference (apps/bvh_cost.h), the
    // same on every machine; "speed" (the default): by the time ratio.
    bool leaderboard_traversal_cost = false;

    const SceneSpec* scene(const std::string& name) const;  // nullptr when not graded
    // The thresholds the grader compares scene `name` with: its own, or image_defaults.
    ImageThresholds thresholds_of(const std::string& name) const;
};

// `stage_json` read without throwing: `problem` says what is wrong ("missing or unreadable",
// "is not valid JSON (...)", "has no \"student_files\" array", ...).
StageInfo read_stage_info(const std::filesystem::path& stage_json);

// The stage in `folder` (a stages/NN-name folder of the tree at `source`); throws
// std::runtime_error naming the file and the key.
StageSpec load_stage_spec(const std::filesystem::path& source, const std::filesystem::path& folder);

// Every stage that has a grading.json, in folder order.
std::vector<StageSpec> load_stage_specs(const std::filesystem::path& source);

}  // namespace rt
