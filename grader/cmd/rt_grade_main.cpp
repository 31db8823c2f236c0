// rt-grade: the instructor's tool. Trusted code only -- it never links or loads student code;
// submissions are built and run in sandboxed child processes (grading/grade.h, sandbox/sandbox.h).
#include <CLI/CLI.hpp>

#include <sys/prctl.h>

#include <charconv>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cmd/batch.h"
#include "cmd/compare.h"
#include "cmd/dashboard.h"
#include "cmd/similarity.h"
#include "cmd/slurm.h"
#include "core/source_dir.h"
#include "core/text_file.h"
#include "grading/grade.h"
#include "grading/rate_limit.h"
#include "package/platforms.h"
#include "release/release.h"
#include "workspace/workspace_prepare.h"

namespace {

void on_signal(int) {
    rt::grader::g_interrupted = true;
}

// "1,2,10" -> {1, 2, 10}; false for anything else (the caller says what was expected).
bool parse_stages(const std::string& list, std::vector<int>& stages) {
    std::stringstream s(list);
    std::string item;
    while (std::getline(s, item, ',')) {
        if (item.empty()) continue;
        int n = 0;
        const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), n);
        if (ec != std::errc() || end != item.data() + item.size() || n < 1 || n > 99) return false;
        stages.push_back(n);
    }
    return true;
}

namespace fs = std::filesystem;

// What the command line says besides the subcommands' own options.
struct GradeArgs {
    rt::grader::GradeOptions grade;
    std::string submission, stages, cache;
    rt::grader::RateLimit limit;
    std::string metadata;  // Gradescope's submission_metadata.json
    std::string prairielearn_data, problem_names;
};

// The options of grading one submission (they also work after a subcommand's name).
void add_grade_options(CLI::App& app, GradeArgs& a) {
    rt::grader::GradeOptions& grade = a.grade;
    grade.source = rt::source_dir();
    app.add_option("submission", a.submission, "folder or .zip to grade ('.' : the working tree)");
    app.add_option("--stages", a.stages,
                   "comma-separated stage numbers (default: every graded stage; for '.', the "
                   "stages you have started)");
    app.add_option("--results", grade.results, "write Gradescope's results.json here");
    app.add_option("--html", grade.html,
                   "write the HTML report here (default for '.': report.html)");
    app.add_option("--source", grade.source, "the instructor's tree (default: this tree)")
        ->check(CLI::ExistingDirectory);
    if (const char* c = std::getenv("RT_GRADE_CACHE")) a.cache = c;
    app.add_option("--cache", a.cache,
                   "grading workspaces (default: $RT_GRADE_CACHE, else SOURCE/build/grader-cache)");
    app.add_option("--jobs", grade.jobs, "test processes at a time (default: all cores)");
    app.add_flag("--quiet", grade.quiet, "no terminal summary");
    app.add_option(
        "--time-limit", grade.time_limit,
        "seconds for every test and render, overriding grading.json (tests of the grader)");
    app.add_flag("--reveal-hidden", grade.reveal_hidden, "summary also lists non-visible tests");
    app.add_option("--max-per-day", a.limit.max_graded,
                   "at most N graded submissions per student in any 24 hours (needs --metadata)")
        ->check(CLI::Range(0, 1000));
    app.add_option("--metadata", a.metadata,
                   "Gradescope's submission_metadata.json (this and the earlier submissions)");
    app.add_option("--prairielearn-results", grade.prairielearn_results,
                   "write PrairieLearn's results.json here");
    app.add_option("--prairielearn-data", a.prairielearn_data,
                   "PrairieLearn's data.json: params.rt_stages (\"1,2\") replaces --stages")
        ->check(CLI::ExistingFile);
    app.add_flag("--autolab-scores", grade.autolab_scores,
                 "print Autolab's score line on stdout before the first test and after each");
    app.add_option("--problem-names", a.problem_names,
                   "Autolab's problem name of each stage, e.g. 1=camera,2=shapes (default: the "
                   "stage's folder name)");
}

