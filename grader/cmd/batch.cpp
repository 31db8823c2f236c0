// `rt-grade batch` (many submissions, one CSV) and `rt-grade package` (the Gradescope zip).
#include "cmd/batch.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <mutex>

#include "cmd/batch_input.h"
#include "cmd/dashboard.h"
#include "core/parallel_for.h"
#include "util.h"
#include "workspace/workspace_prepare.h"

namespace fs = std::filesystem;

namespace rt::grader {

namespace {

// One submission's line of scores.csv.
struct Row {
    std::string name;
    const BatchEntry* entry = nullptr;
    bool graded = false;
    GradeSummary summary;
    std::string error;  // what the grader threw
};

// One column per stage (stageNN), ready for a gradebook import: a row the grader could not
// grade keeps its stage cells empty, so its status never shifts into a stage's column.
// An export's rows also name the students (after the submission) and compare with
// Gradescope's score (at the end).
std::string scores_csv(const std::vector<Row>& rows, const std::vector<int>& stages,
                       bool is_export) {
    std::string csv =
        std::string("submission") + (is_export ? export_header() : "") + ",score,max_score";
    char cell[64];
    for (const int n : stages) csv += ",stage" + two_digits(n);
    csv += std::string(",status,seconds") + (is_export ? ",old_score,change" : "") + "\n";
    for (const auto& r : rows) {
        if (r.name.empty()) continue;  // skipped after an interruption
        const GradeSummary& s = r.summary;
        std::snprintf(cell, sizeof cell, ",%g,%g", s.score, s.max_score);
        csv += csv_cell(r.name) + export_identity(*r.entry) + cell;
        for (const int n : stages) {
            const auto at = std::find(s.stage_numbers.begin(), s.stage_numbers.end(), n);
            cell[0] = '\0';
            if (at != s.stage_numbers.end() &&
                std::size_t(at - s.stage_numbers.begin()) < s.stage_scores.size())
                std::snprintf(cell, sizeof cell, "%g",
                              s.stage_scores[at - s.stage_numbers.begin()]);
            csv += "," + std::string(cell);
        }
        const std::string status = !r.graded        ? "grader error: " + r.error
                                   : s.build_failed ? "build failed"
                                                    : "ok";
        std::snprintf(cell, sizeof cell, ",%.1f", s.seconds);
        csv += "," + csv_cell(status) + cell;
        csv += (is_export && r.graded ? export_change(*r.entry, s.score) : "") + "\n";
    }
    return csv;
}

// changes.csv: what a regrade changed against the scores Gradescope had.
void write_export_changes(const std::vector<Row>& rows, const fs::path& file, std::ostream& log) {
    std::string text = changes_header();
    int changed = 0;
    for (const Row& r : rows) {
        if (!r.graded || !r.entry || !r.entry->exported) continue;  // no new score
        bool moved = false;
        text += changes_line(*r.entry, r.summary.score, moved);
        changed += moved;
    }
    write_text_atomically(file, text);
    log << "changes: " << file.string() << " (" << changed
        << " submissions whose score changed or that Gradescope had not scored)\n";
}

}  // namespace

int run_batch(const GradeOptions& base, const fs::path& dir, const fs::path& out, int jobs,
              bool latest_only, std::ostream& log) {
    const BatchInput in = batch_input(dir, latest_only);
    jobs = std::max(1, std::min<int>(jobs, int(in.entries.size())));
    // One workspace serves every job: gradings only read it (each links in a scratch folder).
    if (!prepare_workspace(base, log)) return 1;
    fs::create_directories(out);
    std::vector<Row> rows(in.entries.size());
    std::vector<int> stage_numbers;
    std::mutex mutex;
    const int per_job_tests = std::max(1, default_thread_count() / jobs);
    // Each submission's row goes to its own index, so the CSV keeps the sorted order.
    parallel_for(in.entries.size(), jobs, [&](std::size_t i) {
        if (g_interrupted) return;  // once interrupted, the rest are skipped
        const BatchEntry& entry = in.entries[i];
        GradeOptions o = base;
        o.submission = entry.path;
        o.results = out / entry.name / "results.json";
        o.html = out / entry.name / "report.html";
        o.renders = out / entry.name / "renders";  // the dashboard's thumbnails of failing scenes
        o.quiet = true;
        o.jobs = per_job_tests;
        Row row{entry.name, &entry, false, {}, {}};
        if (entry.exported) {  // the dashboard's names (cmd/dashboard.h)
            fs::create_directories(out / entry.name);
            write_text_atomically(out / entry.name / kStudentsFile,
                                  entry.exported->names + " (" + entry.exported->sids + ")\n");
        }
        try {
            // One broken submission never stops the batch: anything thrown is its row's error.
            row.summary = grade_submission(o, log);
            row.graded = true;
            std::lock_guard lock(mutex);
            if (stage_numbers.empty()) stage_numbers = row.summary.stage_numbers;
            log << entry.name << ": " << row.summary.score << " / " << row.summary.max_score
                << "\n";
        } catch (const std::exception& e) {
            row.error = clean_output(e.what());
            std::lock_guard lock(mutex);
            log << entry.name << ": grader error: " << e.what() << "\n";
        }
        std::lock_guard lock(mutex);
        rows[i] = std::move(row);
    });
    write_text_atomically(out / "scores.csv", scores_csv(rows, stage_numbers, in.is_export));
    log << "scores: " << (out / "scores.csv").string() << "\n";
    if (in.is_export) write_export_changes(rows, out / "changes.csv", log);
    write_batch_dashboard(out, file_url(base.source), log);
    std::error_code ec;
    if (!in.unpacked.empty()) fs::remove_all(in.unpacked, ec);
    return 0;
}

namespace {

// RT_AUTOGRADER_ROOT (default /autograder) lets the tests run both scripts in a folder that
// stands in for Gradescope's layout (grader/tests/adversarial.sh, case package_run).
const char* const kSetupScript = R"SH(#!/usr/bin/env bash
# Gradescope setup (Ubuntu base image, run once as root when the autograder is built).
set -euo pipefail
root=${RT_AUTOGRADER_ROOT:-/autograder}
cd "$root/source"
bash scripts/install-deps.sh
# Ubuntu 22.04 ships CMake 3.22; the project needs 3.25.
version=$(cmake --version 2>/dev/null | head -n1 | awk '{print $3}')
if [ -z "$version" ] || [ "$(printf '%s\n' 3.25 "$version" | sort -V | head -n1)" != 3.25 ]; then
  apt-get install -y -qq python3-pip >/dev/null
  pip3 install -q 'cmake>=3.25,<4'
  hash -r
fi
# 768 MB of memory: one compiler at a time.
export CMAKE_BUILD_PARALLEL_LEVEL=1 RT_GRADE_BUILD_JOBS=1
cmake --preset release -DRT_WERROR=OFF
cmake --build build --target rt-grade
build/bin/rt-grade prepare --source "$root/source" --cache "$root/rt-grade-cache"
# Student code runs as nobody: the instructor tree (solutions, hidden tests, references) and
# the private part of the cache stay unreadable to it even without namespaces.
chmod 700 "$root/source"
)SH";

// run_autograder: grades `stages` ("" every stage), at most `max_per_day` submissions per
// student in any 24 hours (0: no limit).
std::string run_autograder_script(const std::vector<int>& stages, int max_per_day) {
    // The graded stages, as rt-grade's --stages reads them ("" grades every stage).
    std::string stage_list;
    for (const int n : stages) stage_list += (stage_list.empty() ? "" : ",") + std::to_string(n);
    return R"(#!/usr/bin/env bash
# Gradescope entry point: grades /autograder/submission; results.json is always written.
root=${RT_AUTOGRADER_ROOT:-/autograder}
cd "$root/source" || exit 1
mkdir -p "$root/results"
export RT_GRADE_BUILD_JOBS=1
stages=")" +
           stage_list + R"("  # rt-grade package --stages; empty: every stage
max_per_day=)" +
           std::to_string(max_per_day) +
           R"(  # rt-grade package --max-per-day; 0: no limit
exec build/bin/rt-grade "$root/submission" --source "$root/source" --jobs 1 --quiet \
  ${stages:+--stages "$stages"} --cache "${RT_GRADE_CACHE:-$root/rt-grade-cache}" \
  --max-per-day "$max_per_day" --metadata "$root/submission_metadata.json" \
  --results "$root/results/results.json" --html "$root/results/report.html"
)";
}

}  // namespace

