// `rt-grade package`: the grading bundle (bundle.h) wrapped for the platform a course grades on
// (docs/grading.md, "Grading on Gradescope, PrairieLearn and Autolab"):
//   gradescope    OUT.zip: setup.sh, run_autograder, rt-grade/   (upload as the autograder)
//   prairielearn  OUT/: Dockerfile, entrypoint.sh, rt-grade/     (an image context)
//   autolab       OUT/: autograde-Makefile, autograde.tar        (the assessment's two files)
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>

#include "grading/grade.h"

namespace rt::grader {

enum class Platform { Gradescope, PrairieLearn, Autolab };
std::optional<Platform> parse_platform(const std::string& name);
std::string platform_name(Platform platform);

struct PackageRequest {
    GradeOptions grade;  // source, cache and the graded stages (empty: every stage)
    Platform platform = Platform::Gradescope;
    std::filesystem::path out;                 // empty: autograder.zip, prairielearn/ or autolab/
    int max_per_day = 0;                       // Gradescope's rate limit (0: none)
    std::map<int, std::string> problem_names;  // Autolab's problem names
};

// Prepares the workspace if needed, writes the bundle, audits it and writes the platform's
// files. Returns the exit code; progress goes to `log`, an error (one line) to `err`.
int run_package(const PackageRequest& request, std::ostream& log, std::ostream& err);

}  // namespace rt::grader
