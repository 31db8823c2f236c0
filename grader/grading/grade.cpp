// `rt-grade SUBMISSION`: the driver. grade_submission runs the phases of a grading in order
// (grading.h); the build and run phases are in grade_build.cpp and grade_run.cpp.
#include "grading/grade.h"

#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>

#include "grading/grading.h"
#include "grading/platform_results.h"
#include "util.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt::grader {

std::atomic<bool> g_interrupted{false};

Report Grading::to_report() const {
    Report r;
    r.isolation = describe(isolation);
    r.general = general;
    r.seconds = seconds_since(start);
    for (const auto& s : graded) r.stages.push_back({s.number, s.title, s.folder});
    for (const auto* list : {&notes, &outcomes})
        for (const auto& t : *list)
            r.tests.push_back({t.stage, t.name, t.number, t.status, t.output, t.visibility, t.tags,
                               t.score, t.max_score, t.is_scene, t.student_png, t.reference_png,
                               t.diff_png, t.metrics});
    r.leaderboard = leaderboard;
    return r;
}

void print_autolab_scores(Grading& g, std::optional<std::size_t> task) {
    std::lock_guard lock(g.progress_mutex);
    if (task && *task < g.finished.size()) g.finished[*task] = true;
    std::map<int, double> scores;
    std::map<int, std::string> names;
    for (const auto& s : g.graded) {
        scores[s.number] = 0;
        const auto named = g.o.problem_names.find(s.number);
        names[s.number] = named != g.o.problem_names.end() ? named->second
                                                           : fs::path(s.folder).filename().string();
    }
    // Only outcomes no task is still writing: those finished, or all once grading is over.
    const bool over = !task && !g.finished.empty();
    for (std::size_t i = 0; i < g.outcomes.size(); ++i)
        if (over || (i < g.finished.size() && g.finished[i]))
            scores[g.outcomes[i].stage] += g.outcomes[i].score;
    // One write(2) a line: a kill between two lines never leaves half a line last.
    const std::string line = autolab_scores_line(scores, names) + "\n";
    [[maybe_unused]] const ssize_t written = write(STDOUT_FILENO, line.data(), line.size());
}

