// The class dashboard (cmd/dashboard.h) on a batch folder written here: four graded
// submissions' results.json (no grading runs), their failing renders, and folders it must leave
// out with a warning. Checks the histogram counts, the worst-first order, the links.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <sstream>

#include "cmd/dashboard.h"
#include "grading/report.h"
#include "util.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt::grader {
namespace {

const std::string kSphere = "stages/02-intersections/README.md#ray-sphere";
const std::string kCamera = "stages/01-camera-rays/README.md#camera-rays";

// A test as results.json has it; `hint` is a handout section its output names.
json test(const std::string& name, double max, bool passed, const std::string& hint = "") {
    const std::string stage = "stage" + name.substr(6, 2);
    const bool image = name.find(" image ") != std::string::npos;
    return {{"name", name},
            {"score", passed ? max : 0},
            {"max_score", max},
            {"status", passed ? "passed" : "failed"},
            {"output", hint.empty() ? "" : "not implemented: f (x.cpp:3); read " + hint + "\n"},
            {"tags", {stage, image ? "image" : "unit"}},
            {"visibility", "visible"}};
}

// One submission: its results.json, and its failing renders written as a batch writes them.
void submission(const fs::path& out, const std::string& name, double seconds, json tests,
                const std::vector<std::pair<std::string, std::string>>& renders) {
    write_text(out / name / "results.json",
               json{{"score", 0}, {"execution_time", seconds}, {"tests", tests}}.dump(2));
    Report report;
    for (const auto& [test_name, png] : renders) {
        ReportTest t;
        t.name = test_name;
        t.status = "failed";
        t.is_scene = true;
        t.student_png = png;
        report.tests.push_back(t);
    }
    ReportTest passing;  // a passing scene's image is never kept
    passing.name = "Stage 01 image passing";
    passing.status = "passed";
    passing.is_scene = true;
    passing.student_png = "PNG";
    report.tests.push_back(passing);
    write_failing_renders(report, out / name / "renders");
}

// Stage 01: A, B, C (1 point), image s1 (2). Stage 02: D, E (1 point), image s2 (2).
json tests(bool a, bool b, bool s1, bool e, bool s2) {
    return json::array({test("Stage 01 A", 1, a, a ? "" : kCamera), test("Stage 01 B", 1, b),
                        test("Stage 01 C", 1, true), test("Stage 01 image s1", 2, s1),
                        test("Stage 02 D", 1, false, kSphere), test("Stage 02 E", 1, e),
                        test("Stage 02 image s2", 2, s2)});
}

class Dashboard : public ::testing::Test {
  protected:
    void SetUp() override {
        char tmpl[] = "/tmp/rt-dashboard-test-XXXXXX";
        ASSERT_NE(mkdtemp(tmpl), nullptr);
        out_ = tmpl;
        // Stage 01 percent: 100, 80, 20, 100. Stage 02: 25, 75, 0, 25.
        submission(out_, "ann", 10, tests(true, true, true, true, false),
                   {{"Stage 02 image s2", "PNG-X"}});
        submission(out_, "ben", 20, tests(false, true, true, true, true), {});
        submission(out_, "cat", 30, tests(false, false, false, false, false),
                   {{"Stage 01 image s1", "PNG-Y"}, {"Stage 02 image s2", "PNG-X"}});
        submission(out_, "dan", 50, tests(true, true, true, true, false),
                   {{"Stage 02 image s2", "PNG-Y"}});
        write_text(out_ / "bad<1>" / "results.json", "{not json");
        write_text(out_ / "odd" / "results.json", R"({"tests": 3})");
        fs::create_directories(out_ / "nofile");
        write_text(out_ / "scores.csv", "submission,score\n");  // a file: not a submission
    }
    void TearDown() override { fs::remove_all(out_); }

