// A grading's results in the forms of the platforms besides Gradescope (whose results.json is
// report.h's): PrairieLearn's external-grader results.json and Autolab's score line.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "grading/report.h"

namespace rt::grader {

// PrairieLearn's results.json (its external grading documentation): score in [0, 1], tests with
// points, max_points, message and output, failing scenes' images as data URLs; at most 1 MiB
// (outputs are shortened, then images left out, to fit). `gradable` false: nothing could be
// graded (or grading did not finish), with `why` as the message; PrairieLearn then counts the
// submission as not graded instead of scoring it 0. Written atomically.
void write_prairielearn_results(const Report& report, const std::filesystem::path& file,
                                bool gradable, const std::string& why);

// Autolab's scores as one line of JSON, {"scores": {PROBLEM: points, ...}, "scoreboard":
// [total, per stage...]}; `names` maps a stage number to its Autolab problem name (default: the
// stage's folder name, "01-camera-rays").
std::string autolab_scores_line(const std::map<int, double>& stage_scores,
                                const std::map<int, std::string>& names);

}  // namespace rt::grader
