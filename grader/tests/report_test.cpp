// The HTML report (grader/report.cpp): every test's row has an anchor made from its name, the
// same whether it passes or fails, and the failure summary links to it; results.json's one
// writer and one reader (grading/gradescope_results.h) agree.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "grading/gradescope_results.h"
#include "grading/report.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

std::string html_of(const Report& report) {
    const fs::path file = fs::temp_directory_path() / ("rt-report-" + std::to_string(getpid()));
    write_html_report(report, file);
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    fs::remove(file);
    return text.str();
}

ReportTest test(const std::string& name, const std::string& status) {
    ReportTest t;
    t.stage = 2;
    t.name = name;
    t.number = "2.1";
    t.status = status;
    t.max_score = 1;
    t.score = status == "passed" ? 1 : 0;
    t.output = status == "passed" ? "" : "failed: sphere_test.cpp:83\n";
    return t;
}

TEST(Report, EveryTestHasAnAnchorFromItsName) {
    Report report;
    report.stages = {{2, "Intersections", "stages/02-intersections"}};
    report.tests = {test("Stage 02 Sphere.SmallSphereFarAway", "passed"),
                    test("Stage 02 Scenes/Plane.Hits/a", "failed")};
    const std::string html = html_of(report);
    EXPECT_NE(html.find("<tr id=\"Stage-02-Sphere.SmallSphereFarAway\">"), std::string::npos)
        << html;
    EXPECT_NE(html.find("<tr id=\"Stage-02-Scenes/Plane.Hits/a\">"), std::string::npos) << html;
    EXPECT_NE(html.find("<a href=\"#Stage-02-Scenes/Plane.Hits/a\">"), std::string::npos) << html;
}

// A student grading the stage just worked on finds it first, not after stage 01.
TEST(Report, TheNewestStageComesFirst) {
    Report report;
    report.stages = {{1, "Camera rays", "stages/01-camera-rays"},
                     {2, "Intersections", "stages/02-intersections"}};
    ReportTest first = test("Stage 01 Perspective.CornersFollowFieldOfView", "passed");
    first.stage = 1;
    report.tests = {first, test("Stage 02 Sphere.SmallSphereFarAway", "passed")};
    const std::string html = html_of(report);
    const auto two = html.find("Intersections");
    const auto one = html.find("Camera rays");
    ASSERT_NE(two, std::string::npos) << html;
    ASSERT_NE(one, std::string::npos) << html;
    EXPECT_LT(two, one) << "stage 02's section before stage 01's";
}

}  // namespace
}  // namespace rt::grader

namespace rt::grader {
namespace {

// results.json's one writer and one reader agree: what is written reads back the same, and a score
// Gradescope's metadata writes as a string reads as its number.
TEST(GradescopeResults, WhatIsWrittenReadsBack) {
    GradescopeResults written;
    written.score = 17.5;
    written.execution_time = 41.2;
    written.output = "Sandbox: jail\n";
    written.tests.push_back({.name = "Stage 02 Sphere.SmallSphereFarAway",
                             .number = "2.1",
                             .passed = true,
                             .score = 2,
                             .max_score = 2,
                             .output = "ok",
                             .tags = {"stage02", "unit"},
                             .visibility = "visible"});
    GradescopeTest failed;
    failed.name = "Stage 02 image spheres";
    failed.max_score = 3;
    written.tests.push_back(failed);
    written.leaderboard.push_back({"Traversal cost per ray", 48.08, true});
    written.next_graded_at = "2026-12-08T10:00:00Z";
    std::string why;
    const std::optional<GradescopeResults> read =
        read_results_json(results_json_text(written), why);
    ASSERT_TRUE(read) << why;
    EXPECT_EQ(read->score, 17.5);
    EXPECT_EQ(read->execution_time, 42) << "written as whole seconds, rounded up";
    ASSERT_EQ(read->tests.size(), 2u);
    EXPECT_EQ(read->tests[0].name, written.tests[0].name);
    EXPECT_EQ(read->tests[0].number, "2.1");
    EXPECT_TRUE(read->tests[0].passed);
    EXPECT_EQ(read->tests[0].tags, written.tests[0].tags);
    EXPECT_EQ(read->tests[0].visibility, "visible");
    EXPECT_FALSE(read->tests[1].passed);
    EXPECT_EQ(read->tests[1].max_score, 3);
    ASSERT_EQ(read->leaderboard.size(), 1u);
    EXPECT_TRUE(read->leaderboard[0].ascending);
    EXPECT_EQ(read->next_graded_at, written.next_graded_at);

    const auto from_metadata = read_results_json(R"({"score": "20.0", "tests": []})", why);
    ASSERT_TRUE(from_metadata) << why;
    EXPECT_EQ(from_metadata->score, 20);
    EXPECT_FALSE(read_results_json(R"({"score": 1})", why));
    EXPECT_EQ(why, "no \"tests\" list (not a Gradescope results.json)");
    EXPECT_FALSE(read_results_json(R"({"tests": [{"score": 1}]})", why));
    EXPECT_EQ(why, "a test without a name");
}

}  // namespace
}  // namespace rt::grader
