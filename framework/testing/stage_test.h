// Test support for the stages.
//
// Every stage test derives from rt::testing::StageTest (through RT_TEST_SUITE), whose TearDown
// fails the test if it reached a stub (RT_NOT_IMPLEMENTED). So a stub can never pass a test, even
// when its placeholder return value happens to be what the test expects.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "image/compare.h"
#include "image/image.h"
#include "scene/scene.h"
#include "testing/expect_near.h"

namespace rt::testing {

class StageTest : public ::testing::Test {
  protected:
    void SetUp() override;
    void TearDown() override;

  private:
    std::uint64_t stubs_before_ = 0;
};

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

// Declares a test suite (fixture) of stage tests: RT_TEST_SUITE(Triangle); TEST_F(Triangle, ...)
#define RT_TEST_SUITE(name) \
    class name : public ::rt::testing::StageTest {}
