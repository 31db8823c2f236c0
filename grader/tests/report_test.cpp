// The HTML report (grader/report.cpp): every test's row has an anchor made from its name, the
// same whether it passes or fails, and the failure summary links to it.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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
