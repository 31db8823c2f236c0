// Taking in a submission (a folder, a .zip, or "." for the working tree): only the student
// files of the graded stages are read; everything else is listed as ignored. Trusted code.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "course/manifest.h"
#include "grading/grade.h"

namespace rt::grader {

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
