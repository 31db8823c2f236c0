// The image tests of a stage: every scene its grading.json grades ("scenes"), rendered with the
// student's code and compared with reference_images/<stage>/<scene>.png
// (docs/conventions.md#image-tests). One parametrised test, compiled once and linked into each
// stage's test binary, which names its stage folder in kImageTestStage (a one-line source
// rt_stage_tests writes), so a stage's image tests and its grade list the same scenes.
// CTest names: StageNN.Graded/Image.MatchesReference/<scene>.
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "course/manifest.h"
#include "testing/stage_test.h"

namespace rt::testing {

namespace fs = std::filesystem;

// The stage folder, e.g. "01-camera-rays"; defined by the test binary (cmake/testing.cmake).
// Constant-initialised, so it is set before the test registration below reads it.
extern const char* const kImageTestStage;

namespace {

// The stage's manifest (course/manifest.h: the grader's own reader); nothing when it cannot be
// read (GoogleTest then reports the suite as never instantiated, which fails the run visibly).
std::optional<StageSpec> stage_spec() {
    try {
        const fs::path root = source_dir();
        return load_stage_spec(root, root / "stages" / kImageTestStage);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

std::vector<std::string> graded_scenes() {
    std::vector<std::string> names;
    if (const auto spec = stage_spec())
        for (const SceneSpec& scene : spec->scenes) names.push_back(scene.name);
    return names;
}

// The comparison of scene `name` as the grader makes it for full points, so a test passes exactly
// when rt-grade would give the image full points, and both print the same share of failing
// pixels.
CompareOptions compare_options(const std::string& name) {
    const auto spec = stage_spec();
    const SceneSpec* scene = spec ? spec->scene(name) : nullptr;
    return scene ? scene->thresholds.compare_options() : ImageThresholds{}.compare_options();
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
