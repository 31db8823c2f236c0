#include "testing/stage_test.h"

#include "core/not_implemented.h"
#include "core/source_dir.h"
#include "image/compare.h"
#include "render/prepare.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "testing/test_watch.h"

#include <iostream>
#include <utility>

namespace rt::testing {

StageTest::StageTest(std::string handout_section) : handout_section_(std::move(handout_section)) {}

std::string handout_section(std::string_view test_file, std::string_view anchor) {
    const std::filesystem::path stage =
        std::filesystem::path(test_file).parent_path().parent_path();
    return (stage / "README.md").generic_string() + "#" + std::string(anchor);
}

void StageTest::SetUp() {
    stubs_before_ = stub_calls_total();
    watch_test(*::testing::UnitTest::GetInstance()->current_test_info());
}

void StageTest::TearDown() {
    if (stub_calls_total() != stubs_before_) {
        ADD_FAILURE() << "this test reached code that is not implemented yet (see the "
                         "\"not implemented\" line above for the function and the handout "
                         "section to read)";
        return;
    }
    // On stderr, where a stub's line goes: the grader links every "read stages/...md#..." it
    // finds (grader/grading/test_output.h), and ctest --output-on-failure shows it last.
    if (HasFailure() && !handout_section_.empty())
        std::cerr << "The handout on what this test checks: read " << handout_section_ << "\n";
}

std::filesystem::path source_dir() {
    return rt::source_dir();
}

void expect_matches_reference(const std::string& stage, const std::string& scene_name,
                              const CompareOptions& options) {
    const auto scene_file = source_dir() / "stages" / stage / "scenes" / (scene_name + ".json");
    const auto reference_file = source_dir() / "reference_images" / stage / (scene_name + ".png");
    PreparedScene scene;
    try {
        // In a grading judge prepare_scene crosses to the worker (stage_api/calls.h).
        scene = prepare_scene(load_scene(scene_file));
    } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
        return;
    }
    const Image8 actual = to_image8(render(scene, scene.mode));
    Image8 reference;
    try {
        reference = read_image8(reference_file);
    } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
        return;
    }
    const CompareResult result = compare_images(actual, reference, options);
    if (result.passed) return;
    std::vector<KeptImage> kept = {{"your image", scene_name + ".png", &actual}};
    if (result.size_matches)
        kept.push_back({"difference", scene_name + ".diff.png", &result.heat_map});
    ADD_FAILURE() << scene_file.string() << ": " << result.summary()
                  << keep_failure_images(stage, kept)
                  << "\n  reference: " << reference_file.string();
}

std::string keep_failure_images(const std::string& folder, const std::vector<KeptImage>& images) {
    const auto out_dir = std::filesystem::path(RT_TEST_OUTPUT_DIR) / folder;
    std::string lines;
    try {
        std::filesystem::create_directories(out_dir);
        for (const KeptImage& k : images) {
            write_image8(*k.image, out_dir / k.file);
            lines += "\n  " + k.label + ": " + (out_dir / k.file).string();
        }
    } catch (const std::exception& e) {
        lines += "\n  (the images could not be kept: " + std::string(e.what()) + ")";
    }
    return lines;
}

}  // namespace rt::testing
