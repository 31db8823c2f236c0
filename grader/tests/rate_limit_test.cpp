// The rate limit's decision from Gradescope's submission metadata (grading/rate_limit.h).
#include "grading/rate_limit.h"
#include "util.h"  // parse_iso8601

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace rt::grader {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// An earlier submission at `time` with `score`; `refused`: it was itself rate limited.
json earlier(const std::string& time, double score, bool refused = false) {
    json results = {
        {"score", score},
        {"tests",
         json::array(
             {{{"name", "Stage 01 Perspective.Center"}, {"score", score}, {"max_score", 10}}})}};
    if (refused) results["extra_data"] = {{"rate_limited", true}};
    return {{"submission_time", time}, {"score", score}, {"results", results}};
}

fs::path write_metadata(const std::string& created_at, const json& previous) {
    // A file of this test's own: CTest runs the tests of this file as processes side by side.
    const fs::path file =
        fs::path(::testing::TempDir()) /
        (std::string("metadata-") +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".json");
    std::ofstream(file)
        << json{{"id", 7}, {"created_at", created_at}, {"previous_submissions", previous}}.dump();
    return file;
}

std::optional<json> decide(const std::string& created_at, const json& previous, int max) {
    const auto text = rate_limited_results(write_metadata(created_at, previous), RateLimit{max});
    if (!text) return std::nullopt;
    return json::parse(*text);
}

TEST(RateLimit, ParsesGradescopeTimes) {
    EXPECT_EQ(parse_iso8601("1970-01-01T00:00:00Z"), 0);
    EXPECT_EQ(parse_iso8601("1970-01-02T00:00:00.5+00:00"), 86400);
    // The same instant written in two time zones.
    EXPECT_EQ(parse_iso8601("2018-07-01T14:22:32.365935-07:00"),
              parse_iso8601("2018-07-01T21:22:32Z"));
    EXPECT_EQ(parse_iso8601("2018-07-01 14:22:32.365935000 -0700"),
              parse_iso8601("2018-07-01T21:22:32Z"));
    for (const char* bad : {"", "2018-07-01", "2018-13-01T00:00:00Z", "2018-02-30T00:00:00Z",
                            "2018-07-01T14:22:32+7", "yesterday"})
        EXPECT_FALSE(parse_iso8601(bad)) << bad;
}

TEST(RateLimit, UnderTheLimitIsGraded) {
    const json previous = {earlier("2026-12-04T08:00:00Z", 3)};
    EXPECT_FALSE(decide("2026-12-04T09:00:00Z", previous, 2));
    EXPECT_FALSE(decide("2026-12-04T09:00:00Z", previous, 0)) << "0: no limit";
}

TEST(RateLimit, AtTheLimitRepeatsTheLatestGradedAndSaysWhen) {
    const json previous = {earlier("2026-12-04T08:00:00Z", 3), earlier("2026-12-04T10:30:00Z", 7)};
    const auto r = decide("2026-12-04T12:00:00+01:00", previous, 2);  // 11:00 UTC
    ASSERT_TRUE(r);
    EXPECT_EQ((*r)["score"], 7);
    EXPECT_EQ((*r)["tests"].size(), 1u);
    EXPECT_EQ((*r)["extra_data"]["rate_limited"], true);
    // The earlier of the two leaves the window 24 hours after it was made.
    EXPECT_EQ((*r)["extra_data"]["next_graded_at"], "2026-12-05 08:00 UTC");
    const std::string output = (*r)["output"];
    EXPECT_NE(output.find("2026-12-05 08:00 UTC (21 h 0 min after this one)"), std::string::npos)
        << output;
}

TEST(RateLimit, OnlyGradedSubmissionsInsideTheWindowCount) {
    const json previous = {earlier("2026-12-03T09:00:00Z", 1),        // 26 h before: outside
                           earlier("2026-12-04T08:00:00Z", 5, true),  // refused: not counted
                           earlier("2026-12-04T10:00:00Z", 6),
                           earlier("2026-12-04T12:00:00Z", 9)};  // after this one: a regrade
    EXPECT_FALSE(decide("2026-12-04T11:00:00Z", previous, 2));
    EXPECT_TRUE(decide("2026-12-04T11:00:00Z", previous, 1));
}

TEST(RateLimit, TheSameSubmissionGetsTheSameAnswer) {
    const json previous = {earlier("2026-12-04T08:00:00Z", 3)};
    const fs::path file = write_metadata("2026-12-04T09:00:00Z", previous);
    EXPECT_EQ(rate_limited_results(file, RateLimit{1}), rate_limited_results(file, RateLimit{1}));
}

TEST(RateLimit, UnreadableMetadataNamesTheFileAndTheField) {
    const fs::path file = write_metadata("soon", json::array());
    try {
        rate_limited_results(file, RateLimit{1});
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(file.string()), std::string::npos) << what;
        EXPECT_NE(what.find("\"created_at\""), std::string::npos) << what;
    }
    EXPECT_THROW(rate_limited_results("/nonexistent/metadata.json", RateLimit{1}),
                 std::runtime_error);
}

}  // namespace
}  // namespace rt::grader
