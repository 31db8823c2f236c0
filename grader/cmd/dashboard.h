// The class dashboard: OUT/index.html of a batch (`rt-grade batch`, `rt-grade dashboard OUT`).
// Built only from what the batch wrote (OUT/NAME/results.json, OUT/NAME/renders/), so it can be
// rebuilt after a regrade. Reading and counting: dashboard_data.cpp; the page: dashboard.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace rt::grader {

// One test of one submission, as its results.json says.
struct DashTest {
    std::string name;
    int stage = 0;  // from its "stageNN" tag; 0: none
    bool passed = false;
    bool image = false;              // an image test (tag "image")
    std::vector<std::string> hints;  // handout sections its output names
    std::string render;              // failing image test: its image, relative to OUT ("" none)
    std::uint64_t render_hash = 0;   // of the image's bytes: equal images, equal hashes
};

struct DashSubmission {
    std::string name;      // its folder under OUT
    std::string students;  // OUT/NAME/students.txt (a Gradescope export's submitters), or empty
    double score = 0, max_score = 0;
    double seconds = 0;                               // results.json's execution_time
    std::map<int, std::pair<double, double>> stages;  // stage -> (points, of max)
    std::vector<DashTest> tests;
};

// Beside results.json, the students of a submission from a Gradescope export, one line
// ("Ada Byron (101)"); `rt-grade batch` writes it.
inline constexpr const char* kStudentsFile = "students.txt";

struct ClassResults {
    std::vector<DashSubmission> submissions;  // in name order
    std::vector<std::string> problems;        // one line per folder that could not be read
};

// Every OUT/*/results.json. A folder without one, or with one that is not Gradescope's format,
// is a line in `problems` (and a warning in `log`), never an error.
ClassResults read_class_results(const std::filesystem::path& out, std::ostream& log);

// A stage's scores in percent of its points: ten bins of 10 points below full marks, and full
// marks (bin 10). 99.9% is bin 9.
constexpr int kHistogramBins = 11;
struct StageHistogram {
    int stage = 0;
    std::array<int, kHistogramBins> counts{};
    double mean = 0, median = 0;  // percent
    int graded = 0;
};
std::vector<StageHistogram> stage_histograms(const ClassResults& results);

// How many submissions failed a test (or an image test: a scene), worst first.
struct TestFailures {
    std::string name;
    int stage = 0;
    int failed = 0, graded = 0;
    std::vector<std::pair<std::string, int>> hints;  // handout section, failures naming it
    std::string common_render;  // image tests: the most common failing image (relative to OUT)
    int common_count = 0;       // how many failing submissions rendered exactly that image
};
std::vector<TestFailures> test_failures(const ClassResults& results, bool images);

// Run times in seconds: min, median, max (all 0 without submissions).
std::array<double, 3> run_time_summary(const ClassResults& results);

// OUT/index.html from OUT/*/results.json. `handout_base` is put before a handout section
// ("stages/02-.../README.md#ray-sphere") to make its link. Returns the submissions read; with
// none, nothing is written.
int write_dashboard(const std::filesystem::path& out, const std::string& handout_base,
                    std::ostream& log);
// The same at the end of a batch: the grades are written already, so a failure is a warning.
void write_batch_dashboard(const std::filesystem::path& out, const std::string& handout_base,
                           std::ostream& log);

// "file:///abs/tree/" (percent-encoded): handout links for the machine that graded.
std::string file_url(const std::filesystem::path& dir);

}  // namespace rt::grader
