// A batch on a Slurm cluster (slurm.h): the manifest, the two scripts, one task, the collector.
#include "cmd/slurm.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cmd/batch.h"
#include "cmd/batch_input.h"
#include "course/manifest.h"
#include "util.h"
#include "workspace/workspace_prepare.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt::grader {
namespace {

// Slurm's default MaxArraySize: array indices 0 to 1000. A larger class is submitted as several
// arrays, each task adding its array's offset (RT_GRADE_OFFSET) to its index.
constexpr long kDefaultMaxArraySize = 1001;
// A task's memory: rt-grade, and a test's judge and worker at 512 MB each at most
// (grading/grade_run.cpp). Always set: a job without --mem may take the whole node.
constexpr const char* kTaskMemory = "2G";
// A task's time: this much, plus kMinutesPerStage for each graded stage.
constexpr int kBaseMinutes = 5;
constexpr int kMinutesPerStage = 3;

fs::path slurm_dir(const fs::path& out) {
    return out / ".slurm";
}
fs::path row_file(const fs::path& out, long index) {
    return slurm_dir(out) / "rows" / (std::to_string(index) + ".json");
}

// --- The manifest: the options every task grades with, and the submissions in batch order. ---

json exported_json(const ExportedSubmission& x) {
    json j = {{"path", x.path.string()}, {"folder", x.folder},  {"names", x.names},
              {"sids", x.sids},          {"emails", x.emails},  {"student", x.student},
              {"time", x.time},          {"old_score", nullptr}};
    if (x.old_score) j["old_score"] = *x.old_score;
    return j;
}

ExportedSubmission exported_from(const json& j) {
    ExportedSubmission x;
    x.path = j.at("path").get<std::string>();
    x.folder = j.at("folder").get<std::string>();
    x.names = j.at("names").get<std::string>();
    x.sids = j.at("sids").get<std::string>();
    x.emails = j.at("emails").get<std::string>();
    x.student = j.at("student").get<std::string>();
    x.time = j.at("time").get<std::int64_t>();
    if (!j.at("old_score").is_null()) x.old_score = j.at("old_score").get<double>();
    return x;
}

json entry_json(const BatchEntry& e) {
    return {{"name", e.name},
            {"path", e.path.string()},
            {"refused", e.refused},
            {"exported", e.exported ? exported_json(*e.exported) : json(nullptr)}};
}

BatchEntry entry_from(const json& j) {
    BatchEntry e;
    e.name = j.at("name").get<std::string>();
    e.path = j.at("path").get<std::string>();
    e.refused = j.at("refused").get<std::string>();
    if (!j.at("exported").is_null()) e.exported = exported_from(j.at("exported"));
    return e;
}

// What a task or the collector reads back from the manifest.
struct Manifest {
    GradeOptions base;
    BatchInput input;
};

json manifest_json(const GradeOptions& base, const BatchInput& in) {
    json entries = json::array();
    for (const BatchEntry& e : in.entries) entries.push_back(entry_json(e));
    return {{"made_by", "rt-grade batch --slurm"},
            {"rt_grade", fs::read_symlink("/proc/self/exe").string()},
            {"source", fs::absolute(base.source).string()},
            {"cache", base.cache.empty() ? "" : fs::absolute(base.cache).string()},
            {"stages", base.stages},
            {"time_limit", base.time_limit},
            {"is_export", in.is_export},
            {"submissions", entries}};
}

Manifest read_manifest(const fs::path& out) {
    const fs::path file = slurm_dir(out) / "manifest.json";
    try {
        const json j = json::parse(read_text(file));
        Manifest m;
        m.base.source = j.at("source").get<std::string>();
        m.base.cache = j.at("cache").get<std::string>();
        m.base.stages = j.at("stages").get<std::vector<int>>();
        m.base.time_limit = j.at("time_limit").get<double>();
        m.input.is_export = j.at("is_export").get<bool>();
        for (const json& e : j.at("submissions")) m.input.entries.push_back(entry_from(e));
        return m;
    } catch (const std::exception& e) {
        throw std::runtime_error(file.string() + ": not a manifest of `rt-grade batch --slurm` (" +
                                 e.what() + "); run the batch with --slurm again");
    }
}

// --- A task's row: what scores.csv needs of one submission. ---

json row_json(const BatchRow& r) {
    const GradeSummary& s = r.summary;
    return {{"name", r.name},
            {"graded", r.graded},
            {"refused", r.refused},
            {"error", r.error},
            {"score", s.score},
            {"max_score", s.max_score},
            {"stage_scores", s.stage_scores},
            {"stage_numbers", s.stage_numbers},
            {"build_failed", s.build_failed},
            {"seconds", s.seconds}};
}

// The row task `index` left, or nothing when it left none (it did not finish).
std::optional<BatchRow> read_row(const fs::path& out, long index, const BatchEntry& entry) {
    std::error_code ec;
    if (!fs::exists(row_file(out, index), ec)) return std::nullopt;
    try {
        const json j = json::parse(read_text(row_file(out, index)));
        if (j.at("name").get<std::string>() != entry.name) return std::nullopt;
        BatchRow r{entry.name, &entry, j.at("graded").get<bool>(), {}, {}, false};
        r.refused = j.at("refused").get<bool>();
        r.error = j.at("error").get<std::string>();
        r.summary.score = j.at("score").get<double>();
        r.summary.max_score = j.at("max_score").get<double>();
        r.summary.stage_scores = j.at("stage_scores").get<std::vector<double>>();
        r.summary.stage_numbers = j.at("stage_numbers").get<std::vector<int>>();
        r.summary.build_failed = j.at("build_failed").get<bool>();
        r.summary.seconds = j.at("seconds").get<double>();
        return r;
    } catch (const std::exception&) {
        return std::nullopt;  // a task killed while writing: as if it left nothing
    }
}

// --- The scripts. ---

// The cluster's MaxArraySize (scontrol), or Slurm's default when it cannot be asked.
long max_array_size() {
    const auto config = command_output("scontrol show config 2>/dev/null");
    if (!config) return kDefaultMaxArraySize;
    const auto at = config->find("MaxArraySize");
    if (at == std::string::npos) return kDefaultMaxArraySize;
    const auto eq = config->find('=', at);
    const long value = eq == std::string::npos ? 0 : std::atol(config->c_str() + eq + 1);
    return value > 0 ? value : kDefaultMaxArraySize;
}

int graded_stage_count(const GradeOptions& base) {
    if (!base.stages.empty()) return int(base.stages.size());
    return int(load_stage_specs(base.source).size());
}

std::string grade_script(const GradeOptions& base, const fs::path& out, long tasks,
                         const std::string& rt_grade) {
    const int minutes = kBaseMinutes + kMinutesPerStage * graded_stage_count(base);
    const std::string logs = (slurm_dir(out) / "logs").string();
    return "#!/bin/bash\n"
           "# rt-grade batch --slurm: task N grades line N of manifest.json (rt-grade "
           "slurm-task).\n"
           "# Rerun task N alone: sbatch --array=N " +
           (slurm_dir(out) / "grade.sbatch").string() +
           "\n#SBATCH --job-name=rt-grade\n"
           "#SBATCH --array=0-" +
           std::to_string(tasks - 1) +
           "\n#SBATCH --ntasks=1\n"
           "#SBATCH --cpus-per-task=1\n"
           "#SBATCH --mem=" +
           kTaskMemory + "\n#SBATCH --time=" + std::to_string(minutes) +
           "\n#SBATCH --output=" + logs + "/job-%A-task-%a.log\n" + "exec " +
           shell_quote(rt_grade) + " slurm-task " + shell_quote(out.string()) +
           " \"$(( ${RT_GRADE_OFFSET:-0} + SLURM_ARRAY_TASK_ID ))\"\n";
}

std::string collect_script(const fs::path& out, const std::string& rt_grade) {
    return "#!/bin/bash\n"
           "# rt-grade batch --slurm: scores.csv, changes.csv and index.html from every task.\n"
           "#SBATCH --job-name=rt-grade-collect\n"
           "#SBATCH --ntasks=1\n"
           "#SBATCH --cpus-per-task=1\n"
           "#SBATCH --mem=" +
           std::string(kTaskMemory) + "\n#SBATCH --time=30\n#SBATCH --output=" +
           (slurm_dir(out) / "logs" / "collect.log").string() + "\nexec " + shell_quote(rt_grade) +
           " slurm-collect " + shell_quote(out.string()) + "\n";
}

// #SBATCH lines end at white space, and the scripts name OUT in them.
void require_plain_path(const fs::path& out) {
    if (out.string().find_first_of(" \t\n'\"\\$`") == std::string::npos) return;
    throw std::runtime_error("--slurm: " + out.string() +
                             " holds a space or quote, which #SBATCH lines cannot hold; choose an "
                             "--out without them");
}

// `sbatch --parsable ARGS`: the job id, or a runtime_error with sbatch's complaint.
std::string sbatch(const std::vector<std::string>& args) {
    std::string command = "sbatch --parsable";
    for (const std::string& a : args) command += " " + shell_quote(a);
    std::string output;
    if (run_trusted(command, &output) != 0)
        throw std::runtime_error("sbatch failed: " + std::string(trim(output)) +
                                 " (is this a Slurm login node? see docs/grading.md)");
    const std::string id(trim(output));
    return id.substr(0, id.find(';'));  // "ID;cluster" on a federation
}

// Submits the arrays (several when the class exceeds MaxArraySize) and the collector after all.
void submit(const fs::path& out, long tasks, long chunk, std::ostream& log) {
    const std::string script = (slurm_dir(out) / "grade.sbatch").string();
    std::string after = "afterany";
    for (long offset = 0; offset < tasks; offset += chunk) {
        const long count = std::min(chunk, tasks - offset);
        const std::string id =
            sbatch({"--array=0-" + std::to_string(count - 1),
                    "--export=ALL,RT_GRADE_OFFSET=" + std::to_string(offset), script});
        log << "slurm: job " << id << " grades submissions " << offset << " to "
            << offset + count - 1 << "\n";
        after += ":" + id;
    }
    const std::string collector =
        sbatch({"--dependency=" + after, (slurm_dir(out) / "collect.sbatch").string()});
    log << "slurm: job " << collector << " writes " << (out / "scores.csv").string()
        << " once every task has ended\n";
}

// The command that reruns the tasks in `missing` and then collects again: one sbatch per array
// they fall in (an index beyond the first MaxArraySize is its array's offset plus a task id).
std::string rerun_command(const fs::path& out, const std::vector<long>& missing) {
    const long chunk = std::max(1L, max_array_size());
    const std::string script = (slurm_dir(out) / "grade.sbatch").string();
    std::string command;
    std::string after = "afterany";
    for (std::size_t i = 0; i < missing.size();) {
        const long offset = missing[i] / chunk * chunk;
        std::string ids;
        for (; i < missing.size() && missing[i] / chunk * chunk == offset; ++i)
            ids += (ids.empty() ? "" : ",") + std::to_string(missing[i] - offset);
        const std::string var = "j" + std::to_string(offset / chunk);
        command += var + "=$(sbatch --parsable --array=" + ids +
                   (offset > 0 ? " --export=ALL,RT_GRADE_OFFSET=" + std::to_string(offset) : "") +
                   " " + script + ") && ";
        after += ":$" + var;
    }
    return command + "sbatch --dependency=" + after + " " +
           (slurm_dir(out) / "collect.sbatch").string();
}

}  // namespace