// "1=camera,2=shapes" -> {1: "camera", 2: "shapes"}; false for anything else.
bool parse_problem_names(const std::string& list, std::map<int, std::string>& names) {
    std::stringstream s(list);
    std::string item;
    while (std::getline(s, item, ',')) {
        const auto eq = item.find('=');
        int n = 0;
        if (eq == std::string::npos || eq + 1 == item.size()) return false;
        const auto [end, ec] = std::from_chars(item.data(), item.data() + eq, n);
        if (ec != std::errc() || end != item.data() + eq || n < 1 || n > 99) return false;
        const std::string name = item.substr(eq + 1);
        if (name.find_first_of("\"\\") != std::string::npos || name.size() > 64) return false;
        names[n] = name;
    }
    return true;
}

// PrairieLearn's data.json: a question's params.rt_stages picks the stages it grades, so one
// image serves a question per stage. Unreadable data grades the package's stages (a warning).
void apply_prairielearn_data(const std::string& file, std::string& stages) {
    try {
        const auto data = nlohmann::json::parse(rt::read_text(file));
        const auto params = data.value("params", nlohmann::json::object());
        if (params.contains("rt_stages")) {
            const auto& v = params.at("rt_stages");
            stages = v.is_string() ? v.get<std::string>() : v.dump();
        }
    } catch (const std::exception& e) {
        std::cerr << "rt-grade: warning: " << file << ": " << e.what()
                  << " (grading the package's stages)\n";
    }
}

struct ReleaseArgs {
    rt::grader::ReleaseOptions release;
    std::string out, source = rt::source_dir().string();
};

CLI::App* add_release_command(CLI::App& app, ReleaseArgs& a) {
    rt::grader::ReleaseOptions& release = a.release;
    CLI::App* release_cmd = app.add_subcommand(
        "release",
        "Write a student starter tree: the source tree with solutions replaced by stubs");
    release_cmd->add_option("--out", a.out, "Directory to write the starter tree to")->required();
    release_cmd
        ->add_option("--source", a.source,
                     "Course source tree (default: the tree rt-grade was built from)")
        ->check(CLI::ExistingDirectory)
        ->capture_default_str();
    release_cmd
        ->add_option("--solved-through", release.solved_through,
                     "Stages 1..N keep their solutions (default 0: every stage stubbed)")
        ->check(CLI::Range(0, 99))  // stage numbers are two digits
        ->capture_default_str();
    release_cmd->add_flag("--force", release.force, "Write into a non-empty --out directory");
    release_cmd->add_flag(
        "--include-untracked", release.include_untracked,
        "Git checkout: also copy untracked files that .gitignore does not exclude");
    return release_cmd;
}

struct BatchArgs {
    std::string dir, out = "grades";
    int jobs = 1;
    bool latest = false;
    bool slurm = false, slurm_no_submit = false;
};

CLI::App* add_batch_command(CLI::App& app, BatchArgs& a) {
    CLI::App* batch_cmd =
        app.add_subcommand("batch", "Grade every submission (folder or .zip) in DIR");
    batch_cmd
        ->add_option(
            "dir", a.dir,
            "folder of submissions, or Gradescope's \"Export Submissions\" (folder or .zip)")
        ->required()
        ->check(CLI::ExistingPath);
    batch_cmd->add_flag("--latest", a.latest,
                        "of an export, grade only each student's newest submission");
    batch_cmd->add_option("--out", a.out, "where scores.csv and the reports go");
    batch_cmd->add_option("--jobs", a.jobs, "submissions graded at a time")
        ->check(CLI::Range(1, 64));
    batch_cmd->add_flag("--slurm", a.slurm,
                        "grade on a Slurm cluster: a job array of one task per submission and a "
                        "collector job (OUT on shared storage; docs/grading.md)");
    batch_cmd->add_flag("--slurm-no-submit", a.slurm_no_submit,
                        "with --slurm: write OUT/.slurm's scripts and say how to submit them");
    return batch_cmd;
}

// The two commands of a Slurm batch's jobs (cmd/slurm.h); not for typing by hand.
struct SlurmArgs {
    std::string out;
    long index = -1;
};