namespace {

// Self-grading (`rt-grade .` without --stages): the stages whose files differ from their
// stubs, at least stage 01. Otherwise the stages asked for, or all.
void choose_stages(Grading& g) {
    const GradeOptions& o = g.o;
    if (!(o.stages.empty() && o.started_only)) {
        for (const auto& s : g.all_specs)
            if (o.stages.empty() || std::count(o.stages.begin(), o.stages.end(), s.number))
                g.graded.push_back(s);
        return;
    }
    for (const auto& s : g.all_specs) {
        bool started = false;
        for (const auto& f : s.student_files) {
            std::error_code ec;
            const fs::path mine = o.source / s.folder / f,
                           stub = g.w.priv / "pristine" / s.folder / (f + ".stub");
            started = started || (fs::is_regular_file(mine, ec) && fs::is_regular_file(stub, ec) &&
                                  read_text(mine) != read_text(stub));
        }
        if (started) g.graded.push_back(s);
    }
    if (g.graded.empty() && !g.all_specs.empty()) {
        g.graded.push_back(g.all_specs.front());
        g.general = "No stage started yet (every student file is still its stub): grading stage " +
                    two_digits(g.all_specs.front().number) + ".\n";
    } else {
        g.general = "Grading the stages you have started:";
        for (const auto& s : g.graded) g.general += " " + two_digits(s.number);
        g.general += " (--stages N,M grades others).\n";
    }
}

std::map<std::string, std::vector<std::string>> list_tests(const Workspace& w,
                                                           const std::vector<StageSpec>& specs) {
    std::map<std::string, std::vector<std::string>> tests;
    for (const auto& s : specs)
        for (const auto& group : s.groups)
            if (!tests.count(group.binary))
                tests[group.binary] =
                    json::parse(read_text(w.priv / "expected" / (group.binary + ".json")))
                        .get<std::vector<std::string>>();
    return tests;
}

// Every test the grade will have, score 0 until run: the placeholder results.json and the list
// a failed build reports.
void plan_outcomes(Grading& g) {
    const auto expected = list_tests(g.w, g.all_specs);
    for (const auto& s : g.graded) {
        int n = 0;
        const auto outcome = [&](std::string name, double points, const std::string& visibility,
                                 std::vector<std::string> tags) {
            TestOutcome out;
            out.stage = s.number;
            out.name = "Stage " + two_digits(s.number) + " " + std::move(name);
            out.number = std::to_string(s.number) + "." + std::to_string(++n);
            out.max_score = points;
            out.visibility = visibility;
            out.tags = std::move(tags);
            out.output = "not run: grading did not finish\n";
            return out;
        };
        for (const auto& group : s.groups) {
            const auto it = expected.find(group.binary);
            if (it == expected.end()) continue;
            for (const auto& t : it->second) {
                bool in = false;
                for (const auto& p : group.include) in = in || glob_match(p, t);
                for (const auto& p : group.exclude) in = in && !glob_match(p, t);
                if (!in) continue;
                g.tasks.push_back({g.outcomes.size(), group.binary, t, nullptr, &s});
                g.outcomes.push_back(outcome(t, group.points, group.visibility,
                                             {"stage" + two_digits(s.number),
                                              group.hidden_sources.empty() ? "unit" : "hidden"}));
            }
        }
        for (const auto& sc : s.scenes) {
            g.tasks.push_back({g.outcomes.size(), "rt", sc.name, &sc, &s});
            g.outcomes.push_back(outcome("image " + sc.name, sc.points, sc.visibility,
                                         {"stage" + two_digits(s.number), "image"}));
            g.outcomes.back().is_scene = true;
        }
    }
}

// This grading's scratch folder, and the reference renderer where a sandbox uid may execute
// but not read it (uid-drop mode has no jail to bind it into).
void prepare_scratch(Grading& g) {
    char scratch_template[] = "/tmp/rt-grade-run-XXXXXX";
    if (!mkdtemp(scratch_template))
        throw std::runtime_error("rt-grade: cannot create a scratch folder in /tmp");
    g.scratch = scratch_template;
    // Only the grader lists it; uid-drop children (no jail) may pass through to their own folder.
    const auto pass_through = fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec;
    fs::permissions(g.scratch, pass_through);
    g.reference_rt = trusted_dir(g.scratch / "reference") / "rt";
    if (g.plan.has_reference) {
        fs::copy_file(g.w.priv / "bin" / "rt", g.reference_rt);
        fs::permissions(g.reference_rt.parent_path(), pass_through);
        fs::permissions(g.reference_rt, pass_through);
    }
}

// The submitted files of the graded stages; a 0-point note for each one missing or refused.
void take_in_submission(Grading& g) {
    g.in = take_in(g.o, g.graded, g.all_specs, g.w.src);
    if (!g.in.error.empty()) g.general += "The submission could not be read: " + g.in.error + "\n";
    for (const auto& [key, text] : g.in.files) g.digest += key + "\n" + hex(fnv1a(text)) + "\n";
    for (const auto& s : g.graded) {
        for (const auto& f : s.student_files) {
            const std::string key = s.folder + "/" + f;
            if (g.in.files.count(key)) continue;
            TestOutcome note;
            note.stage = s.number;
            note.name = "Stage " + two_digits(s.number) + " file " + f;
            note.number = std::to_string(s.number) + ".0";
            note.tags = {"stage" + two_digits(s.number), "submission"};
            note.output = g.in.rejected.count(key)
                              ? key + " was not used: " + g.in.rejected[key] + "\n"
                              : key + " is missing from the submission\n";
            note.output += "The stage is graded with the starter stub in its place.\n";
            g.notes.push_back(note);
        }
    }
    // Without namespaces the hidden tests are kept from the children (compiler included) by
    // permissions only.
    if (g.isolation == Isolation::UidDrop)
        for (const auto& d : hidden_dirs(g.w)) {
            std::error_code ec;
            fs::permissions(d, fs::perms::owner_all, ec);
        }
}

// Notes for the top of the report, the scores per stage, and the reports written.
void summarise(Grading& g, std::ostream& log) {
    if (g_interrupted) g.general += "Grading was interrupted: tests not run score 0.\n";
    if (g.survivors > 0)
        g.general += "Sandbox: " + std::to_string(g.survivors.load()) +
                     " processes outlived their test and could not be killed.\n";
    if (!g.in.ignored.empty() || g.in.ignored_other > 0) {
        g.general += "Ignored files (only the student files of the graded stages are used):\n";
        for (const auto& ig : g.in.ignored) g.general += "  " + ig.path + ": " + ig.reason + "\n";
        if (g.in.ignored_other > 0)
            g.general += "  ... and " + std::to_string(g.in.ignored_other) +
                         " more files outside the whitelist\n";
    }
    if (g.isolation != Isolation::Namespaces)
        g.general += "Sandbox: " + describe(g.isolation) + "\n";

    GradeSummary& summary = g.summary;
    for (const auto& s : g.graded) {
        double got = 0;
        for (const auto& t : g.outcomes)
            if (t.stage == s.number) got += t.score;
        summary.stage_numbers.push_back(s.number);
        summary.stage_scores.push_back(got);
    }
    for (const auto& t : g.outcomes) {
        summary.score += t.score;
        summary.max_score += t.max_score;
    }
    summary.seconds = seconds_since(g.start);
    const Report report = g.to_report();
    if (!g.o.results.empty()) write_results_json(report, g.o.results);
    if (!g.o.prairielearn_results.empty()) {
        const bool gradable = g.in.error.empty() && !g.in.files.empty();
        write_prairielearn_results(report, g.o.prairielearn_results, gradable,
                                   g.in.error.empty()
                                       ? "None of the graded stages' files was in the submission "
                                         "(nothing to grade): check the file names."
                                       : "The submission could not be read: " + g.in.error);
    }
    if (!g.o.html.empty()) write_html_report(report, g.o.html);
    if (!g.o.renders.empty()) {
        std::error_code ec;
        fs::remove_all(g.o.renders, ec);  // a regrade's images only: none left from the last one
        write_failing_renders(report, g.o.renders);
    }
    if (!g.o.quiet) write_terminal_summary(report, log, g.o.reveal_hidden);
}

}  // namespace