int run_slurm_batch(const GradeOptions& base, const SlurmRequest& r, std::ostream& log) {
    const fs::path out = fs::absolute(r.out).lexically_normal();
    require_plain_path(out);
    fs::create_directories(slurm_dir(out) / "rows");
    fs::create_directories(slurm_dir(out) / "logs");
    // A zipped export is unpacked once, where every node reads it.
    const fs::path unpacked = slurm_dir(out) / "input";
    std::error_code ec;
    fs::remove_all(unpacked, ec);
    const BatchInput in = batch_input(r.input, r.latest_only, unpacked);
    if (in.entries.empty()) throw std::runtime_error(r.input.string() + ": no submission in it");
    if (!prepare_workspace(base, log)) return 1;
    for (const auto& e : fs::directory_iterator(slurm_dir(out) / "rows")) fs::remove(e.path());
    const std::string rt_grade = fs::read_symlink("/proc/self/exe").string();
    const long tasks = long(in.entries.size());
    const long chunk = std::max(1L, max_array_size());  // scontrol, asked once
    write_text_atomically(slurm_dir(out) / "manifest.json", manifest_json(base, in).dump(1) + "\n");
    write_text_atomically(slurm_dir(out) / "grade.sbatch",
                          grade_script(base, out, std::min(tasks, chunk), rt_grade));
    write_text_atomically(slurm_dir(out) / "collect.sbatch", collect_script(out, rt_grade));
    log << "slurm: " << tasks << " submissions in " << (slurm_dir(out) / "manifest.json").string()
        << "\n";
    if (r.submit) {
        submit(out, tasks, chunk, log);
        return 0;
    }
    log << "slurm: submit with: id=$(sbatch --parsable "
        << (slurm_dir(out) / "grade.sbatch").string() << ") && sbatch --dependency=afterany:$id "
        << (slurm_dir(out) / "collect.sbatch").string() << "\n";
    return 0;
}