CLI::App* add_slurm_commands(CLI::App& app, SlurmArgs& a, CLI::App*& collect) {
    CLI::App* task = app.add_subcommand(
        "slurm-task", "One task of `batch --slurm`: grade line INDEX of OUT/.slurm/manifest.json");
    task->add_option("out", a.out, "the batch's --out folder")
        ->required()
        ->check(CLI::ExistingDirectory);
    task->add_option("index", a.index, "the manifest line (0 is the first)")->required();
    collect = app.add_subcommand("slurm-collect",
                                 "The collector of `batch --slurm`: scores.csv and the dashboard");
    collect->add_option("out", a.out, "the batch's --out folder")
        ->required()
        ->check(CLI::ExistingDirectory);
    return task;
}

int run_batch_command(const BatchArgs& b, const rt::grader::GradeOptions& grade) {
    if (b.slurm_no_submit && !b.slurm) {
        std::cerr << "rt-grade: error: --slurm-no-submit goes with --slurm\n";
        return 2;
    }
    if (!b.slurm) return rt::grader::run_batch(grade, b.dir, b.out, b.jobs, b.latest, std::cout);
    return rt::grader::run_slurm_batch(grade, {b.dir, b.out, b.latest, !b.slurm_no_submit},
                                       std::cout);
}

struct DashboardArgs {
    std::string out, handout_base;
};

CLI::App* add_dashboard_command(CLI::App& app, DashboardArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "dashboard",
        "Rebuild OUT/index.html, the class dashboard, from a batch's results.json files");
    cmd->add_option("out", a.out, "a batch's --out folder")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd->add_option("--handout-base", a.handout_base,
                    "prefix of the handout links, e.g. a repository's web address ending in / "
                    "(default: file:// of --source)");
    return cmd;
}

// `rt-grade dashboard OUT`: a folder without a single readable results.json is an error.
int run_dashboard(const DashboardArgs& a, const fs::path& source) {
    const std::string base = a.handout_base.empty() ? rt::grader::file_url(source) : a.handout_base;
    const int read = rt::grader::write_dashboard(a.out, base, std::cerr);
    const fs::path page = fs::path(a.out) / "index.html";
    if (read == 0) {
        std::cerr << "rt-grade: error: no readable OUT/NAME/results.json in " << a.out
                  << " (is it a batch's --out folder?)\n";
        return 1;
    }
    std::cout << "dashboard: " << page.string() << " (" << read << " submissions)\n";
    return 0;
}

CLI::App* add_compare_command(CLI::App& app, rt::grader::CompareRequest& compare) {
    CLI::App* compare_cmd = app.add_subcommand(
        "compare",
        "Score images with the grader's comparison (calibration): every graded scene "
        "rendered by --renderer, or one --image as --scene NN-name/scene");
    compare_cmd->add_option("--renderer", compare.renderer, "an rt binary (trusted build)");
    compare_cmd->add_option("--threads", compare.threads, "render threads (default: all cores)");
    compare_cmd->add_option("--image", compare.image, "an image: .exr linear, .png display values");
    compare_cmd->add_option("--scene", compare.scene,
                            "the graded scene the image is, NN-name/scene");
    return compare_cmd;
}

struct SimilarityArgs {
    rt::grader::SimilarityRequest request;
    std::string dir, out = "similarity";
};

CLI::App* add_similarity_command(CLI::App& app, SimilarityArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "similarity",
        "Plagiarism report: every pair of submissions in DIR compared per student file, "
        "starter code excluded (similarity-tester's sim_c++)");
    cmd->add_option("dir", a.dir, "folder of submissions (each a folder or .zip)")->required();
    cmd->add_option("--out", a.out, "where index.html and pairs.csv go")->capture_default_str();
    cmd->add_option("--threshold", a.request.threshold,
                    "percent of a file's own code found in the other's that flags a pair")
        ->check(CLI::Range(0.0, 100.0))
        ->capture_default_str();
    return cmd;
}

int run_similarity_command(SimilarityArgs& a, const rt::grader::GradeOptions& grade) {
    rt::grader::SimilarityRequest& r = a.request;
    r.source = grade.source;
    r.stages = grade.stages;
    r.dir = a.dir;
    r.out = a.out;
    return rt::grader::run_similarity(r, std::cout, std::cerr);
}

