#include "cmd/batch_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "core/text_file.h"
#include "util.h"

namespace rt::grader {

namespace fs = std::filesystem;

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

fs::path unpack(const fs::path& zip) {
    char tmpl[] = "/tmp/rt-grade-export-XXXXXX";
    if (!mkdtemp(tmpl)) throw std::runtime_error("cannot make a temporary folder in /tmp");
    std::string output;
    if (run_trusted("unzip -q " + shell_quote(zip.string()) + " -d " + shell_quote(tmpl),
                    &output) != 0)
        throw std::runtime_error(zip.string() + ": not a readable zip (" + clean_output(output) +
                                 ")");
    return tmpl;
}

}  // namespace

std::string csv_cell(const std::string& text) {
    std::string cell = "\"";
    for (const char c : text) cell += c == '"' ? std::string("\"\"") : std::string(1, c);
    return cell + "\"";
}

BatchInput batch_input(const fs::path& dir, bool latest_only) {
    BatchInput in;
    fs::path folder = dir;
    if (fs::is_regular_file(dir) && dir.extension() == ".zip") folder = in.unpacked = unpack(dir);
    if (!fs::is_directory(folder))
        throw std::runtime_error(dir.string() +
                                 ": not a folder of submissions nor a Gradescope export's .zip");
    if (const auto root = export_root(folder)) {
        in.is_export = true;
        std::vector<ExportedSubmission> all = read_gradescope_export(*root);
        if (latest_only) all = latest_per_student(all);
        for (auto& s : all) in.entries.push_back({s.path, s.folder, s});
    } else {
        for (const auto& e : fs::directory_iterator(folder)) {
            if (!e.is_directory() && e.path().extension() != ".zip") continue;
            std::string name = e.path().filename().string();
            if (name.ends_with(".zip")) name.resize(name.size() - 4);
            in.entries.push_back({e.path(), clean_output(name), {}});
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
