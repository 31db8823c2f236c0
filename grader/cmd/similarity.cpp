// `rt-grade similarity`: every pair of submissions compared per student file by Debian's
// similarity-tester, on the code each student wrote (the starter tree's text taken out first).
#include "cmd/similarity.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "cmd/similarity_report.h"
#include "course/manifest.h"
#include "grading/intake.h"
#include "release/release.h"
#include "util.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

constexpr const char* kInstall =
    "install it: apt-get install similarity-tester (scripts/install-deps.sh lists it)";

// The similarity tester's tools, and GNU diff, which takes the starter text out.
struct Tools {
    fs::path sim_cpp, sim_text, diff;
};

// `name` in a folder of $PATH, or empty.
fs::path find_program(const std::string& name) {
    const char* env = std::getenv("PATH");
    std::stringstream path(env ? env : "/usr/bin:/bin");
    std::string folder;
    while (std::getline(path, folder, ':')) {
        const fs::path candidate = fs::path(folder.empty() ? "." : folder) / name;
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec) && access(candidate.c_str(), X_OK) == 0)
            return fs::absolute(candidate);
    }
    return {};
}

// Finds the tools; false with `problem` naming the missing one and the fix.
bool find_tools(Tools& tools, std::string& problem) {
    tools = {find_program("sim_c++"), find_program("sim_text"), find_program("diff")};
    if (tools.sim_cpp.empty() || tools.sim_text.empty())
        problem = "sim_c++ or sim_text not found on PATH; " + std::string(kInstall);
    else if (tools.diff.empty())
        problem = "diff not found on PATH; install it: apt-get install diffutils";
    return problem.empty();
}

// The submissions, as `rt-grade batch` finds them: each folder or .zip in `dir`, sorted (the
// report's own folder left out when it is inside `dir`).
std::vector<fs::path> list_submissions(const fs::path& dir, const fs::path& out) {
    std::vector<fs::path> found;
    std::error_code ec;
    const fs::path own = fs::weakly_canonical(fs::absolute(out), ec);
    for (const auto& e : fs::directory_iterator(dir)) {
        if (fs::weakly_canonical(e.path(), ec) == own) continue;
        if (e.is_directory() || e.path().extension() == ".zip") found.push_back(e.path());
    }
    std::sort(found.begin(), found.end());
    return found;
}

// One submission's student files through the grader's intake (zips, whole trees, stage folders
// and loose files alike); what it could not take becomes a note.
CohortMember take_member(const fs::path& submission, const SimilarityRequest& request,
                         const std::vector<StageSpec>& graded) {
    CohortMember m;
    m.name = submission.filename().string();
    if (m.name.ends_with(".zip")) m.name.resize(m.name.size() - 4);
    m.name = clean_output(m.name);
    GradeOptions options;
    options.source = request.source;
    options.submission = submission;
    try {
        Intake in = take_in(options, graded, graded, request.source);
        m.files = std::move(in.files);
        for (const auto& [key, why] : in.rejected) m.notes.push_back(key + ": " + why);
        if (!in.error.empty()) m.notes.push_back(in.error);
        std::error_code ec;
        if (!in.temp.empty()) fs::remove_all(in.temp, ec);
    } catch (const std::exception& e) {
        m.notes.push_back(clean_output(e.what()));
    }
    if (m.files.empty() && m.notes.empty()) m.notes.push_back("no student file found");
    return m;
}

// The submitted text with every line the starter file also has (white space aside) blanked, so
// only the student's own code is compared and line numbers still point into the submission.
std::string own_code(const Tools& tools, const fs::path& starter, const fs::path& submitted) {
    std::string out;
    const int code =
        run_argv({tools.diff.string(), "-w", "--old-line-format=", "--new-line-format=%L",
                  "--unchanged-line-format=\n", starter.string(), submitted.string()},
                 submitted.parent_path(), out);
    if (code != 0 && code != 1)  // 1: the files differ
        throw std::runtime_error("diff failed on " + submitted.string() + ": " + out);
    return out;
}