// The grading options that need more than CLI11's checks; false (and a one-line error) when
// they do not make sense.
bool finish_grade_args(GradeArgs& args, bool packaging) {
    args.grade.cache = args.cache;
    if (!args.prairielearn_data.empty())
        apply_prairielearn_data(args.prairielearn_data, args.stages);
    if (!parse_problem_names(args.problem_names, args.grade.problem_names)) {
        std::cerr << "rt-grade: error: --problem-names \"" << args.problem_names
                  << "\": expected STAGE=NAME pairs separated by commas, e.g. "
                     "--problem-names 1=camera,2=shapes (no quotes or backslashes)\n";
        return false;
    }
    if (args.limit.max_graded > 0 && args.metadata.empty() && !packaging) {
        std::cerr << "rt-grade: error: --max-per-day needs --metadata FILE (Gradescope's "
                     "/autograder/submission_metadata.json)\n";
        return false;
    }
    if (!parse_stages(args.stages, args.grade.stages)) {
        std::cerr << "rt-grade: error: --stages \"" << args.stages
                  << "\": expected stage numbers separated by commas, e.g. --stages 1,2,10\n";
        return false;
    }
    return true;
}

// True when the rate limit refuses this submission: its results.json (the latest graded
// submission's score, and when the next is possible) is written instead of a grading. Metadata
// that cannot be read grades the submission (a warning for the instructor's log): a student is
// never refused by the grader's own mistake.
bool refused_by_rate_limit(const GradeArgs& a) {
    if (a.limit.max_graded <= 0) return false;
    std::optional<std::string> results;
    try {
        results = rt::grader::rate_limited_results(a.metadata, a.limit);
    } catch (const std::exception& e) {
        std::cerr << "rt-grade: warning: rate limit not applied: " << e.what() << "\n";
        return false;
    }
    if (!results) return false;
    if (!a.grade.results.empty()) rt::write_text_atomically(a.grade.results, *results);
    if (!a.grade.quiet) std::cout << "rt-grade: not graded (rate limit)\n";
    return true;
}

// `rt-grade SUBMISSION`: the workspace, then the grading; self-grading (the tree rt-grade grades
// from) takes the started stages and writes a report.
int grade_one(rt::grader::GradeOptions& grade, const std::string& submission) {
    grade.submission = submission;
    std::error_code ec;
    const bool self = fs::weakly_canonical(fs::absolute(submission), ec) ==
                      fs::weakly_canonical(fs::absolute(grade.source), ec);
    if (self) {
        grade.started_only = grade.stages.empty();
        if (grade.html.empty()) grade.html = "report.html";
    }
    if (!rt::grader::prepare_workspace(grade, std::cerr)) return 1;
    rt::grader::grade_submission(grade, std::cout);
    if (!grade.html.empty() && !grade.quiet)
        std::cout << "Report: " << fs::absolute(grade.html).lexically_normal().string()
                  << " (failures first; open it in a browser)\n";
    return 0;
}

// `rt-grade package`: each option only where it means something (docs/grading.md).
int run_package_command(const GradeArgs& args, const std::string& platform,
                        const std::string& out) {
    rt::grader::PackageRequest r;
    r.grade = args.grade;
    r.platform = *rt::grader::parse_platform(platform);
    r.out = out;
    r.max_per_day = args.limit.max_graded;
    r.problem_names = args.grade.problem_names;
    if (r.max_per_day > 0 && r.platform != rt::grader::Platform::Gradescope) {
        std::cerr << "rt-grade: error: --max-per-day is Gradescope's (it reads the earlier "
                     "submissions from submission_metadata.json); on "
                  << platform << " limit submissions in the platform's own settings\n";
        return 2;
    }
    if (!r.problem_names.empty() && r.platform != rt::grader::Platform::Autolab) {
        std::cerr << "rt-grade: error: --problem-names names Autolab's problems; " << platform
                  << " takes its names from the tests (leave the option out)\n";
        return 2;
    }
    return rt::grader::run_package(r, std::cout, std::cerr);
}

}  // namespace

