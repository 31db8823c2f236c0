// Taking in a submission (a folder, a .zip, or "." for the working tree): only the student
// files of the graded stages are read; everything else is listed as ignored. Trusted code.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "course/manifest.h"
#include "grading/grade.h"

namespace rt::grader {

// The most a submission's files may expand to: a zip that declares more is refused unread (a zip
// bomb), whether it is uploaded alone or is one submission of an export.
inline constexpr std::uintmax_t kMaxZipBytes = 64ull << 20;

// What the entries of `zip` matching `pattern` (unzip's wildcards; every entry when empty)
// declare they expand to, in bytes; false when unzip cannot list them. The extraction itself
// runs with each file capped at kMaxZipBytes (extract_capped), so a size the listing
// understates cannot fill the disk.
bool zip_declared_bytes(const std::filesystem::path& zip, const std::string& pattern,
                        std::uintmax_t& bytes);

// unzip's command line for extracting `zip`'s entries matching `pattern` (every entry when
// empty) but those matching `exclude` into `dir`, each file limited to kMaxZipBytes; for
// run_trusted.
std::string extract_capped(const std::filesystem::path& zip, const std::string& pattern,
                           const std::filesystem::path& dir, const std::string& exclude = "");

struct Ignored {
    std::string path, reason;
};

struct Intake {
    std::filesystem::path root;                // where the files are (extracted zip or the folder)
    std::filesystem::path temp;                // to remove afterwards
    std::map<std::string, std::string> files;  // "stages/NN/file" -> content (accepted)
    std::map<std::string, std::string> rejected;  // "stages/NN/file" -> why
    std::vector<Ignored> ignored;
    int ignored_other = 0;  // files outside the whitelist beyond the listed ones
    int unchanged = 0;      // files identical to the course tree's (a whole starter tree)
    std::string error;      // the submission could not be read at all
};

// `graded`: the stages whose files are taken; `all`: every stage (a file of a stage not graded
// in this run is named as such). `ws_src`: the workspace tree (framework headers).
Intake take_in(const GradeOptions& options, const std::vector<StageSpec>& graded,
               const std::vector<StageSpec>& all, const std::filesystem::path& ws_src);

}  // namespace rt::grader