int run_slurm_task(const fs::path& out, long index, std::ostream& log) {
    const Manifest m = read_manifest(out);
    if (index < 0 || index >= long(m.input.entries.size()))
        throw std::runtime_error("slurm-task: index " + std::to_string(index) +
                                 " is not a line of the manifest (0 to " +
                                 std::to_string(long(m.input.entries.size()) - 1) + ")");
    const BatchEntry& entry = m.input.entries[std::size_t(index)];
    // The CPUs Slurm gave this task (--cpus-per-task), one when it does not say.
    const char* cpus = std::getenv("SLURM_CPUS_PER_TASK");
    const int jobs = std::max(1, cpus ? std::atoi(cpus) : 1);
    const BatchRow row = grade_batch_entry(m.base, entry, out, jobs, log);
    // Cancelled (scancel, a time or memory limit: Slurm's SIGTERM) is not graded: an interrupted
    // grading scores what ran, and its row would stand for the whole. Without a row, the
    // collector names the task as not finished and prints the command that reruns it.
    if (g_interrupted) {
        log << entry.name << ": interrupted, no row written; the collector will name this task\n";
        return 1;
    }
    write_text_atomically(row_file(out, index), row_json(row).dump() + "\n");
    log << batch_row_line(row);
    return 0;
}

int run_slurm_collect(const fs::path& out, std::ostream& log) {
    const Manifest m = read_manifest(out);
    std::vector<BatchRow> rows;
    std::vector<long> missing;
    for (std::size_t i = 0; i < m.input.entries.size(); ++i) {
        const BatchEntry& entry = m.input.entries[i];
        if (auto row = read_row(out, long(i), entry)) {
            rows.push_back(std::move(*row));
            continue;
        }
        missing.push_back(long(i));
        rows.push_back({entry.name, &entry, false, {}, "its Slurm task did not finish", false});
    }
    write_batch_outputs(m.base, m.input, rows, out, log);
    if (missing.empty()) return 0;
    std::string list;
    for (const long i : missing) list += (list.empty() ? "" : ",") + std::to_string(i);
    log << "slurm: " << missing.size() << " tasks left no row (manifest lines " << list
        << "); rerun them, then collect again:\n  " << rerun_command(out, missing) << "\n";
    return 1;
}

}  // namespace rt::grader
