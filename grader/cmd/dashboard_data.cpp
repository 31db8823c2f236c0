// The class dashboard's numbers (cmd/dashboard.h): a batch's results.json files read back, and
// counted per stage, per test and per scene.

#include <algorithm>
#include <cmath>

#include "cmd/dashboard.h"
#include "grading/gradescope_results.h"
#include "grading/report.h"
#include "grading/test_output.h"
#include "util.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

// "stage02" -> 2; 0 when no tag names a stage.
int stage_of(const std::vector<std::string>& tags) {
    for (const std::string& t : tags) {
        if (t.size() == 7 && t.starts_with("stage") && std::isdigit((unsigned char)t[5]) &&
            std::isdigit((unsigned char)t[6]))
            return (t[5] - '0') * 10 + (t[6] - '0');
    }
    return 0;
}

bool has_tag(const std::vector<std::string>& tags, const std::string& wanted) {
    return std::find(tags.begin(), tags.end(), wanted) != tags.end();
}

// A failing image test's render, kept by the batch beside results.json (report.h).
void find_render(const fs::path& out, const std::string& submission, DashTest& t) {
    const fs::path rel = fs::path(submission) / "renders" / render_png_name(t.name);
    std::string bytes;
    if (!read_text_if(out / rel, bytes)) return;
    t.render = rel.generic_string();
    t.render_hash = fnv1a(bytes);
}

// A test of results.json as the dashboard counts it.
DashTest dash_test(const GradescopeTest& g) {
    DashTest t;
    t.name = g.name;
    t.stage = stage_of(g.tags);
    t.image = has_tag(g.tags, "image");
    t.passed = g.passed;
    t.hints = handout_hints(g.output);
    return t;
}

// OUT/NAME/results.json; false (with `why`) when it is missing or not Gradescope's format.
bool read_submission(const fs::path& out, DashSubmission& s, std::string& why) {
    const fs::path file = out / s.name / "results.json";
    std::string body;
    if (!fs::is_regular_file(file) || !read_text_if(file, body)) {
        why = "missing or unreadable";
        return false;
    }
    const std::optional<GradescopeResults> results = read_results_json(body, why);
    if (!results) return false;
    s.seconds = results->execution_time;
    read_text_if(out / s.name / kStudentsFile, s.students);
    while (!s.students.empty() && s.students.back() == '\n') s.students.pop_back();
    for (const GradescopeTest& g : results->tests) {
        DashTest t = dash_test(g);
        s.score += g.score;
        s.max_score += g.max_score;
        if (t.stage > 0) {
            s.stages[t.stage].first += g.score;
            s.stages[t.stage].second += g.max_score;
        }
        if (t.image && !t.passed) find_render(out, s.name, t);
        s.tests.push_back(std::move(t));
    }
    return true;
}

double median_of(std::vector<double> values) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

}  // namespace

ClassResults read_class_results(const fs::path& out, std::ostream& log) {
    ClassResults r;
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(out, ec))
        // A hidden folder is a tool's (a Slurm batch's .slurm), not a submission's.
        if (e.is_directory() && !e.path().filename().string().starts_with("."))
            names.push_back(e.path().filename().string());
    if (ec) throw std::runtime_error("cannot list " + out.string() + " (" + ec.message() + ")");
    std::sort(names.begin(), names.end());
    for (const auto& name : names) {
        DashSubmission s;
        s.name = name;
        std::string why;
        if (read_submission(out, s, why)) {
            r.submissions.push_back(std::move(s));
            continue;
        }
        const std::string file = (out / name / "results.json").string();
        r.problems.push_back(file + ": " + why + ", left out");
        log << "rt-grade: warning: " << r.problems.back() << "\n";
    }
    // An export's folders are numbers (submission_123456): its students' names order it.
    std::stable_sort(r.submissions.begin(), r.submissions.end(),
                     [](const auto& a, const auto& b) { return a.students < b.students; });
    return r;
}

std::vector<StageHistogram> stage_histograms(const ClassResults& results) {
    std::map<int, std::vector<double>> percents;
    for (const auto& s : results.submissions)
        for (const auto& [stage, points] : s.stages)
            if (points.second > 0) percents[stage].push_back(100 * points.first / points.second);
    std::vector<StageHistogram> out;
    for (const auto& [stage, values] : percents) {
        StageHistogram h;
        h.stage = stage;
        h.graded = int(values.size());
        double sum = 0;
        for (const double p : values) {
            // Rounding in results.json (points to 2 decimals) must not drop full marks a bin.
            const int bin = p >= 99.995 ? kHistogramBins - 1 : std::clamp(int(p / 10), 0, 9);
            ++h.counts[std::size_t(bin)];
            sum += p;
        }
        h.mean = sum / double(values.size());
        h.median = median_of(values);
        out.push_back(h);
    }
    return out;
}

namespace {

// One test's failures being counted: its handout sections and its failing images.
struct Tally {
    TestFailures f;
    std::map<std::string, int> hints;
    std::map<std::uint64_t, std::pair<int, std::string>> renders;  // hash -> (count, an image)
    std::vector<std::uint64_t> render_order;                       // first seen first (ties)
};

void count_failure(Tally& tally, const DashTest& t) {
    ++tally.f.failed;
    for (const auto& h : t.hints) ++tally.hints[h];
    if (t.render.empty()) return;
    auto [it, fresh] = tally.renders.try_emplace(t.render_hash, 0, t.render);
    if (fresh) tally.render_order.push_back(t.render_hash);
    ++it->second.first;
}

TestFailures finish(Tally& tally) {
    TestFailures f = std::move(tally.f);
    f.hints.assign(tally.hints.begin(), tally.hints.end());
    std::stable_sort(f.hints.begin(), f.hints.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    for (const std::uint64_t hash : tally.render_order) {
        const auto& [count, file] = tally.renders[hash];
        if (count > f.common_count) {
            f.common_count = count;
            f.common_render = file;
        }
    }
    return f;
}

}  // namespace

std::vector<TestFailures> test_failures(const ClassResults& results, bool images) {
    std::map<std::string, Tally> tallies;
    for (const auto& s : results.submissions)
        for (const auto& t : s.tests) {
            if (t.image != images) continue;
            Tally& tally = tallies[t.name];
            tally.f.name = t.name;
            tally.f.stage = t.stage;
            ++tally.f.graded;
            if (!t.passed) count_failure(tally, t);
        }
    std::vector<TestFailures> out;
    for (auto& [name, tally] : tallies) out.push_back(finish(tally));
    // Worst first: the highest failure rate, then the most failures; ties by name (map order).
    std::stable_sort(out.begin(), out.end(), [](const TestFailures& a, const TestFailures& b) {
        const double ra = double(a.failed) / a.graded, rb = double(b.failed) / b.graded;
        return ra != rb ? ra > rb : a.failed > b.failed;
    });
    return out;
}

std::array<double, 3> run_time_summary(const ClassResults& results) {
    std::vector<double> seconds;
    for (const auto& s : results.submissions) seconds.push_back(s.seconds);
    if (seconds.empty()) return {0, 0, 0};
    const auto [min, max] = std::minmax_element(seconds.begin(), seconds.end());
    return {*min, median_of(seconds), *max};
}

}  // namespace rt::grader
