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

// One column per stage (stageNN), ready for a gradebook import: a row the grader could not
// grade keeps its stage cells empty, so its status never shifts into a stage's column.
// An export's rows also name the students (after the submission) and compare with
// Gradescope's score (at the end). No timings (they are in each results.json and on the
// dashboard): the same submissions give the same file, whether graded here or on a cluster.
std::string scores_csv(const std::vector<BatchRow>& rows, const std::vector<int>& stages,
                       bool is_export) {
    std::string csv =
        std::string("submission") + (is_export ? export_header() : "") + ",score,max_score";
    char cell[64];
    for (const int n : stages) csv += ",stage" + two_digits(n);
    csv += std::string(",status") + (is_export ? ",old_score,change" : "") + "\n";
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
        const std::string status = r.refused        ? "refused: " + r.error
                                   : !r.graded      ? "grader error: " + r.error
                                   : s.build_failed ? "build failed"
                                                    : "ok";
        csv += "," + csv_cell(status);
        csv += (is_export && r.graded ? export_change(*r.entry, s.score) : "") + "\n";
    }
    return csv;
}

// changes.csv: what a regrade changed against the scores Gradescope had.
void write_export_changes(const std::vector<BatchRow>& rows, const fs::path& file,
                          std::ostream& log) {
    std::string text = changes_header();
    int changed = 0;
    for (const BatchRow& r : rows) {
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

BatchRow grade_batch_entry(const GradeOptions& base, const BatchEntry& entry, const fs::path& out,
                           int jobs, std::ostream& log) {
    GradeOptions o = base;
    o.submission = entry.path;
    o.results = out / entry.name / "results.json";
    o.html = out / entry.name / "report.html";
    o.renders = out / entry.name / "renders";  // the dashboard's thumbnails of failing scenes
    o.quiet = true;
    o.jobs = jobs;
    BatchRow row{entry.name, &entry, false, {}, {}, false};
    if (entry.exported) {  // the dashboard's names (cmd/dashboard.h)
        fs::create_directories(out / entry.name);
        write_text_atomically(out / entry.name / kStudentsFile,
                              entry.exported->names + " (" + entry.exported->sids + ")\n");
    }
    // A submission its export could not unpack is graded as unreadable (its results.json
    // and report say why) and its row says "refused: <why>".
    o.refused = entry.refused;
    row.refused = !entry.refused.empty();
    row.error = entry.refused;
    try {
        // One broken submission never stops the batch: anything thrown is its row's error.
        row.summary = grade_submission(o, log);
        row.graded = true;
    } catch (const std::exception& e) {
        row.refused = false;
        row.error = clean_output(e.what());
    }
    return row;
}

std::string batch_row_line(const BatchRow& row) {
    if (!row.graded) return row.name + ": grader error: " + row.error + "\n";
    char score[64];
    std::snprintf(score, sizeof score, "%g / %g", row.summary.score, row.summary.max_score);
    return row.name + ": " + score + "\n";
}

void write_batch_outputs(const GradeOptions& base, const BatchInput& in,
                         const std::vector<BatchRow>& rows, const fs::path& out,
                         std::ostream& log) {
    std::vector<int> stage_numbers;
    for (const BatchRow& row : rows)
        if (row.graded && stage_numbers.empty()) stage_numbers = row.summary.stage_numbers;
    write_text_atomically(out / "scores.csv", scores_csv(rows, stage_numbers, in.is_export));
    log << "scores: " << (out / "scores.csv").string() << "\n";
    if (in.is_export) write_export_changes(rows, out / "changes.csv", log);
    write_batch_dashboard(out, file_url(base.source), log);
}

int run_batch(const GradeOptions& base, const fs::path& dir, const fs::path& out, int jobs,
              bool latest_only, std::ostream& log) {
    const BatchInput in = batch_input(dir, latest_only);
    jobs = std::max(1, std::min<int>(jobs, int(in.entries.size())));
    // One workspace serves every job: gradings only read it (each links in a scratch folder).
    if (!prepare_workspace(base, log)) return 1;
    fs::create_directories(out);
    std::vector<BatchRow> rows(in.entries.size());
    std::mutex mutex;
    const int per_job_tests = std::max(1, default_thread_count() / jobs);
    // Each submission's row goes to its own index, so the CSV keeps the sorted order.
    parallel_for(in.entries.size(), jobs, [&](std::size_t i) {
        if (g_interrupted) return;  // once interrupted, the rest are skipped
        BatchRow row = grade_batch_entry(base, in.entries[i], out, per_job_tests, log);
        std::lock_guard lock(mutex);
        log << batch_row_line(row);
        rows[i] = std::move(row);
    });
    write_batch_outputs(base, in, rows, out, log);
    std::error_code ec;
    if (!in.unpacked.empty()) fs::remove_all(in.unpacked, ec);
    return 0;
}

}  // namespace rt::grader