int run_package(const fs::path& source, const fs::path& out, const std::vector<int>& stages,
                int max_per_day, std::ostream& log) {
    char tmpl[] = "/tmp/rt-grade-package-XXXXXX";
    if (!mkdtemp(tmpl)) return 1;
    const fs::path stage = tmpl;
    // The whole instructor tree (hidden tests and references included: the zip stays with the
    // course staff), without build trees.
    const fs::path src = stage / "source";
    fs::create_directories(src);  // a top-level file may come before any folder
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(source, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (it.depth() == 0 &&
            (name == ".git" || name.starts_with("build") || name == "gallery" || name == "out")) {
            it.disable_recursion_pending();
            continue;
        }
        const fs::path rel = it->path().lexically_relative(source);
        if (it->is_directory())
            fs::create_directories(src / rel);
        else if (it->is_regular_file())
            fs::copy_file(it->path(), src / rel);
    }
    write_text(stage / "setup.sh", kSetupScript);
    write_text(stage / "run_autograder", run_autograder_script(stages, max_per_day));
    fs::permissions(stage / "setup.sh", fs::perms::owner_all | fs::perms::group_read |
                                            fs::perms::group_exec | fs::perms::others_read |
                                            fs::perms::others_exec);
    fs::permissions(stage / "run_autograder", fs::status(stage / "setup.sh").permissions());
    const fs::path zip = fs::absolute(out);
    fs::remove(zip, ec);
    std::string output;
    const int code = run_trusted("cd " + shell_quote(stage.string()) + " && zip -q -r -X " +
                                     shell_quote(zip.string()) + " setup.sh run_autograder source",
                                 &output);
    fs::remove_all(stage, ec);
    if (code != 0) {
        log << "rt-grade: error: zip failed (is the zip package installed?)\n" << output;
        return 1;
    }
    log << "autograder: " << zip.string() << " (upload it as is; setup.sh builds on Gradescope)\n"
        << "Gradescope settings: grading fits the defaults (768 MB, half a CPU, 10 minutes); "
           "setup.sh's build peaked at 1.1 GB, so if the image build fails or stalls, ask for "
           "1.5 GB of memory (docs/grading.md#gradescopes-limits-rehearsed)\n";
    return 0;
}

}  // namespace rt::grader
