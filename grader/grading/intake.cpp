#include "grading/intake.h"

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>

#include "util.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

constexpr std::uintmax_t kMaxStudentFileBytes = 256 * 1024;

bool odd_name(const std::string& name) {
    if (name.empty() || name[0] == '-' || name.size() > 100) return true;
    for (unsigned char c : name)
        if (c < 0x20 || c >= 0x7f || c == '\\' || c == ':' || c == '*' || c == '?' || c == '"')
            return true;
    return false;
}

// A quoted include must name a framework header or a file of the stage folder (not hidden/);
// absolute paths, "..", macros and .incbin/#embed would let the compiler read files the
// student must not see (hidden tests, references) into error messages or the binary.
std::string check_source(const std::string& text, const fs::path& ws_src,
                         const std::string& folder) {
    if (text.find('\0') != std::string::npos) return "contains NUL bytes (not a source file)";
    std::string joined;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == '\n') {
            ++i;
            continue;
        }
        joined += text[i];
    }
    for (const char* word : {"incbin", "embed", "__has_include"})
        if (std::regex_search(joined, std::regex(std::string("\\b") + word + "\\b")))
            return std::string("uses `") + word + "`, which the grader does not allow";
    const std::regex directive(R"(^\s*#\s*include(.*)$)");
    std::istringstream lines(joined);
    std::string line;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        std::smatch m;
        if (!std::regex_match(line, m, directive)) continue;
        std::string target = m[1].str();
        const auto first = target.find_first_not_of(" \t");
        target = first == std::string::npos ? "" : target.substr(first);
        const std::string where = "line " + std::to_string(number) + ": ";
        std::string name;
        if (target.size() >= 2 && target[0] == '<') {
            name = target.substr(1, target.find('>') - 1);
        } else if (target.size() >= 2 && target[0] == '"') {
            name = target.substr(1, target.find('"', 1) - 1);
            const bool framework = fs::is_regular_file(ws_src / "framework" / name);
            const bool local = fs::is_regular_file(ws_src / folder / name);
            if (!framework && !local)
                return where + "#include \"" + name + "\" is not a framework header";
        } else {
            return where + "#include must name a file in quotes or angle brackets";
        }
        if (name.empty() || name[0] == '/' || name.find("..") != std::string::npos ||
            name.find("hidden") != std::string::npos)
            return where + "#include <" + name + "> is not allowed (absolute or .. path)";
    }
    return "";
}

// A zip is listed before it is extracted: its total size is capped (zip bombs).
bool extract_zip(const fs::path& zip, const fs::path& dir, std::string& error) {
    std::uintmax_t bytes = 0;
    if (!zip_declared_bytes(zip, "", bytes)) {
        error = "not a readable zip file";
        return false;
    }
    if (bytes > kMaxZipBytes) {
        error = "the zip expands to more than 64 MB";
        return false;
    }
    std::string out;
    fs::create_directories(dir);
    run_trusted(extract_capped(zip, "", dir), &out);
    return true;
}

}  // namespace