// Runs the similarity tester in `folder` on `names`; its standard output.
std::string run_sim(const fs::path& tool, const std::vector<std::string>& options,
                    const std::vector<std::string>& names, const fs::path& folder) {
    std::vector<std::string> argv{tool.string()};
    argv.insert(argv.end(), options.begin(), options.end());
    argv.insert(argv.end(), names.begin(), names.end());
    std::string out;
    if (const int code = run_argv(argv, folder, out); code != 0)
        throw std::runtime_error(tool.filename().string() + " exited with " + std::to_string(code) +
                                 " in " + folder.string() + ": " +
                                 clean_output(out.substr(0, 300)));
    return out;
}

// The cohort index a scratch file name ("12.cpp") stands for.
std::size_t member_of(const std::string& name) {
    return std::stoul(name.substr(0, name.find('.')));
}

// What sim_c++ -p says ("3.cpp consists for 87 % of 5.cpp material"), into `pairs`; and the
// token counts of its header ("File 3.cpp: 1257 tokens, 164 lines") into the cohort.
void read_percentages(const std::string& output, const std::string& key,
                      std::map<std::pair<std::size_t, std::size_t>, SimilarityPair>& pairs,
                      std::vector<CohortMember>& cohort) {
    static const std::regex percent(R"(^(\S+) consists for (\d+) % of (\S+) material)");
    static const std::regex tokens(R"(^File (\S+): (\d+) tokens)");
    std::istringstream lines(output);
    std::string line;
    std::smatch m;
    while (std::getline(lines, line)) {
        if (std::regex_search(line, m, tokens)) {
            cohort[member_of(m[1])].tokens[key] = std::stoi(m[2]);
            continue;
        }
        if (!std::regex_search(line, m, percent)) continue;
        const std::size_t from = member_of(m[1]), to = member_of(m[3]);
        SimilarityPair& p = pairs[{std::min(from, to), std::max(from, to)}];
        (from < to ? p.a_in_b : p.b_in_a) = std::stoi(m[2]);
    }
}

// The regions of sim_c++ -n ("3.cpp: line 14-40 |5.cpp: line 2-30 [211]"), a pair's a first.
void read_runs(const std::string& output,
               std::map<std::pair<std::size_t, std::size_t>, SimilarityPair>& pairs) {
    static const std::regex run(
        R"(^(\S+): line (\d+)-(\d+)\s*\|(\S+): line (\d+)-(\d+)\s*\[(\d+)\])");
    std::istringstream lines(output);
    std::string line;
    std::smatch m;
    while (std::getline(lines, line)) {
        if (!std::regex_search(line, m, run)) continue;
        std::size_t a = member_of(m[1]), b = member_of(m[4]);
        SimilarityRun r{std::stoi(m[2]), std::stoi(m[3]), std::stoi(m[5]), std::stoi(m[6]),
                        std::stoi(m[7])};
        if (a > b) {
            std::swap(a, b);
            std::swap(r.a_first, r.b_first);
            std::swap(r.a_last, r.b_last);
        }
        const auto p = pairs.find({a, b});
        if (p != pairs.end()) p->second.runs.push_back(r);
    }
}

// C-like files (C++, GLSL) go to sim_c++, which ignores layout, comments and identifier names;
// anything else to sim_text.
bool c_like(const std::string& key) {
    const std::string ext = fs::path(key).extension().string();
    return ext == ".cpp" || ext == ".h" || ext == ".hpp" || ext == ".cc" || ext == ".glsl";
}

// One student file across the cohort: the starter text taken out of each copy, then every pair
// compared in isolation (-e), in both directions (-a) for the percentages.
void compare_file(const std::string& key, const fs::path& folder, const Tools& tools,
                  const SimilarityRequest& request, SimilarityReport& report) {
    fs::create_directories(folder);
    const MarkerResult starter =
        process_markers(read_text(request.source / key), RegionMode::Strip);
    const fs::path starter_file = folder / "starter";
    write_text(starter_file, starter.text);
    const std::string ext = fs::path(key).extension().string();
    std::vector<std::string> names;
    for (std::size_t i = 0; i < report.cohort.size(); ++i) {
        const auto f = report.cohort[i].files.find(key);
        if (f == report.cohort[i].files.end()) continue;
        const std::string name = std::to_string(i) + ext;
        write_text(folder / ("submitted-" + name), f->second);
        const std::string own = own_code(tools, starter_file, folder / ("submitted-" + name));
        if (trim(own).empty()) continue;  // the starter file as released: nothing to compare
        write_text(folder / name, own);
        names.push_back(name);
    }
    if (names.size() < 2) return;
    const fs::path& tool = c_like(key) ? tools.sim_cpp : tools.sim_text;
    std::map<std::pair<std::size_t, std::size_t>, SimilarityPair> pairs;
    read_percentages(run_sim(tool, {"-p", "-e", "-a", "-t", "1"}, names, folder), key, pairs,
                     report.cohort);
    read_runs(run_sim(tool, {"-e", "-s", "-n"}, names, folder), pairs);
    for (auto& [ab, pair] : pairs) {
        pair.file = key;
        pair.a = ab.first;
        pair.b = ab.second;
        report.pairs.push_back(std::move(pair));
    }
}

