// `rt-grade batch` (batch.cpp); `rt-grade package` is package/platforms.h's.
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

}  // namespace rt::grader
