// The course manifest (course/manifest.h), the one reader of stage.json and grading.json that
// the grader, the release tool, the image tests and the gallery share.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>
#include <string>

#include "core/source_dir.h"
#include "course/manifest.h"
#include "testing/temp_dir.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt {
namespace {

json read_json(const fs::path& file) {
    std::ifstream in(file);
    return json::parse(in);
}

// What grading.json asks for scene entry `scene`, read here on its own: the defaults (ImageThresholds),
// image_defaults over them, the scene's keys over those.
ImageThresholds expected(const json& grading, const json& scene) {
    json merged = grading.value("image_defaults", json::object());
    merged.update(scene);
    ImageThresholds t;
    t.tolerance = merged.value("tolerance", 2);
    t.pass_percent = merged.value("pass_percent", 0.1);
    t.fail_percent = merged.value("fail_percent", 2.0);
    t.neighbourhood = merged.value("neighbourhood", true);
    t.block = merged.value("block", 0);
    return t;
}

// Every graded scene of the tree gets the thresholds its grading.json gives it, and the
// comparison that decides full points carries all of them (block included: stage 10).
TEST(CourseManifest, EveryGradedSceneGetsItsGradingJsonThresholds) {
    const std::vector<StageSpec> specs = load_stage_specs(source_dir());
    ASSERT_GE(specs.size(), 10u);
    int scenes = 0, blocks = 0;
    for (const StageSpec& stage : specs) {
        const json grading = read_json(source_dir() / stage.folder / "grading.json");
        ASSERT_EQ(stage.scenes.size(), grading.value("scenes", json::array()).size());
        for (std::size_t i = 0; i < stage.scenes.size(); ++i) {
            const json& entry = grading["scenes"][i];
            const SceneSpec& scene = stage.scenes[i];
            SCOPED_TRACE(stage.folder + "/" + scene.name);
            ASSERT_EQ(scene.name, entry.at("name").get<std::string>());
            ASSERT_EQ(stage.scene(scene.name), &scene);
            const ImageThresholds want = expected(grading, entry);
            const CompareOptions got = scene.thresholds.compare_options();
            EXPECT_EQ(got.tolerance, want.tolerance);
            EXPECT_EQ(got.max_failing_percent, want.pass_percent);
            EXPECT_EQ(got.neighbourhood, want.neighbourhood);
            EXPECT_EQ(got.block, want.block);
            EXPECT_EQ(scene.thresholds.fail_percent, want.fail_percent);
            ++scenes;
            blocks += got.block > 0;
        }
    }
    EXPECT_GT(scenes, 40);
    EXPECT_GT(blocks, 0);  // stage 10's Monte Carlo images
}

// A stage folder with `grading` as its grading.json.
fs::path stage_with(const testing::TempDir& tree, const std::string& grading) {
    tree.write("stages/01-a/stage.json",
               R"({"number": 1, "title": "A", "student_files": ["a.cpp"]})");
    tree.write("stages/01-a/grading.json", grading);
    tree.write("stages/01-a/scenes/s.json", "{}");
    return tree.path() / "stages/01-a";
}

std::string load_error(const std::string& grading) {
    testing::TempDir tree("manifest");
    const fs::path folder = stage_with(tree, grading);
    try {
        load_stage_spec(tree.path(), folder);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(CourseManifest, MistakesNameTheFileAndTheFix) {
    EXPECT_NE(load_error(R"({"renderer": "vulkan"})")
                  .find("grading.json: \"renderer\" is "
                        "\"vulkan\"; use \"cpu\""),
              std::string::npos);
    EXPECT_NE(load_error(R"({"scenes": [{"name": "s", "visibility": "secret"}]})")
                  .find("grading.json: visibility \"secret\" is not one of visible"),
              std::string::npos);
    EXPECT_NE(load_error(R"({"scenes": [{"name": "s", "from": "02-b"}]})")
                  .find("grading.json: scene \"s\" from \"02-b\": no stages/02-b/scenes/s.json"),
              std::string::npos);
    EXPECT_NE(load_error(R"({"scenes": [{"name": "s", "tolerance": "big"}]})")
                  .find("01-a/grading.json: "),
              std::string::npos);
    EXPECT_NE(load_error("{").find("01-a/grading.json: "), std::string::npos);
    EXPECT_NE(load_error(R"({"scenes": [{"name": "s"}], "leaderboard": {"scene": "t"}})")
                  .find("grading.json: \"leaderboard\": scene \"t\" is not one of the graded"),
              std::string::npos);
}

TEST(CourseManifest, StageInfoSaysWhatIsWrong) {
    testing::TempDir tree("stage-info");
    EXPECT_EQ(read_stage_info(tree.path() / "none.json").problem, "missing or unreadable");
    EXPECT_EQ(read_stage_info(tree.write("a.json", R"({"title": "x"})")).problem,
              "has no \"student_files\" array");
    EXPECT_EQ(read_stage_info(tree.write("b.json", R"({"student_files": [3]})")).problem,
              "lists a \"student_files\" entry that is not a string");
    const StageInfo ok = read_stage_info(
        tree.write("c.json", R"({"number": 4, "title": "T", "student_files": ["f.cpp"]})"));
    EXPECT_EQ(ok.problem, "");
    EXPECT_EQ(ok.number, 4);
    EXPECT_EQ(ok.student_files, std::vector<std::string>{"f.cpp"});
}

}  // namespace
}  // namespace rt