namespace {

// The submission's folder: a .zip extracted into a temporary folder (in.temp), and a zip or
// folder of one folder looked inside. Empty with in.error set when there is none.
fs::path open_submission(const GradeOptions& o, Intake& in) {
    fs::path sub = o.submission;
    std::error_code ec;
    if (!o.refused.empty()) {
        in.error = o.refused;
        return {};
    }
    if (fs::is_regular_file(sub) && sub.extension() == ".zip") {
        char tmpl[] = "/tmp/rt-grade-zip-XXXXXX";
        if (!mkdtemp(tmpl)) {
            in.error = "cannot create a temporary folder";
            return {};
        }
        in.temp = tmpl;
        if (!extract_zip(sub, in.temp, in.error)) return {};
        sub = in.temp;
    } else if (!fs::is_directory(sub)) {
        in.error = "the submission is neither a folder nor a .zip";
        return {};
    }
    for (int depth = 0; depth < 3; ++depth) {
        std::vector<fs::path> entries;
        for (const auto& e : fs::directory_iterator(sub, ec))
            if (e.path().filename() != "__MACOSX") entries.push_back(e.path());
        if (entries.size() == 1 && fs::is_directory(fs::symlink_status(entries[0])))
            sub = entries[0];
        else
            break;
    }
    return sub;
}

// Each graded student file where it may be: a whole tree, a stage folder, or loose files. Taken
// into in.files (or in.rejected with the reason); returns the paths it claimed.
std::set<std::string> claim_student_files(Intake& in, const fs::path& sub,
                                          const std::vector<StageSpec>& graded,
                                          const fs::path& ws_src) {
    std::set<std::string> claimed;
    std::error_code ec;
    for (const auto& s : graded) {
        const std::string stage_name = fs::path(s.folder).filename().string();
        for (const auto& f : s.student_files) {
            const std::string key = s.folder + "/" + f;
            for (const std::string& candidate : {key, stage_name + "/" + f, f}) {
                const fs::path p = sub / candidate;
                const auto st = fs::symlink_status(p, ec);
                if (ec || !fs::exists(st)) continue;
                claimed.insert(candidate);
                if (fs::is_symlink(st)) {
                    in.ignored.push_back({candidate, "symbolic link"});
                    continue;
                }
                if (!fs::is_regular_file(st)) {
                    in.ignored.push_back({candidate, "not a regular file"});
                    continue;
                }
                if (fs::file_size(p, ec) > kMaxStudentFileBytes) {
                    in.ignored.push_back({candidate, "larger than 256 KB"});
                    in.rejected[key] = "larger than 256 KB";
                    break;
                }
                const std::string text = read_text(p);
                const std::string problem = check_source(text, ws_src, s.folder);
                if (!problem.empty())
                    in.rejected[key] = problem;
                else
                    in.files[key] = text;
                break;
            }
        }
    }
    return claimed;
}

// Files of the stages not graded in this run, by every name they may be submitted under.
std::map<std::string, int> other_stage_files(const std::vector<StageSpec>& graded,
                                             const std::vector<StageSpec>& all) {
    std::map<std::string, int> others;
    for (const auto& s : all) {
        if (std::any_of(graded.begin(), graded.end(),
                        [&](const StageSpec& g) { return g.number == s.number; }))
            continue;
        const std::string stage_name = fs::path(s.folder).filename().string();
        for (const auto& f : s.student_files)
            for (const std::string& candidate : {s.folder + "/" + f, stage_name + "/" + f, f})
                others.emplace(candidate, s.number);
    }
    return others;
}

// Why a file nobody claimed is ignored; "" when it is expected and not worth a line (another
// stage's file inside a whole tree, an unchanged file of the course).
std::string ignored_reason(const GradeOptions& o, const fs::directory_entry& entry,
                           const std::string& rel, const std::map<std::string, int>& others) {
    const auto st = entry.symlink_status();
    const std::string name = entry.path().filename().string();
    if (fs::is_symlink(st)) return "symbolic link";
    if (odd_name(name)) return "odd file name";
    if (!fs::is_regular_file(st)) return "not a regular file";
    if (const auto other = others.find(rel); other != others.end()) {
        // In a whole tree, other stages' files are expected; loose ones are worth a word.
        if (rel.starts_with("stages/")) return "";
        const int n = other->second;
        return "the student file of stage " + std::string(n < 10 ? "0" : "") + std::to_string(n) +
               ", which this run does not grade (see --stages)";
    }
    // A copy of the course tree: unchanged files are expected and not worth listing.
    const fs::path theirs = o.source / rel;
    std::error_code ec;
    if (!fs::is_regular_file(theirs, ec)) return "not a student file of the graded stages";
    if (fs::file_size(theirs, ec) == fs::file_size(entry.path(), ec) &&
        read_text(theirs) == read_text(entry.path()))
        return "";
    return "edited course file: ignored, the instructor's copy is used";
}

// Everything else in the submission, listed as ignored (the first 30; the rest counted).
void list_ignored(const GradeOptions& o, Intake& in, const fs::path& sub,
                  const std::set<std::string>& claimed, const std::map<std::string, int>& others) {
    int listed = 0;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(sub, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const std::string rel = it->path().lexically_relative(sub).string();
        const std::string name = it->path().filename().string();
        // Build trees, the history and installed npm packages (tools/web/node_modules, whose
        // .bin/ links every self-grade would otherwise list) are never a student's work.
        const bool generated = it.depth() == 0 && (name.starts_with("build") || name == ".git");
        if (generated || (fs::is_directory(it->symlink_status()) && name == "node_modules")) {
            it.disable_recursion_pending();
            continue;
        }
        if (fs::is_directory(it->symlink_status()) || claimed.count(rel)) continue;
        const std::string reason = ignored_reason(o, *it, rel, others);
        if (reason.empty()) {
            ++in.unchanged;
            continue;
        }
        if (listed >= 30) {
            ++in.ignored_other;
            continue;
        }
        ++listed;
        in.ignored.push_back({clean_output(rel), reason});
        if (in.ignored.size() > 200) break;
    }
}

}  // namespace

Intake take_in(const GradeOptions& o, const std::vector<StageSpec>& graded,
               const std::vector<StageSpec>& all, const fs::path& ws_src) {
    Intake in;
    const fs::path sub = open_submission(o, in);
    if (sub.empty()) return in;
    in.root = sub;
    const std::set<std::string> claimed = claim_student_files(in, sub, graded, ws_src);
    list_ignored(o, in, sub, claimed, other_stage_files(graded, all));
    return in;
}

bool zip_declared_bytes(const fs::path& zip, const std::string& pattern, std::uintmax_t& bytes) {
    std::string command = "unzip -Z -t " + shell_quote(zip.string());
    if (!pattern.empty()) command += " " + shell_quote(pattern);
    std::string listing;
    if (run_trusted(command, &listing) != 0) return false;
    std::smatch m;
    if (!std::regex_search(listing, m, std::regex(R"((\d+) bytes uncompressed)"))) return false;
    bytes = std::stoull(m[1].str());
    return true;
}

std::string extract_capped(const fs::path& zip, const std::string& pattern, const fs::path& dir,
                           const std::string& exclude) {
    // ulimit -f counts 1024-byte blocks; unzip stops at the first file over it. Without -: unzip
    // never writes an absolute or ../ path (-: would allow them, so it is left out).
    std::string command = "ulimit -f " + std::to_string(kMaxZipBytes / 1024) + " && unzip -q -o " +
                          shell_quote(zip.string());
    if (!pattern.empty()) command += " " + shell_quote(pattern);
    if (!exclude.empty()) command += " -x " + shell_quote(exclude);
    return command + " -d " + shell_quote(dir.string());
}

}  // namespace rt::grader
