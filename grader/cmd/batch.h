// `rt-grade batch` and `rt-grade package` (batch.cpp).
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "grading/grade.h"

namespace rt::grader {

// Grades every submission (folder or .zip) in `dir`, `jobs` at a time, into `out` (one CSV).
// `dir` may be Gradescope's "Export Submissions" (folder or .zip, cmd/batch_input.h): the CSV
// then names each submission's students, and changes.csv compares the new scores with
// Gradescope's; `latest_only` grades only the newest submission of each student.
int run_batch(const GradeOptions& base, const std::filesystem::path& dir,
              const std::filesystem::path& out, int jobs, bool latest_only, std::ostream& log);

// The Gradescope zip. `stages` (empty: every stage with a grading.json) are the stages its
// run_autograder grades: one assignment per stage or per group of stages. `max_per_day` > 0:
// run_autograder grades at most that many submissions per student in any 24 hours
// (grading/rate_limit.h).
int run_package(const std::filesystem::path& source, const std::filesystem::path& out,
                const std::vector<int>& stages, int max_per_day, std::ostream& log);

}  // namespace rt::grader
