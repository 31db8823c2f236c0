// Gradescope rate limits: at most N graded submissions in any 24 hours per student.
//
// Gradescope writes /autograder/submission_metadata.json before run_autograder: this
// submission's time (`created_at`) and every earlier one (`previous_submissions`, each with its
// `submission_time`, `score` and `results`, the results.json it got). A submission beyond the
// limit is not graded: its results.json repeats the latest graded submission's score and tests
// and says when the next graded submission is possible. Everything is computed from the
// submission times in the metadata, never from the clock, so a rerun of the same submission
// gives the same answer. A submission that was itself refused carries `extra_data.rate_limited`
// in its results and does not count against the limit.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

namespace rt::grader {

struct RateLimit {
    int max_graded = 0;  // per window; 0: no limit
    std::chrono::seconds window{std::chrono::hours(24)};
};

// The results.json of a refused submission, or nothing when this one is to be graded.
// Throws std::runtime_error naming the metadata file and the field when it cannot be read.
std::optional<std::string> rate_limited_results(const std::filesystem::path& metadata,
                                                const RateLimit& limit);

}  // namespace rt::grader
