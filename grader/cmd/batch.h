// `rt-grade batch` (batch.cpp): every submission graded here, `jobs` at a time. Its two halves,
// one submission's grading and the class's files, are also the tasks of a batch on a Slurm
// cluster (cmd/slurm.h).
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "cmd/batch_input.h"
#include "grading/grade.h"

namespace rt::grader {

// Grades every submission (folder or .zip) in `dir`, `jobs` at a time, into `out` (one CSV).
// `dir` may be Gradescope's "Export Submissions" (folder or .zip, cmd/batch_input.h): the CSV
// then names each submission's students, and changes.csv compares the new scores with
// Gradescope's; `latest_only` grades only the newest submission of each student.
int run_batch(const GradeOptions& base, const std::filesystem::path& dir,
              const std::filesystem::path& out, int jobs, bool latest_only, std::ostream& log);

// One submission's line of scores.csv.
struct BatchRow {
    std::string name;
    const BatchEntry* entry = nullptr;
    bool graded = false;
    GradeSummary summary;
    std::string error;  // what the grader threw, or why the submission was refused
    bool refused = false;
};

// Grades `entry` into OUT/NAME/ (results.json, report.html, the failing scenes' renders) with
// `jobs` test processes at a time. Never throws: what the grader threw is the row's error.
BatchRow grade_batch_entry(const GradeOptions& base, const BatchEntry& entry,
                           const std::filesystem::path& out, int jobs, std::ostream& log);

// The log's line of a graded row: "NAME: 12 / 84", or "NAME: grader error: why".
std::string batch_row_line(const BatchRow& row);

// OUT/scores.csv, OUT/changes.csv (of an export) and the dashboard OUT/index.html, from one row
// per entry of `in`, in its order.
void write_batch_outputs(const GradeOptions& base, const BatchInput& in,
                         const std::vector<BatchRow>& rows, const std::filesystem::path& out,
                         std::ostream& log);

}  // namespace rt::grader
