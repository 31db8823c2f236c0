// `rt-grade batch` (many submissions, one CSV) and `rt-grade package` (the Gradescope zip).
#include "cmd/batch.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <mutex>

#include "cmd/batch_input.h"
#include "core/parallel_for.h"
#include "util.h"
#include "workspace/workspace_prepare.h"

namespace fs = std::filesystem;

namespace rt::grader {

namespace {

// One submission's CSV row (its scores, or why it has none); `score` receives its total.
std::string grade_row(const GradeOptions& base, const BatchEntry& entry, const fs::path& out,
                      int tests_per_job, double& score, bool& graded,
                      std::vector<int>& stage_numbers, std::mutex& mutex, std::ostream& log) {
    GradeOptions o = base;
    o.submission = entry.path;
    o.results = out / entry.name / "results.json";
    o.html = out / entry.name / "report.html";
    o.quiet = true;
    o.jobs = tests_per_job;
    std::string row = "\"" + entry.name + "\"" + export_identity(entry) + ",";
    try {
        // One broken submission never stops the batch: anything thrown is its row's error.
        const GradeSummary s = grade_submission(o, log);
        char cell[64];
        std::snprintf(cell, sizeof cell, "%g,%g", s.score, s.max_score);
        row += cell;
        for (double v : s.stage_scores) {
            std::snprintf(cell, sizeof cell, ",%g", v);
            row += cell;
        }
        row += s.build_failed ? ",build failed" : ",ok";
        std::snprintf(cell, sizeof cell, ",%.1f", s.seconds);
        row += cell;
        score = s.score, graded = true;
        std::lock_guard lock(mutex);
        if (stage_numbers.empty()) stage_numbers = s.stage_numbers;
        log << entry.name << ": " << s.score << " / " << s.max_score << "\n";
    } catch (const std::exception& e) {
        row += "0,0,grader error: " + clean_output(e.what());
        std::lock_guard lock(mutex);
        log << entry.name << ": grader error: " << e.what() << "\n";
    }
    return row;
}

}  // namespace

int run_batch(const GradeOptions& base, const fs::path& dir, const fs::path& out, int jobs,
              bool latest_only, std::ostream& log) {
    const BatchInput in = batch_input(dir, latest_only);
    const std::vector<BatchEntry>& entries = in.entries;
    jobs = std::max(1, std::min<int>(jobs, int(entries.size())));
    // One workspace serves every job: gradings only read it (each links in a scratch folder).
    if (!prepare_workspace(base, log)) return 1;
    fs::create_directories(out);
    std::vector<std::string> rows(entries.size());
    std::vector<double> scores(entries.size(), 0);
    std::vector<bool> graded(entries.size(), false);
    std::vector<int> stage_numbers;
    std::mutex mutex;
    const int per_job_tests = std::max(1, default_thread_count() / jobs);
    // Each submission's row goes to its own index, so the CSV keeps the sorted order.
    parallel_for(entries.size(), jobs, [&](std::size_t i) {
        if (g_interrupted) return;  // once interrupted, the rest are skipped
        double score = 0;
        bool done = false;
        std::string row =
            grade_row(base, entries[i], out, per_job_tests, score, done, stage_numbers, mutex, log);
        row += in.is_export ? export_change(entries[i], score) : "";
        std::lock_guard lock(mutex);
        rows[i] = row, scores[i] = score, graded[i] = done;
    });
    std::string csv =
        std::string("submission") + (in.is_export ? export_header() : "") + ",score,max_score";
    char cell[32];
    for (int n : stage_numbers) {
        std::snprintf(cell, sizeof cell, ",stage%02d", n);
        csv += cell;
    }
    csv += std::string(",status,seconds") + (in.is_export ? ",old_score,change" : "") + "\n";
    for (const auto& r : rows)
        if (!r.empty()) csv += r + "\n";
    write_text_atomically(out / "scores.csv", csv);
    log << "scores: " << (out / "scores.csv").string() << "\n";
    if (in.is_export) {
        const int changed = write_changes(entries, scores, graded, out / "changes.csv");
        log << "changes: " << (out / "changes.csv").string() << " (" << changed
            << " submissions whose score changed or that Gradescope had not scored)\n";
    }
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
    log << "autograder: " << zip.string() << " (upload it as is; setup.sh builds on Gradescope)\n";
    return 0;
}

}  // namespace rt::grader
