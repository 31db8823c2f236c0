// What `rt-grade batch` grades: the submissions (folders or .zip files) of a folder, or
// Gradescope's "Export Submissions" (a folder or its .zip), whose submitters, times and old
// scores go into the CSV (cmd/gradescope_export.h).
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cmd/gradescope_export.h"

namespace rt::grader {

struct BatchEntry {
    std::filesystem::path path;                  // a folder or a .zip
    std::string name;                            // its row and its report folder
    std::optional<ExportedSubmission> exported;  // from an export's metadata
    std::string refused;  // why its part of a zipped export could not be unpacked ("": it was)
};

struct BatchInput {
    std::vector<BatchEntry> entries;
    bool is_export = false;
    std::filesystem::path unpacked;  // a zipped export's temporary folder (removed by the caller)
};

// The entries of `dir` (a folder, or an export's .zip, unpacked into `unpack_into`, else a
// temporary folder), sorted; of an export, its submissions (`latest_only`: the newest of each
// student). A folder's hidden entries (".name") are not submissions. Throws std::runtime_error
// with a one-line reason when it cannot be read.
BatchInput batch_input(const std::filesystem::path& dir, bool latest_only,
                       const std::filesystem::path& unpack_into = {});

// The CSV columns an export adds after the submission's name, and after its new score.
std::string export_header();
std::string export_identity(const BatchEntry& entry);
std::string export_change(const BatchEntry& entry, double new_score);

// changes.csv's header, and the line of `entry` (of an export) regraded to `new_score`; `changed`
// is set when the score moved or Gradescope had none.
std::string changes_header();
std::string changes_line(const BatchEntry& entry, double new_score, bool& changed);

}  // namespace rt::grader