int main(int argc, char** argv) {
    // Not dumpable: a child running as the same user (no user namespace, no uid drop) cannot
    // open /proc/<rt-grade>/fd to read another test's nonce pipe or result file.
    prctl(PR_SET_DUMPABLE, 0);
    CLI::App app{"rt-grade: grade submissions and release starter trees"};
    app.footer(
        "Grade one submission: rt-grade SUBMISSION [--stages 1,2] [--results results.json] "
        "[--html report.html]   (SUBMISSION: a folder, a .zip, or . for this tree)");
    GradeArgs args;
    add_grade_options(app, args);
    rt::grader::GradeOptions& grade = args.grade;
    ReleaseArgs release;
    CLI::App* release_cmd = add_release_command(app, release);
    CLI::App* prepare_cmd = app.add_subcommand(
        "prepare", "Build the grading workspace now (otherwise the first grading does it)");
    int slots = 1;  // accepted for old scripts: one workspace now serves every job
    prepare_cmd->add_option("--slots", slots, "ignored (one workspace serves every batch job)");
    BatchArgs batch;
    CLI::App* batch_cmd = add_batch_command(app, batch);
    std::string package_out, platform = "gradescope";
    CLI::App* package_cmd = app.add_subcommand(
        "package",
        "Build the grader for a course platform (--stages: the stages it grades; "
        "--max-per-day: Gradescope's rate limit; --problem-names: Autolab's problems)");
    package_cmd->add_option("--out", package_out,
                            "the zip (gradescope, default autograder.zip) or folder "
                            "(prairielearn, autolab; default the platform's name) to write");
    package_cmd->add_option("--platform", platform, "gradescope, prairielearn or autolab")
        ->check(CLI::IsMember({"gradescope", "prairielearn", "autolab"}))
        ->capture_default_str();
    rt::grader::CompareRequest compare;
    CLI::App* compare_cmd = add_compare_command(app, compare);
    SimilarityArgs similarity;
    CLI::App* similarity_cmd = add_similarity_command(app, similarity);
    DashboardArgs dashboard;
    CLI::App* dashboard_cmd = add_dashboard_command(app, dashboard);
    SlurmArgs slurm;
    CLI::App* slurm_collect_cmd = nullptr;
    CLI::App* slurm_task_cmd = add_slurm_commands(app, slurm, slurm_collect_cmd);
    // Grading options (--stages, --source, ...) also work after a subcommand's name.
    for (CLI::App* sub :
         {prepare_cmd, batch_cmd, package_cmd, compare_cmd, similarity_cmd, dashboard_cmd})
        sub->fallthrough();
    CLI11_PARSE(app, argc, argv);
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    if (!finish_grade_args(args, package_cmd->parsed())) return 2;

    try {
        if (*release_cmd) {
            release.release.out = release.out;
            release.release.source = release.source;
            return rt::grader::run_release(release.release, std::cout, std::cerr);
        }
        if (*prepare_cmd) return rt::grader::prepare_workspace(grade, std::cerr) ? 0 : 1;
        if (*batch_cmd) return run_batch_command(batch, grade);
        if (*slurm_task_cmd) return rt::grader::run_slurm_task(slurm.out, slurm.index, std::cout);
        if (*slurm_collect_cmd) return rt::grader::run_slurm_collect(slurm.out, std::cout);
        if (*dashboard_cmd) return run_dashboard(dashboard, grade.source);
        if (*compare_cmd) {
            compare.source = grade.source;
            compare.stages = grade.stages;
            return rt::grader::run_compare(compare, std::cout);
        }
        if (*similarity_cmd) return run_similarity_command(similarity, grade);
        if (*package_cmd) return run_package_command(args, platform, package_out);
        if (args.submission.empty()) {
            std::cerr << app.help();
            return 2;
        }
        if (refused_by_rate_limit(args)) return 0;
        return grade_one(grade, args.submission);
    } catch (const std::exception& e) {
        std::cerr << "rt-grade: error: " << e.what() << "\n";
        return 1;
    }
}
