// Test support for the stages.
//
// Every stage test derives from rt::testing::StageTest (through RT_TEST_SUITE), whose TearDown
// fails the test if it reached a stub (RT_NOT_IMPLEMENTED). So a stub can never pass a test, even
// when its placeholder return value happens to be what the test expects. A test that fails for
// another reason names the handout section of its suite, which the grader turns into a link.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "image/compare.h"
#include "image/image.h"
#include "scene/scene.h"
#include "testing/expect_near.h"

namespace rt::testing {

class StageTest : public ::testing::Test {
  protected:
    // `handout_section`: "stages/NN-x/README.md#anchor", named when a test of the suite fails.
    explicit StageTest(std::string handout_section = {});
    void SetUp() override;
    void TearDown() override;

  private:
    std::string handout_section_;
    std::uint64_t stubs_before_ = 0;
};

// The handout section `anchor` of the stage whose test file is `test_file`
// ("stages/NN-x/tests/f.cpp", as __FILE__ spells it): "stages/NN-x/README.md#anchor".
std::string handout_section(std::string_view test_file, std::string_view anchor);

// The source tree (scenes, reference images), independent of the working directory.
std::filesystem::path source_dir();

// Renders `scene_file` (relative to the source tree) with the scene's own mode and compares it
// with reference_images/<stage>/<name>.png using the framework's image comparison. Adds a gtest
// failure with the comparison summary and writes the rendered image and a diff image under
// build/test-output/ when it does not match.
// `options`: the comparison (the default, or stage 10's block means from its grading.json).
void expect_matches_reference(const std::string& stage, const std::string& scene_name,
                              const CompareOptions& options = {});

// For a failing image comparison: writes each (label, file name, image) under
// build/test-output/<folder>/ and returns lines naming them ("\n  label: PATH"), or says why they
// could not be written (a grading judge's folder is read-only).
struct KeptImage {
    std::string label, file;
    const Image8* image;
};
std::string keep_failure_images(const std::string& folder, const std::vector<KeptImage>& images);

}  // namespace rt::testing

// Declares a test suite (fixture) of stage tests and the handout section that teaches what they
// test (an anchor of the stage's README.md, checked by Stages.StubsLinkToHandoutSections):
//   RT_TEST_SUITE(Triangle, "ray-triangle-cramers-rule"); TEST_F(Triangle, ...)
#define RT_TEST_SUITE(name, anchor)                                             \
    class name : public ::rt::testing::StageTest {                              \
      protected:                                                                \
        name() : StageTest(::rt::testing::handout_section(__FILE__, anchor)) {} \
    }
