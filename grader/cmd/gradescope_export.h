// Gradescope's "Export Submissions" as the input of `rt-grade batch`: a folder (or a .zip of it)
// holding one folder per submission and submission_metadata.yml, which maps each folder to its
// submitters (name, student id, email), its time and the score Gradescope gave it:
//   submission_123456:
//     :submitters:
//     - :name: A Student
//       :sid: '1234'
//       :email: student@example.com
//     :created_at: 2026-12-01 14:22:32.365935000 -0800
//     :score: 12.0
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rt::grader {

struct ExportedSubmission {
    std::filesystem::path path;       // the submission's folder
    std::string folder;               // its name in the export, e.g. submission_123456
    std::string names, sids, emails;  // of every submitter (a group), joined by "; "
    std::string student;              // the key of "latest per student": sids, else emails
    std::int64_t time = 0;            // :created_at, seconds since the epoch (UTC)
    std::optional<double> old_score;  // :score, when Gradescope had one
};

// The submission folder of an export: `dir` itself, or the one folder inside it (an unpacked
// zip), whichever holds submission_metadata.yml; nothing when `dir` is not an export.
std::optional<std::filesystem::path> export_root(const std::filesystem::path& dir);

// Every submission the metadata lists whose folder exists, oldest first. Throws
// std::runtime_error naming the metadata file, the submission and the field when it is malformed.
std::vector<ExportedSubmission> read_gradescope_export(const std::filesystem::path& root);

// The newest submission of each student, in the order of `all`.
std::vector<ExportedSubmission> latest_per_student(const std::vector<ExportedSubmission>& all);

}  // namespace rt::grader