// The stages whose student files are compared: --stages, or every graded stage.
std::vector<StageSpec> chosen_stages(const SimilarityRequest& request) {
    std::vector<StageSpec> all = load_stage_specs(request.source), chosen;
    for (auto& s : all)
        if (request.stages.empty() ||
            std::count(request.stages.begin(), request.stages.end(), s.number))
            chosen.push_back(std::move(s));
    return chosen;
}

// Removes the scratch folder however the comparison ends.
struct Scratch {
    fs::path path;
    ~Scratch() {
        std::error_code ec;
        if (!path.empty()) fs::remove_all(path, ec);
    }
};

// The one-line problem with the request, or "".
std::string check_request(const SimilarityRequest& request, std::size_t submissions) {
    const std::string dir = request.dir.string();
    std::error_code ec;
    if (!fs::is_directory(request.source / "stages", ec))
        return "--source " + request.source.string() +
               ": not a course tree (no stages/ folder); give the instructor's tree";
    if (fs::exists(request.out, ec) && !fs::is_directory(request.out, ec))
        return "--out " + request.out.string() +
               ": is a file; name a folder for index.html and pairs.csv (it is created)";
    if (submissions < 2)
        return dir + ": " + std::to_string(submissions) +
               " submission(s) found; put one folder or .zip per student in it (at least two)";
    return "";
}

}  // namespace

int run_similarity(const SimilarityRequest& request, std::ostream& log, std::ostream& errors) {
    const auto fail = [&](const std::string& message) {
        errors << "rt-grade similarity: error: " << message << "\n";
        return 1;
    };
    std::error_code ec;
    if (!fs::is_directory(request.dir, ec))
        return fail(request.dir.string() +
                    ": no such folder; give the folder that holds one folder or .zip per "
                    "submission");
    Tools tools;
    if (std::string problem; !find_tools(tools, problem)) return fail(problem);
    const std::vector<fs::path> submissions = list_submissions(request.dir, request.out);
    if (const std::string problem = check_request(request, submissions.size()); !problem.empty())
        return fail(problem);
    const std::vector<StageSpec> stages = chosen_stages(request);
    if (stages.empty())
        return fail(
            "--stages: no graded stage among them; name stages that have a "
            "stages/NN-name/grading.json");

    SimilarityReport report;
    report.dir = request.dir;
    report.threshold = request.threshold;
    report.tool =
        "sim_c++ -p -e -a (percentages), sim_c++ -e -s -n (regions); sim_text for "
        "other files";
    for (const fs::path& s : submissions) report.cohort.push_back(take_member(s, request, stages));
    char scratch_template[] = "/tmp/rt-grade-similarity-XXXXXX";
    if (!mkdtemp(scratch_template)) return fail("cannot create a folder in /tmp; free space");
    const Scratch scratch{scratch_template};
    int folder = 0;
    for (const StageSpec& s : stages)
        for (const std::string& f : s.student_files)
            compare_file(s.folder + "/" + f, scratch.path / std::to_string(folder++), tools,
                         request, report);
    std::stable_sort(
        report.pairs.begin(), report.pairs.end(),
        [](const SimilarityPair& x, const SimilarityPair& y) { return x.score() > y.score(); });
    write_similarity_report(report, request.out);
    const auto flagged =
        std::count_if(report.pairs.begin(), report.pairs.end(),
                      [&](const SimilarityPair& p) { return p.score() >= request.threshold; });
    log << "similarity: " << report.cohort.size() << " submissions, " << report.pairs.size()
        << " file pairs with a match, " << flagged << " at or above " << request.threshold
        << "%: " << (request.out / "index.html").string() << "\n";
    return 0;
}

}  // namespace rt::grader
