// `rt-grade similarity` (similarity.cpp): a plagiarism report for a cohort of submissions.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

namespace rt::grader {

// Every pair of submissions in `dir` (each a folder or .zip, as `rt-grade batch` reads them) is
// compared file by file over the stages' student files, by Debian's similarity-tester (sim_c++,
// sim_text), on what each student wrote: the starter tree's text (the pristine file with its
// solutions stripped) is taken out first. Writes `out`/index.html (the pairs at or above
// `threshold` percent, highest first, with their matching regions side by side) and
// `out`/pairs.csv (every pair compared). Returns 0, or 1 with one line on `errors` naming the
// problem and its fix.
struct SimilarityRequest {
    std::filesystem::path source;  // the instructor's tree: stage.json files, pristine sources
    std::filesystem::path dir;
    std::filesystem::path out;
    std::vector<int> stages;  // empty: every graded stage
    double threshold = 50;    // percent of a file's own code found in the other's
};
int run_similarity(const SimilarityRequest& request, std::ostream& log, std::ostream& errors);

}  // namespace rt::grader
