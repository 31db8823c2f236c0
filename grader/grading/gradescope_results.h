// Gradescope's results.json (https://gradescope-autograders.readthedocs.io/en/latest/specs/) as
// one type with one writer and one reader: a grading writes it (report.h), a submission the rate
// limit refuses writes the latest graded one's again (rate_limit.h), and the class dashboard reads
// a batch's back (cmd/dashboard.h).
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace rt::grader {

struct GradescopeTest {
    std::string name, number;  // number: "" leaves it out
    bool passed = false;
    double score = 0, max_score = 0;
    std::string output;
    std::vector<std::string> tags;
    // "visible", "hidden", "after_due_date" or "after_published"; "": left out.
    std::string visibility;
};

// One column of Gradescope's leaderboard ("order": "asc" when lower is better).
struct LeaderboardEntry {
    std::string name;
    double value = 0;
    bool ascending = false;
};

struct GradescopeResults {
    double score = 0;
    double execution_time = 0;  // seconds (written as a whole number, rounded up)
    std::string output;         // shown above the tests; the build log stays hidden
    std::vector<GradescopeTest> tests;
    std::vector<LeaderboardEntry> leaderboard;  // empty: no "leaderboard"
    // A submission the rate limit refused: when the next graded one is possible, as rate_limit.cpp
    // writes it ("2026-12-05 08:00 UTC"); written as extra_data.rate_limited and next_graded_at.
    // "": graded.
    std::string next_graded_at;
};

// The one writer: the JSON text, every output cleaned for Gradescope's page (util.h's
// clean_output), ending in a newline.
std::string results_json_text(const GradescopeResults& results);

// The one reader, as lenient as its readers need: a missing field reads as its default, a score
// written as a string ("20.0", as Gradescope's metadata has it) as its number. nullopt, with
// `why`, when `text` is not a JSON object with a "tests" list of named tests.
std::optional<GradescopeResults> read_results_json(const std::string& text, std::string& why);
// The same for results already parsed (Gradescope's metadata holds them inside its own JSON).
std::optional<GradescopeResults> read_results_json(const nlohmann::json& results, std::string& why);

}  // namespace rt::grader
