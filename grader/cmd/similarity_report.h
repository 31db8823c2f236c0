// What `rt-grade similarity` found, and the pages it writes from it (similarity_report.cpp).
#pragma once

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace rt::grader {

// One matching region as the similarity tester reports it: 1-based line ranges in both files.
struct SimilarityRun {
    int a_first = 0, a_last = 0, b_first = 0, b_last = 0;
    int tokens = 0;
};

// Two submissions' copies of one student file.
struct SimilarityPair {
    std::string file;            // "stages/NN-name/file"
    std::size_t a = 0, b = 0;    // indices into the cohort, a < b
    int a_in_b = 0, b_in_a = 0;  // percent of a's own code found in b, and the reverse
    std::vector<SimilarityRun> runs;
    // The larger share: a student who copied one function out of a longer file is still caught.
    int score() const { return std::max(a_in_b, b_in_a); }
};

struct CohortMember {
    std::string name;                          // the folder, or the zip without .zip
    std::map<std::string, std::string> files;  // "stages/NN-name/file" -> text as submitted
    std::map<std::string, int> tokens;         // the tokens of the student's own code, per file
    std::vector<std::string> notes;            // what could not be compared, and why
};

struct SimilarityReport {
    std::filesystem::path dir;
    double threshold = 0;
    std::vector<CohortMember> cohort;
    std::vector<SimilarityPair> pairs;  // every pair compared, highest score first
    std::string tool;                   // the similarity tester's command line, for the record
};

// out/index.html (pairs at or above the threshold, each with its regions side by side) and
// out/pairs.csv (every pair), both written atomically.
void write_similarity_report(const SimilarityReport& report, const std::filesystem::path& out);

}  // namespace rt::grader