    fs::path out_;
};

TEST_F(Dashboard, ReadsEveryReadableSubmissionAndNamesTheRest) {
    std::ostringstream log;
    const ClassResults r = read_class_results(out_, log);
    ASSERT_EQ(r.submissions.size(), 4u);
    EXPECT_EQ(r.submissions[0].name, "ann");
    EXPECT_EQ(r.submissions[3].stages.at(2), std::make_pair(1.0, 4.0));
    ASSERT_EQ(r.problems.size(), 3u) << log.str();
    for (const char* name : {"bad<1>", "odd", "nofile"})
        EXPECT_NE(log.str().find((out_ / name / "results.json").string()), std::string::npos)
            << name << " in:\n"
            << log.str();
    EXPECT_NE(log.str().find("not valid JSON"), std::string::npos);
}

TEST_F(Dashboard, HistogramCountsPerStage) {
    std::ostringstream log;
    const auto h = stage_histograms(read_class_results(out_, log));
    ASSERT_EQ(h.size(), 2u);
    EXPECT_EQ(h[0].stage, 1);
    EXPECT_EQ(h[0].counts, (std::array<int, kHistogramBins>{0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 2}));
    EXPECT_DOUBLE_EQ(h[0].median, 90);
    EXPECT_EQ(h[1].counts, (std::array<int, kHistogramBins>{1, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0}));
    EXPECT_DOUBLE_EQ(h[1].mean, 31.25);
}

TEST_F(Dashboard, TestsWorstFirstWithTheirHandoutSections) {
    std::ostringstream log;
    const auto f = test_failures(read_class_results(out_, log), false);
    std::vector<std::string> order;
    for (const auto& t : f) order.push_back(t.name + " " + std::to_string(t.failed));
    EXPECT_EQ(order, (std::vector<std::string>{"Stage 02 D 4", "Stage 01 A 2", "Stage 01 B 1",
                                               "Stage 02 E 1", "Stage 01 C 0"}));
    EXPECT_EQ(f[0].hints, (std::vector<std::pair<std::string, int>>{{kSphere, 4}}));
    EXPECT_EQ(f[1].hints, (std::vector<std::pair<std::string, int>>{{kCamera, 2}}));
}

TEST_F(Dashboard, ScenesShowTheMostCommonFailingImage) {
    std::ostringstream log;
    const auto f = test_failures(read_class_results(out_, log), true);
    ASSERT_EQ(f.size(), 2u);
    EXPECT_EQ(f[0].name, "Stage 02 image s2");
    EXPECT_EQ(f[0].failed, 3);
    EXPECT_EQ(f[0].common_count, 2);  // ann's and cat's are the same image, dan's another
    EXPECT_EQ(f[0].common_render, "ann/renders/Stage-02-image-s2.png");
    EXPECT_EQ(f[1].common_render, "cat/renders/Stage-01-image-s1.png");
    EXPECT_FALSE(fs::exists(out_ / "ann" / "renders" / render_png_name("Stage 01 image passing")));
}

TEST_F(Dashboard, RunTimes) {
    std::ostringstream log;
    EXPECT_EQ(run_time_summary(read_class_results(out_, log)), (std::array<double, 3>{10, 25, 50}));
}

TEST_F(Dashboard, ThePageLinksReportsHandoutsAndImages) {
    std::ostringstream log;
    EXPECT_EQ(write_dashboard(out_, "https://example.org/course/", log), 4);
    const std::string page = read_text(out_ / "index.html");
    auto at = [&](const std::string& s) { return page.find(s); };
    for (const char* name : {"ann", "ben", "cat", "dan"})
        EXPECT_NE(at("href=\"" + std::string(name) + "/report.html\""), std::string::npos) << name;
    EXPECT_NE(at("href=\"https://example.org/course/" + kSphere + "\""), std::string::npos);
    EXPECT_NE(at("src=\"ann/renders/Stage-02-image-s2.png\""), std::string::npos);
    EXPECT_NE(at("data-bin=\"10\" data-count=\"2\""), std::string::npos);
    EXPECT_LT(at("<td>Stage 02 D</td>"), at("<td>Stage 01 A</td>"));
    EXPECT_LT(at("<td>Stage 01 A</td>"), at("<td>Stage 01 B</td>"));
    EXPECT_EQ(at("<td>Stage 01 C</td>"), std::string::npos);  // passed by everyone
    EXPECT_NE(at("bad&lt;1&gt;"), std::string::npos);         // left out, escaped
    EXPECT_EQ(at("bad<1>"), std::string::npos);
}

TEST(DashboardFileUrl, EncodesThePath) {
    EXPECT_EQ(file_url("/a b/tree"), "file:///a%20b/tree/");
}

}  // namespace
}  // namespace rt::grader
