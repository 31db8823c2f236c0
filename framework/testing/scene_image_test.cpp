// The image tests of a stage: every scene its grading.json grades ("scenes"), rendered with the
// student's code and compared with reference_images/<stage>/<scene>.png
// (docs/conventions.md#image-tests). One parametrised test, compiled into each stage's test
// binary with RT_STAGE naming the stage folder, so a stage's image tests and its grade list the
// same scenes. CTest names: StageNN.Graded/Image.MatchesReference/<scene>.
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "testing/stage_test.h"

#ifndef RT_STAGE
#error "RT_STAGE (the stage folder, e.g. 01-camera-rays) is set by rt_stage_tests"
#endif

namespace rt::testing {
namespace {

// The scene names of the stage's grading.json; empty when it cannot be read (GoogleTest then
// reports the suite as never instantiated, which fails the run visibly).
std::vector<std::string> graded_scenes() {
    std::vector<std::string> names;
    std::ifstream in(source_dir() / "stages" / RT_STAGE / "grading.json");
    const nlohmann::json spec = nlohmann::json::parse(in, nullptr, false);
    if (spec.is_discarded() || !spec.contains("scenes")) return names;
    for (const nlohmann::json& scene : spec["scenes"])
        if (scene.contains("name") && scene["name"].is_string()) names.push_back(scene["name"]);
    return names;
}

class Image : public StageTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(Image, MatchesReference) {
    expect_matches_reference(RT_STAGE, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Graded, Image, ::testing::ValuesIn(graded_scenes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param;
                         });

}  // namespace
}  // namespace rt::testing