GradeSummary grade_submission(const GradeOptions& o, std::ostream& log) {
    Grading g(o);
    g.w = workspace_paths(o);
    g.all_specs = load_stage_specs(o.source);
    choose_stages(g);
    plan_outcomes(g);
    g.isolation = probe_isolation();
    if (!o.results.empty()) write_results_json(g.to_report(), o.results);  // the placeholder
    if (!o.prairielearn_results.empty())  // a grader that dies never scores the student 0
        write_prairielearn_results(g.to_report(), o.prairielearn_results, false,
                                   "Grading did not finish (a problem of the grader, not of "
                                   "your submission); this submission does not count: submit "
                                   "again, or ask the course staff.");
    if (o.autolab_scores) print_autolab_scores(g);  // every stage 0 until its tests finish

    // Gradings share the workspace read-only; `prepare` takes this lock exclusively.
    WorkspaceLock lock(g.w.cache);
    lock.shared();
    g.plan = load_build_plan(g.w);

    prepare_scratch(g);
    take_in_submission(g);
    build_stages(g);
    run_tests_and_scenes(g);
    time_leaderboard(g);
    summarise(g, log);
    if (o.autolab_scores) print_autolab_scores(g);  // the final scores, notes included

    std::error_code ec;
    fs::remove_all(g.scratch, ec);
    if (!g.in.temp.empty()) fs::remove_all(g.in.temp, ec);
    return g.summary;
}

}  // namespace rt::grader
