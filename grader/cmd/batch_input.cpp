#include "cmd/batch_input.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/text_file.h"
#include "grading/intake.h"
#include "util.h"

namespace rt::grader {

namespace fs = std::filesystem;

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// The folder of an export's submission an entry of its zip belongs to ("assignment_61_export/
// submission_3/" of "assignment_61_export/submission_3/a.cpp"), or "" for the export's own files.
std::string submission_prefix(const std::string& entry) {
    static const std::regex prefix("^((?:[A-Za-z0-9_.-]+/)?submission_[0-9]+/)");
    std::smatch m;
    return std::regex_search(entry, m, prefix) ? m[1].str() : "";
}

// unzip's first line of complaint, for a row of scores.csv, with the paths relative to the
// export (`dir`: the temporary folder it is unpacked in).
std::string unzip_complaint(const std::string& output, const fs::path& dir = {}) {
    std::string line = clean_output(output);
    line = line.substr(0, line.find('\n'));
    const std::string prefix = dir.string() + "/";
    for (auto at = line.find(prefix); !dir.empty() && at != std::string::npos;
         at = line.find(prefix))
        line.erase(at, prefix.size());
    return line.empty() ? "unzip could not extract it" : line;
}

fs::path make_temporary_folder() {
    char tmpl[] = "/tmp/rt-grade-export-XXXXXX";
    if (!mkdtemp(tmpl)) throw std::runtime_error("cannot make a temporary folder in /tmp");
    return tmpl;
}

// A zipped export, unpacked one submission at a time: a submission whose entries unzip cannot
// write (a symbolic link followed by a file written through it, a truncated or encrypted entry)
// is refused alone, with unzip's reason in `refused` under its folder's name, and left empty;
// the other submissions are unpacked and graded. A zip that cannot be listed, or whose own
// files (the metadata) cannot be extracted, is refused whole.
fs::path unpack(const fs::path& zip, const fs::path& into,
                std::map<std::string, std::string>& refused) {
    const fs::path dir = into.empty() ? make_temporary_folder() : into;
    fs::create_directories(dir);
    const std::string archive = shell_quote(zip.string());
    std::string listing;
    if (run_trusted("unzip -Z1 " + archive, &listing) != 0)
        throw std::runtime_error(zip.string() + ": not a readable zip (" +
                                 unzip_complaint(listing) + ")");
    std::set<std::string> prefixes;
    std::istringstream lines(listing);
    for (std::string entry; std::getline(lines, entry);)
        if (const std::string prefix = submission_prefix(entry); !prefix.empty())
            prefixes.insert(prefix);
    std::string output;
    const int status = run_trusted(extract_capped(zip, "", dir, "*submission_[0-9]*/*"), &output);
    if (status > 1 && status != 11)  // 1: a warning, nothing lost; 11: no file of its own
        throw std::runtime_error(zip.string() + ": not a readable zip (" + unzip_complaint(output) +
                                 ")");
    for (const std::string& prefix : prefixes) {
        const std::string folder = fs::path(prefix).parent_path().filename().string();
        // A submission that declares more than one uploaded alone may hold is not unpacked.
        std::uintmax_t bytes = 0;
        if (zip_declared_bytes(zip, prefix + "*", bytes) && bytes > kMaxZipBytes) {
            refused[folder] = "its files expand to " + std::to_string(bytes >> 20) +
                              " MB, more than the 64 MB a submission may hold (a zip bomb?)";
            fs::create_directories(dir / prefix);  // listed by the metadata, graded as refused
            continue;
        }
        const int unzipped = run_trusted(extract_capped(zip, prefix + "*", dir), &output);
        if (unzipped == 0) continue;
        refused[folder] = unzipped == 128 + SIGXFSZ
                              ? "a file of it expands beyond the 64 MB a submission may hold, "
                                "more than its zip entry declares (a zip bomb?)"
                              : unzip_complaint(output, dir);
        std::error_code ec;
        fs::remove_all(dir / prefix, ec);
        fs::create_directories(dir / prefix, ec);  // listed by the metadata, graded as refused
    }
    return dir;
}

}  // namespace

BatchInput batch_input(const fs::path& dir, bool latest_only, const fs::path& unpack_into) {
    BatchInput in;
    fs::path folder = dir;
    std::map<std::string, std::string> refused;
    if (fs::is_regular_file(dir) && dir.extension() == ".zip") {
        folder = unpack(dir, unpack_into, refused);
        if (unpack_into.empty()) in.unpacked = folder;
    }
    if (!fs::is_directory(folder))
        throw std::runtime_error(dir.string() +
                                 ": not a folder of submissions nor a Gradescope export's .zip");
    if (const auto root = export_root(folder)) {
        in.is_export = true;
        std::vector<ExportedSubmission> all = read_gradescope_export(*root);
        if (latest_only) all = latest_per_student(all);
        for (auto& s : all) {
            const auto why = refused.find(s.folder);
            in.entries.push_back({s.path, s.folder, s, why == refused.end() ? "" : why->second});
        }
    } else {
        for (const auto& e : fs::directory_iterator(folder)) {
            if (!e.is_directory() && e.path().extension() != ".zip") continue;
            std::string name = e.path().filename().string();
            if (name.starts_with(".")) continue;  // hidden: a tool's folder, not a submission
            if (name.ends_with(".zip")) name.resize(name.size() - 4);
            in.entries.push_back({e.path(), clean_output(name), {}, {}});
        }
    }
    std::sort(in.entries.begin(), in.entries.end(),
              [](const auto& a, const auto& b) { return a.path < b.path; });
    return in;
}

std::string export_header() {
    return ",student,sid,email";
}

std::string export_identity(const BatchEntry& e) {
    if (!e.exported) return "";
    return "," + csv_cell(e.exported->names) + "," + csv_cell(e.exported->sids) + "," +
           csv_cell(e.exported->emails);
}

std::string export_change(const BatchEntry& e, double new_score) {
    if (!e.exported || !e.exported->old_score) return ",,";
    const double old = *e.exported->old_score;
    return "," + number(old) + "," + number(std::round((new_score - old) * 100) / 100);
}

std::string changes_header() {
    return "submission,student,sid,old_score,new_score,change\n";
}

std::string changes_line(const BatchEntry& e, double new_score, bool& changed) {
    const ExportedSubmission& x = *e.exported;
    const double change = x.old_score ? new_score - *x.old_score : 0;
    changed = !x.old_score || std::abs(change) > 0.005;
    return csv_cell(e.name) + "," + csv_cell(x.names) + "," + csv_cell(x.sids) + "," +
           (x.old_score ? number(*x.old_score) : "") + "," + number(new_score) + "," +
           (x.old_score ? number(std::round(change * 100) / 100) : "new") + "\n";
}

}  // namespace rt::grader
