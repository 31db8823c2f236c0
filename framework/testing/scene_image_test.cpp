// The image tests of a stage: every scene its grading.json grades ("scenes"), rendered with the
// student's code and compared with reference_images/<stage>/<scene>.png
// (docs/conventions.md#image-tests). One parametrised test, compiled once and linked into each
// stage's test binary, which names its stage folder in kImageTestStage (a one-line source
// rt_stage_tests writes), so a stage's image tests and its grade list the same scenes.
// CTest names: StageNN.Graded/Image.MatchesReference/<scene>.
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "testing/stage_test.h"

namespace rt::testing {

// The stage folder, e.g. "01-camera-rays"; defined by the test binary (cmake/testing.cmake).
// Constant-initialised, so it is set before the test registration below reads it.
extern const char* const kImageTestStage;

namespace {

nlohmann::json grading_spec() {
    std::ifstream in(source_dir() / "stages" / kImageTestStage / "grading.json");
    return nlohmann::json::parse(in, nullptr, false);
}

// The scene names of the stage's grading.json; empty when it cannot be read (GoogleTest then
// reports the suite as never instantiated, which fails the run visibly).
std::vector<std::string> graded_scenes() {
    std::vector<std::string> names;
    const nlohmann::json spec = grading_spec();
    if (spec.is_discarded() || !spec.contains("scenes")) return names;
    for (const nlohmann::json& scene : spec["scenes"])
        if (scene.contains("name") && scene["name"].is_string()) names.push_back(scene["name"]);
    return names;
}

// The comparison of scene `name` as the grader makes it for full points (grader/stage_specs.cpp
// reads the same keys): grading.json's image_defaults with the scene's own entry over them, the
// grader's defaults (grader/grade.h, ImageThresholds) for what neither sets. So a test passes
// exactly when rt-grade would give the image full points, and both print the same share of
// failing pixels.
CompareOptions compare_options(const std::string& name) {
    CompareOptions options;
    const nlohmann::json spec = grading_spec();
    if (spec.is_discarded()) return options;
    nlohmann::json merged = spec.value("image_defaults", nlohmann::json::object());
    for (const nlohmann::json& scene : spec.value("scenes", nlohmann::json::array()))
        if (scene.value("name", "") == name) merged.update(scene);
    options.tolerance = merged.value("tolerance", options.tolerance);
    options.max_failing_percent = merged.value("pass_percent", options.max_failing_percent);
    options.neighbourhood = merged.value("neighbourhood", true);
    options.block = merged.value("block", options.block);
    return options;
}

class Image : public StageTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(Image, MatchesReference) {
    expect_matches_reference(kImageTestStage, GetParam(), compare_options(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Graded, Image, ::testing::ValuesIn(graded_scenes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param;
                         });

}  // namespace
}  // namespace rt::testing
