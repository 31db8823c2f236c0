#include "grade.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "image/compare.h"
#include "image/image.h"
#include "perceptual.h"
#include "release.h"
#include "report.h"
#include "sandbox.h"
#include "util.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt::grader {

std::atomic<bool> g_interrupted{false};

namespace {

constexpr std::uintmax_t kMaxStudentFileBytes = 256 * 1024;
constexpr std::uintmax_t kMaxZipBytes = 64ull << 20;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string two_digits(int n) {
    char text[8];
    std::snprintf(text, sizeof text, "%02d", n);
    return text;
}

// ---------------------------------------------------------------- grading specs

ImageThresholds parse_thresholds(const json& j, ImageThresholds t) {
    t.tolerance = j.value("tolerance", t.tolerance);
    t.pass_percent = j.value("pass_percent", t.pass_percent);
    t.fail_percent = j.value("fail_percent", t.fail_percent);
    t.neighbourhood = j.value("neighbourhood", t.neighbourhood);
    return t;
}

void check_visibility(const std::string& v, const fs::path& file) {
    if (v != "visible" && v != "hidden" && v != "after_due_date" && v != "after_published")
        throw std::runtime_error(file.string() + ": visibility \"" + v +
                                 "\" is not one of visible, hidden, after_due_date, after_published");
}

}  // namespace

std::vector<StageSpec> load_stage_specs(const fs::path& source) {
    std::vector<StageSpec> specs;
    std::vector<fs::path> folders;
    for (const auto& entry : fs::directory_iterator(source / "stages"))
        if (entry.is_directory() && fs::exists(entry.path() / "grading.json"))
            folders.push_back(entry.path());
    std::sort(folders.begin(), folders.end());
    for (const auto& folder : folders) {
        const fs::path file = folder / "grading.json";
        try {
            const json stage = json::parse(read_text(folder / "stage.json"));
            const json g = json::parse(read_text(file));
            StageSpec s;
            s.number = stage.at("number").get<int>();
            s.folder = "stages/" + folder.filename().string();
            s.title = stage.value("title", folder.filename().string());
            s.student_files = stage.at("student_files").get<std::vector<std::string>>();
            s.test_seconds = g.value("test_seconds", s.test_seconds);
            s.render_seconds = g.value("render_seconds", s.render_seconds);
            const ImageThresholds defaults =
                parse_thresholds(g.value("image_defaults", json::object()), ImageThresholds{});
            for (const json& u : g.value("unit_tests", json::array())) {
                UnitGroup group;
                group.binary = u.at("binary").get<std::string>();
                group.include = u.value("include", group.include);
                group.exclude = u.value("exclude", group.exclude);
                group.hidden_sources = u.value("hidden_sources", group.hidden_sources);
                group.points = u.value("points", group.points);
                group.visibility = u.value("visibility", group.visibility);
                check_visibility(group.visibility, file);
                bool present = true;
                for (const auto& h : group.hidden_sources) {
                    if (!h.starts_with("hidden/"))
                        throw std::runtime_error(file.string() + ": hidden source " + h +
                                                 " must lie in the stage's hidden/ folder");
                    present = present && fs::is_regular_file(folder / h);
                }
                // A released starter tree has no hidden/ folder: students grading themselves
                // simply do not get those tests.
                if (present) s.groups.push_back(group);
            }
            for (const json& sc : g.value("scenes", json::array())) {
                SceneSpec scene;
                scene.name = sc.at("name").get<std::string>();
                scene.points = sc.value("points", scene.points);
                scene.visibility = sc.value("visibility", scene.visibility);
                check_visibility(scene.visibility, file);
                scene.thresholds = parse_thresholds(sc, defaults);
                s.scenes.push_back(scene);
            }
            specs.push_back(std::move(s));
        } catch (const json::exception& e) {
            throw std::runtime_error(file.string() + ": " + e.what());
        }
    }
    return specs;
}

namespace {

// ---------------------------------------------------------------- workspace

struct Workspace {
    fs::path cache, slot, src, build, priv;
};

Workspace workspace_paths(const GradeOptions& o) {
    Workspace w;
    w.cache = o.cache.empty() ? o.source / "build" / "grader-cache" : o.cache;
    w.cache = fs::absolute(w.cache).lexically_normal();
    w.slot = w.cache / ("slot-" + std::to_string(o.slot));
    w.src = w.slot / "src";
    w.build = w.slot / "build";
    w.priv = w.cache / "private";
    return w;
}

bool skipped_top_level(const std::string& name) {
    return name == ".git" || name.starts_with("build") || name == "gallery" || name == "out";
}

// Every file of the instructor's tree the workspace depends on, and a hash of them all.
std::vector<fs::path> source_files(const fs::path& source, std::uint64_t& hash) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(source, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (it.depth() == 0 && skipped_top_level(it->path().filename().string())) {
            it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file()) files.push_back(it->path().lexically_relative(source));
    }
    std::sort(files.begin(), files.end());
    hash = fnv1a("rt-grade workspace v2");
    for (const auto& f : files) {
        hash = fnv1a(f.string(), hash);
        hash = fnv1a(read_text(source / f), hash);
    }
    return files;
}

std::vector<std::string> build_targets(const std::vector<StageSpec>& specs) {
    std::set<std::string> targets{"rt"};
    for (const auto& s : specs)
        for (const auto& g : s.groups) targets.insert(g.binary);
    return {targets.begin(), targets.end()};
}

// The instructor's strong symbols (framework libraries, tests): a student object that defines
// one of them would replace framework or test code at link time.
std::string collect_instructor_symbols(const fs::path& build) {
    std::string list;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(build, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const fs::path p = it->path();
        const std::string s = p.string();
        if (s.find("rt_stages") != std::string::npos || s.find("grader-cache") != std::string::npos)
            continue;
        if (p.extension() != ".a" && p.extension() != ".o") continue;
        std::string out;
        run_trusted("nm -g --defined-only -P " + shell_quote(s), &out);
        std::istringstream lines(out);
        std::string line;
        while (std::getline(lines, line)) {
            std::istringstream words(line);
            std::string name, type;
            if (!(words >> name >> type) || name.back() == ':') continue;
            if (type == "T" || type == "D" || type == "B" || type == "R") list += name + "\n";
        }
    }
    return list;
}

std::map<std::string, std::vector<std::string>> list_tests(const Workspace& w,
                                                           const std::vector<std::string>& bins) {
    std::map<std::string, std::vector<std::string>> tests;
    for (const auto& bin : bins) {
        if (bin == "rt") continue;
        const json saved = json::parse(read_text(w.priv / "expected" / (bin + ".json")));
        tests[bin] = saved.get<std::vector<std::string>>();
    }
    return tests;
}

}  // namespace

bool prepare_workspace(const GradeOptions& o, std::ostream& log) {
    const Workspace w = workspace_paths(o);
    const auto specs = load_stage_specs(o.source);
    std::uint64_t hash = 0;
    const auto files = source_files(o.source, hash);
    const std::string key = hex(hash);
    fs::create_directories(w.cache);
    const int lock = open((w.cache / ("slot-" + std::to_string(o.slot) + ".lock")).c_str(),
                          O_CREAT | O_RDWR | O_CLOEXEC, 0600);
    flock(lock, LOCK_EX);
    struct Unlock {
        int fd;
        ~Unlock() { close(fd); }
    } unlock{lock};

    auto read_key = [](const fs::path& f) {
        std::error_code ec;
        return fs::exists(f, ec) ? read_text(f) : std::string();
    };
    // Private: pristine student files, references, expected test lists (shared by slots).
    if (read_key(w.priv / "key") != key) {
        fs::remove_all(w.priv);
        fs::create_directories(w.priv);
        fs::permissions(w.priv, fs::perms::owner_all);  // 0700: unreadable after a uid drop
        for (const auto& s : specs) {
            for (const auto& f : s.student_files) {
                const std::string text = read_text(o.source / s.folder / f);
                write_text(w.priv / "pristine" / s.folder / (f + ".solution"), text);
                const MarkerResult stub = process_markers(text, RegionMode::Strip);
                write_text(w.priv / "pristine" / s.folder / (f + ".stub"),
                           stub.errors.empty() ? stub.text : text);
            }
            const fs::path refs = o.source / "reference_images" / fs::path(s.folder).filename();
            fs::create_directories(w.priv / "reference_images" / fs::path(s.folder).filename());
            for (const auto& sc : s.scenes)
                fs::copy_file(refs / (sc.name + ".png"),
                              w.priv / "reference_images" / fs::path(s.folder).filename() /
                                  (sc.name + ".png"),
                              fs::copy_options::overwrite_existing) ||
                    true;
        }
    }
    // Later stages without grading.json (work in progress) get stubs too, if they have markers.
    if (read_key(w.slot / "key") == key && fs::exists(w.build / "bin" / "rt")) return true;

    log << "rt-grade: preparing grading workspace " << w.slot.string()
        << " (once per source change; builds the framework)\n";
    const auto start = std::chrono::steady_clock::now();
    // Sync rather than copy afresh: unchanged files keep their timestamps, so a change to the
    // instructor's tree rebuilds incrementally.
    std::set<fs::path> wanted;
    auto sync = [&](const fs::path& rel, const std::string& text) {
        wanted.insert(rel);
        std::error_code ec;
        if (fs::exists(w.src / rel, ec) && read_text(w.src / rel) == text) return;
        write_text(w.src / rel, text);
    };
    for (const auto& f : files) {
        if (*f.begin() == "reference_images") continue;  // the child must never see them
        if (f == "CMakeLists.txt") continue;
        sync(f, read_text(o.source / f));
    }
    // Hidden tests: targets of their own, added to the workspace copy only.
    std::string hidden_cmake = "# Written by rt-grade: hidden tests (never released).\n";
    for (const auto& s : specs)
        for (const auto& g : s.groups) {
            if (g.hidden_sources.empty()) continue;
            hidden_cmake += "rt_stage_tests(" + two_digits(s.number) + " " + g.binary + " SOURCES";
            for (const auto& h : g.hidden_sources) hidden_cmake += " " + s.folder + "/" + h;
            hidden_cmake += ")\n";
        }
    // Every graded test binary gets the trusted main (grader/test_main.cpp) instead of
    // gtest_main, and is stripped: its verdicts come through the nonce channel.
    hidden_cmake += "# The trusted test main: verdicts through the nonce channel.\n";
    for (const auto& t : build_targets(specs)) {
        if (t == "rt") continue;
        hidden_cmake += "get_target_property(rt_grade_libs " + t + " LINK_LIBRARIES)\n"
                        "list(TRANSFORM rt_grade_libs REPLACE \"^GTest::gtest_main$\" \"GTest::gtest\")\n"
                        "set_property(TARGET " + t +
                        " PROPERTY LINK_LIBRARIES ${rt_grade_libs} rt_grade_test_main)\n"
                        "target_link_options(" + t + " PRIVATE -s)\n";
    }
    sync("grader_hidden.cmake", hidden_cmake);
    sync("CMakeLists.txt", read_text(o.source / "CMakeLists.txt") + "\ninclude(grader_hidden.cmake)\n");
    {
        std::vector<fs::path> stale;
        std::error_code ec;
        for (auto it = fs::recursive_directory_iterator(w.src, ec);
             !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
            if (!it->is_directory() && !wanted.count(it->path().lexically_relative(w.src)))
                stale.push_back(it->path());
        for (const auto& p : stale) fs::remove(p, ec);
    }
    std::string out;
    std::string cmd = "cmake -S " + shell_quote(w.src.string()) + " -B " +
                      shell_quote(w.build.string()) +
                      " -G Ninja -DCMAKE_BUILD_TYPE=Release -DRT_WERROR=OFF";
    if (run_trusted(cmd, &out) != 0) {
        log << "rt-grade: error: configuring the workspace failed:\n" << out;
        return false;
    }
    const auto targets = build_targets(specs);
    cmd = "ninja -C " + shell_quote(w.build.string());
    if (const char* j = std::getenv("RT_GRADE_BUILD_JOBS")) cmd += " -j " + std::to_string(std::atoi(j));
    for (const auto& t : targets) cmd += " " + t;
    out.clear();
    if (run_trusted(cmd, &out) != 0) {
        log << "rt-grade: error: building the instructor's tree failed:\n" << out;
        return false;
    }
    // The expected test lists come from the instructor's binaries, built from the solutions.
    for (const auto& t : targets) {
        if (t == "rt") continue;
        out.clear();
        run_trusted(shell_quote((w.build / "bin" / t).string()) + " --gtest_list_tests", &out);
        std::vector<std::string> names;
        std::istringstream lines(out);
        std::string line, suite;
        while (std::getline(lines, line)) {
            if (line.empty() || line.starts_with("Running main")) continue;
            if (line[0] != ' ') {
                suite = line.substr(0, line.find_first_of(" #"));
            } else {
                std::string test = line.substr(2);
                test = test.substr(0, test.find_first_of(" #"));
                names.push_back(suite + test);
            }
        }
        write_text(w.priv / "expected" / (t + ".json"), json(names).dump(1));
    }
    write_text(w.priv / "symbols.txt", collect_instructor_symbols(w.build));
    write_text(w.priv / "key", key);
    write_text(w.slot / "key", key);
    log << "rt-grade: workspace ready in " << int(seconds_since(start)) << " s\n";
    return true;
}

namespace {

// ---------------------------------------------------------------- submission intake

struct Ignored {
    std::string path, reason;
};

struct Intake {
    fs::path root;  // where the files are (extracted zip or the folder)
    fs::path temp;  // to remove afterwards
    std::map<std::string, std::string> files;  // "stages/NN/file" -> content (accepted)
    std::map<std::string, std::string> rejected;  // "stages/NN/file" -> why
    std::vector<Ignored> ignored;
    int ignored_other = 0;  // files outside the whitelist beyond the listed ones
    int unchanged = 0;      // files identical to the course tree's (a whole starter tree)
    std::string error;      // the submission could not be read at all
};

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
std::string check_source(const std::string& text, const fs::path& ws_src, const std::string& folder) {
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
    std::string listing;
    if (run_trusted("unzip -Z -t " + shell_quote(zip.string()), &listing) != 0) {
        error = "not a readable zip file";
        return false;
    }
    std::smatch m;
    if (std::regex_search(listing, m, std::regex(R"((\d+) bytes uncompressed)")) &&
        std::stoull(m[1].str()) > kMaxZipBytes) {
        error = "the zip expands to more than 64 MB";
        return false;
    }
    std::string out;
    fs::create_directories(dir);
    // -: never absolute or ../ paths (unzip's default refuses them; -: would allow, so omit it).
    run_trusted("unzip -qq -o " + shell_quote(zip.string()) + " -d " + shell_quote(dir.string()),
                &out);
    return true;
}

Intake take_in(const GradeOptions& o, const std::vector<StageSpec>& graded,
               const std::vector<StageSpec>& all, const fs::path& ws_src) {
    Intake in;
    fs::path sub = o.submission;
    std::error_code ec;
    if (fs::is_regular_file(sub) && sub.extension() == ".zip") {
        char tmpl[] = "/tmp/rt-grade-zip-XXXXXX";
        if (!mkdtemp(tmpl)) {
            in.error = "cannot create a temporary folder";
            return in;
        }
        in.temp = tmpl;
        if (!extract_zip(sub, in.temp, in.error)) return in;
        sub = in.temp;
    } else if (!fs::is_directory(sub)) {
        in.error = "the submission is neither a folder nor a .zip";
        return in;
    }
    // A zip of one folder: look inside it.
    for (int depth = 0; depth < 3; ++depth) {
        std::vector<fs::path> entries;
        for (const auto& e : fs::directory_iterator(sub, ec))
            if (e.path().filename() != "__MACOSX") entries.push_back(e.path());
        if (entries.size() == 1 && fs::is_directory(fs::symlink_status(entries[0])))
            sub = entries[0];
        else
            break;
    }
    in.root = sub;

    // Where each graded student file may be: a whole tree, a stage folder, or loose files.
    std::set<std::string> claimed;
    for (const auto& s : graded) {
        const std::string stage_name = fs::path(s.folder).filename().string();
        for (const auto& f : s.student_files) {
            const std::string key = s.folder + "/" + f;
            for (const std::string& candidate :
                 {key, stage_name + "/" + f, f}) {
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
                if (!problem.empty()) {
                    in.rejected[key] = problem;
                } else {
                    in.files[key] = text;
                }
                break;
            }
        }
    }
    (void)all;
    // Everything else is listed as ignored.
    int listed = 0;
    for (auto it = fs::recursive_directory_iterator(sub, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const std::string rel = it->path().lexically_relative(sub).string();
        const std::string name = it->path().filename().string();
        if (it.depth() == 0 && (name.starts_with("build") || name == ".git")) {
            it.disable_recursion_pending();
            continue;
        }
        const auto st = it->symlink_status();
        if (fs::is_directory(st)) continue;
        if (claimed.count(rel)) continue;
        std::string reason = fs::is_symlink(st)      ? "symbolic link"
                             : odd_name(name)        ? "odd file name"
                             : !fs::is_regular_file(st) ? "not a regular file"
                                                     : "not a student file of the graded stages";
        if (reason.starts_with("not a student")) {
            // A copy of the course tree: unchanged files are expected and not worth listing.
            const fs::path theirs = o.source / rel;
            std::error_code e2;
            if (fs::is_regular_file(theirs, e2)) {
                if (fs::file_size(theirs, e2) == fs::file_size(it->path(), e2) &&
                    read_text(theirs) == read_text(it->path())) {
                    ++in.unchanged;
                    continue;
                }
                reason = "edited course file: ignored, the instructor's copy is used";
            }
        }
        if (listed >= 30) {
            ++in.ignored_other;
            continue;
        }
        ++listed;
        in.ignored.push_back({clean_output(rel), reason});
        if (in.ignored.size() > 200) break;
    }
    return in;
}

// ---------------------------------------------------------------- running

struct TestOutcome {
    std::string name, number, status = "failed", output, visibility = "visible";
    std::vector<std::string> tags;
    double score = 0, max_score = 0;
    int stage = 0;
    bool is_scene = false;
    // Scenes: images for the HTML report (PNG bytes), metrics.
    std::string student_png, reference_png, diff_png;
    std::string metrics;
};

std::vector<std::string> handout_hints(const std::string& output) {
    std::vector<std::string> hints;
    static const std::regex read(R"(read (stages/[^\s;]+\.md#[A-Za-z0-9_-]+))");
    for (auto it = std::sregex_iterator(output.begin(), output.end(), read);
         it != std::sregex_iterator(); ++it)
        if (std::find(hints.begin(), hints.end(), (*it)[1].str()) == hints.end())
            hints.push_back((*it)[1].str());
    return hints;
}

std::string trim_gtest_output(const std::string& raw) {
    std::string out;
    std::istringstream lines(clean_output(raw));
    std::string line;
    while (std::getline(lines, line)) {
        if (line.starts_with("Running main()") || line.starts_with("Note: Google Test filter") ||
            line.starts_with("[==========]") || line.starts_with("[----------]") ||
            line.starts_with("[  PASSED  ]") || line.starts_with(" 1 FAILED TEST") ||
            line.starts_with("[ RUN      ]") || line.starts_with("[       OK ]"))
            continue;
        out += line + "\n";
    }
    if (out.size() > 4000) out = out.substr(0, 4000) + "\n[... output truncated]\n";
    return out;
}

// The unit-test channel (grader/test_main.cpp): a random nonce goes to the child through a
// pipe, its trusted main writes one record per test to an unlinked file, each carrying the nonce.
struct TestChannel {
    std::string nonce;      // 32 hex digits
    int nonce_read = -1;    // the child's RT_GRADE_NONCE_FD
    int results = -1;       // the child's RT_GRADE_RESULT_FD; read back by the grader
    bool ok = false;
    ~TestChannel() {
        if (nonce_read >= 0) close(nonce_read);
        if (results >= 0) close(results);
    }
};
constexpr int kNonceFd = 3, kResultFd = 4;

void open_channel(TestChannel& c, const fs::path& dir) {
    unsigned char bytes[16];
    if (getrandom(bytes, sizeof bytes, 0) != ssize_t(sizeof bytes)) return;
    static const char digits[] = "0123456789abcdef";
    for (unsigned char b : bytes) {
        c.nonce.push_back(digits[b >> 4]);
        c.nonce.push_back(digits[b & 15]);
    }
    int p[2];
    if (pipe2(p, O_CLOEXEC) != 0) return;
    const bool written = write(p[1], c.nonce.data(), c.nonce.size()) == ssize_t(c.nonce.size());
    close(p[1]);
    c.nonce_read = p[0];
    // No name: nothing in the child can open it by path (it can only write to the descriptor).
    c.results = open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    if (c.results < 0) {
        // Filesystems without O_TMPFILE (overlayfs before Linux 6.6, as in many containers): a
        // file of a random name, unlinked before the child starts.
        std::string name = (dir / ".channel-XXXXXX").string();
        c.results = mkostemp(name.data(), O_CLOEXEC);
        if (c.results >= 0) unlink(name.c_str());
    }
    c.ok = written && c.results >= 0;
}

std::string read_channel(const TestChannel& c) {
    std::string text(1 << 16, '\0');
    const ssize_t n = pread(c.results, text.data(), text.size(), 0);
    text.resize(n > 0 ? std::size_t(n) : 0);
    return text;
}

// The verdict: every record carries the nonce (else the channel was tampered with), exactly one
// record names this test and says PASS, the program's end record counts 1 passed and 0 failed,
// and the process exited with code 0 (checked by the caller).
bool channel_passed(const std::string& records, const std::string& nonce, const std::string& test,
                    std::string& why) {
    const std::string prefix = "RTG1 " + nonce + " ";
    std::istringstream lines(records);
    std::string line;
    int mine = 0, passes = 0, ends = 0;
    bool end_ok = false;
    while (std::getline(lines, line)) {
        if (!line.starts_with(prefix)) {
            why = "the test's result channel holds a record that did not come from the test "
                  "runner (tampering?)";
            return false;
        }
        const std::string rest = line.substr(prefix.size());
        if (rest.starts_with("END ")) {
            ++ends;
            end_ok = rest == "END 1 0";
        } else if (rest.starts_with("PASS ") || rest.starts_with("FAIL ")) {
            if (rest.substr(5) != test) {
                why = "the result channel names a test that was not run (tampering?)";
                return false;
            }
            ++mine;
            passes += rest.starts_with("PASS ");
        } else {
            why = "the test's result channel holds a malformed record (tampering?)";
            return false;
        }
    }
    if (mine == 0) {
        why = "the test produced no result (it exited early?)";
        return false;
    }
    if (mine != 1 || ends != 1) {
        why = "the result channel holds duplicate records (tampering?)";
        return false;
    }
    return passes == 1 && end_ok;
}

std::string png_bytes(const Image8& image, const fs::path& scratch, const std::string& name) {
    const fs::path file = scratch / (name + ".png");
    write_image8(image, file);
    return read_text(file);
}

// What a student object must not contain. Its definitions would replace the instructor's at link
// time (main, GoogleTest, framework functions, C library functions such as write or getenv,
// operator new), or run before the trusted test main has taken the nonce (prioritized
// constructors, .preinit_array, .init code, IFUNC resolvers). One line per problem.
std::string object_problems(const fs::path& obj, const std::set<std::string>& instructor) {
    std::string problems;
    auto demangle = [](const std::string& name) {
        std::string d;
        run_trusted("c++filt " + shell_quote(name), &d);
        while (!d.empty() && d.back() == '\n') d.pop_back();
        return d;
    };
    std::string out;
    run_trusted("nm -g --defined-only -P " + shell_quote(obj.string()), &out);
    std::istringstream lines(out);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string name, type;
        if (!(words >> name >> type)) continue;
        const bool weak = type == "W" || type == "V";
        if (name == "main" || name.find("7testing") != std::string::npos ||
            name.find("gtest") != std::string::npos || (!weak && instructor.count(name))) {
            problems += "  " + demangle(name) + "\n";
            continue;
        }
        if (type == "i") {
            problems += "  " + demangle(name) + " (an IFUNC resolver)\n";
            continue;
        }
        // The compiler's own weak helper for exception handling is not a C library function.
        if (!name.starts_with("_Z") && name != "DW.ref.__gxx_personality_v0") {
            problems += "  " + name + " (extern \"C\" or assembler name: could replace a C library function)\n";
            continue;
        }
        if (weak) continue;  // template instantiations and inline functions
        const std::string d = demangle(name);
        std::string bare = d;
        for (const char* p : {"vtable for ", "typeinfo for ", "typeinfo name for ", "VTT for ",
                              "guard variable for ", "non-virtual thunk to ", "virtual thunk to "})
            if (bare.starts_with(p)) bare = bare.substr(std::strlen(p));
        for (const char* p : {"std::", "__gnu_cxx::", "__cxxabiv1::", "abi::", "operator new",
                              "operator delete", "__"})
            if (bare.starts_with(p)) {
                problems += "  " + d + " (a definition of a standard library symbol)\n";
                break;
            }
    }
    // Sections: code that runs before main must be ordinary constructors (.init_array).
    out.clear();
    run_trusted("readelf -S -W " + shell_quote(obj.string()), &out);
    std::istringstream sections(out);
    while (std::getline(sections, line)) {
        const auto open = line.find('[');
        const auto close = line.find("] ", open == std::string::npos ? 0 : open);
        if (open == std::string::npos || close == std::string::npos) continue;
        std::istringstream words(line.substr(close + 2));
        std::string section;
        if (!(words >> section) || section == "Name" || section == "NULL") continue;
        std::string base = section;
        for (const char* rel : {".rela", ".rel"})
            if (base.starts_with(std::string(rel) + ".")) {
                base = base.substr(std::strlen(rel));
                break;
            }
        const bool ok =
            base == ".init_array" || base == ".fini_array" || base == ".group" ||
            base == ".symtab" || base == ".strtab" || base == ".shstrtab" ||
            base == ".comment" || base == ".eh_frame" || base == ".llvm_addrsig" ||
            base == ".sframe" || base == ".tbss" || base == ".tdata" ||
            base.starts_with(".text") || base.starts_with(".data") || base.starts_with(".bss") ||
            base.starts_with(".rodata") || base.starts_with(".gcc_except_table") ||
            base.starts_with(".note.GNU-stack") || base.starts_with(".note.gnu.property") ||
            base.starts_with(".debug") || base.starts_with(".tbss.") || base.starts_with(".tdata.");
        if (!ok) problems += "  section " + section + " (runs code or data before main?)\n";
    }
    return problems;
}

}  // namespace

// Reads the child's EXR after it has exited. NaN or Inf pixels fail the image.
bool read_render(const fs::path& file, Image& image, std::string& why) {
    std::error_code ec;
    const auto st = fs::symlink_status(file, ec);
    if (ec || !fs::is_regular_file(st)) {
        why = "the renderer wrote no image";
        return false;
    }
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) {
        why = "the rendered image cannot be read";
        return false;
    }
    const auto& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.width > 8192 || spec.height > 8192 ||
        spec.nchannels < 3) {
        why = "the rendered image has an impossible size";
        return false;
    }
    std::vector<float> data(std::size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data())) {
        why = "the rendered image cannot be read";
        return false;
    }
    image = Image(spec.width, spec.height);
    long long bad = 0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        Color c(data[i * spec.nchannels], data[i * spec.nchannels + 1], data[i * spec.nchannels + 2]);
        if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) ++bad;
        image.pixels[i] = c;
    }
    if (bad > 0) {
        why = std::to_string(bad) + " pixels are NaN or infinite";
        return false;
    }
    return true;
}


ImageScore score_image(const Image8& actual, const Image8& reference, const ImageThresholds& th) {
    ImageScore score;
    CompareOptions co;
    co.tolerance = th.tolerance;
    co.max_failing_percent = th.pass_percent;
    co.neighbourhood = th.neighbourhood;
    score.compare = compare_images(actual, reference, co);
    if (!score.compare.size_matches) {
        score.metrics = "the image is " + std::to_string(actual.width) + "x" +
                        std::to_string(actual.height) + ", the reference " +
                        std::to_string(reference.width) + "x" + std::to_string(reference.height);
        return score;
    }
    const double failing = score.compare.failing_percent;
    if (failing <= th.pass_percent) score.fraction = 1;
    else if (failing < th.fail_percent)
        score.fraction = (th.fail_percent - failing) / (th.fail_percent - th.pass_percent);
    score.ssim = ssim_luminance(actual, reference);
    char line[400];
    std::snprintf(line, sizeof line,
                  "%.3f%% of the pixels differ by more than %d (full points up to %.2f%%, none "
                  "from %.2f%%); max difference %d; SSIM %.4f (reported, not graded)",
                  failing, th.tolerance, th.pass_percent, th.fail_percent,
                  score.compare.max_difference, score.ssim);
    score.metrics = line;
    return score;
}

GradeSummary grade_submission(const GradeOptions& o, std::ostream& log) {
    const auto start = std::chrono::steady_clock::now();
    GradeSummary summary;
    const Workspace w = workspace_paths(o);
    const auto all_specs = load_stage_specs(o.source);
    std::vector<StageSpec> graded;
    for (const auto& s : all_specs)
        if (o.stages.empty() || std::count(o.stages.begin(), o.stages.end(), s.number))
            graded.push_back(s);
    const auto expected = list_tests(w, build_targets(all_specs));
    // Only the graded stages' binaries are relinked (stale others are never run).
    const auto targets = build_targets(graded);
    const Isolation isolation = probe_isolation();

    // Every test the grade will have, score 0 until run: the placeholder results.json and
    // the list a failed build reports.
    std::vector<TestOutcome> outcomes;
    struct Task {
        std::size_t outcome;
        std::string binary, test;  // unit test
        const SceneSpec* scene = nullptr;
        const StageSpec* stage = nullptr;
    };
    std::vector<Task> tasks;
    for (const auto& s : graded) {
        int n = 0;
        for (const auto& g : s.groups) {
            const auto it = expected.find(g.binary);
            if (it == expected.end()) continue;
            for (const auto& t : it->second) {
                bool in = false;
                for (const auto& p : g.include) in = in || glob_match(p, t);
                for (const auto& p : g.exclude) in = in && !glob_match(p, t);
                if (!in) continue;
                TestOutcome out;
                out.stage = s.number;
                out.name = "Stage " + two_digits(s.number) + " " + t;
                out.number = std::to_string(s.number) + "." + std::to_string(++n);
                out.max_score = g.points;
                out.visibility = g.visibility;
                out.tags = {"stage" + two_digits(s.number),
                            g.hidden_sources.empty() ? "unit" : "hidden"};
                out.output = "not run: grading did not finish\n";
                tasks.push_back({outcomes.size(), g.binary, t, nullptr, &s});
                outcomes.push_back(out);
            }
        }
        for (const auto& sc : s.scenes) {
            TestOutcome out;
            out.stage = s.number;
            out.name = "Stage " + two_digits(s.number) + " image " + sc.name;
            out.number = std::to_string(s.number) + "." + std::to_string(++n);
            out.max_score = sc.points;
            out.visibility = sc.visibility;
            out.tags = {"stage" + two_digits(s.number), "image"};
            out.output = "not run: grading did not finish\n";
            out.is_scene = true;
            tasks.push_back({outcomes.size(), "rt", sc.name, &sc, &s});
            outcomes.push_back(out);
        }
    }
    std::vector<TestOutcome> notes;  // 0-point entries: build, file checks
    std::string general;             // top-level output

    auto to_report = [&]() {
        Report r;
        r.isolation = describe(isolation);
        r.general = general;
        r.seconds = seconds_since(start);
        for (const auto& s : graded) r.stages.push_back({s.number, s.title, s.folder});
        for (const auto* list : {&notes, &outcomes})
            for (const auto& t : *list)
                r.tests.push_back({t.stage, t.name, t.number, t.status, t.output, t.visibility,
                                   t.tags, t.score, t.max_score, t.is_scene, t.student_png,
                                   t.reference_png, t.diff_png, t.metrics});
        return r;
    };
    if (!o.results.empty()) write_results_json(to_report(), o.results);

    const int lock = open((w.cache / ("slot-" + std::to_string(o.slot) + ".lock")).c_str(),
                          O_CREAT | O_RDWR | O_CLOEXEC, 0600);
    flock(lock, LOCK_EX);
    char scratch_template[] = "/tmp/rt-grade-run-XXXXXX";
    const fs::path scratch = mkdtemp(scratch_template) ? scratch_template : "/tmp/rt-grade-run";
    fs::permissions(scratch, fs::perms::all);  // children (nobody) write their output here

    Intake in = take_in(o, graded, all_specs, w.src);
    if (!in.error.empty()) general += "The submission could not be read: " + in.error + "\n";
    for (const auto& s : graded) {
        for (const auto& f : s.student_files) {
            const std::string key = s.folder + "/" + f;
            if (in.files.count(key)) continue;
            TestOutcome note;
            note.stage = s.number;
            note.name = "Stage " + two_digits(s.number) + " file " + f;
            note.number = std::to_string(s.number) + ".0";
            note.tags = {"stage" + two_digits(s.number), "submission"};
            note.output = in.rejected.count(key)
                              ? key + " was not used: " + in.rejected[key] + "\n"
                              : key + " is missing from the submission\n";
            note.output += "The stage is graded with the starter stub in its place.\n";
            notes.push_back(note);
        }
    }

    // Overlay: graded stages get the student's files (or the stub); stages before the first
    // graded one keep the solution (so a later stage can be graded alone); later stages stubs.
    const int first_graded = graded.empty() ? 0 : graded.front().number;
    bool changed = false;
    std::vector<fs::path> student_objects;
    for (const auto& s : all_specs) {
        const bool is_graded = std::any_of(graded.begin(), graded.end(),
                                           [&](const StageSpec& g) { return g.number == s.number; });
        for (const auto& f : s.student_files) {
            const std::string key = s.folder + "/" + f;
            std::string text;
            if (is_graded && in.files.count(key)) text = in.files[key];
            else if (!is_graded && s.number < first_graded)
                text = read_text(w.priv / "pristine" / s.folder / (f + ".solution"));
            else
                text = read_text(w.priv / "pristine" / s.folder / (f + ".stub"));
            const fs::path target = w.src / key;
            if (read_text(target) != text) {
                write_text(target, text);
                changed = true;
            }
            if (is_graded)
                student_objects.push_back(w.build / "stages" / "CMakeFiles" / "rt_stages.dir" /
                                          fs::path(s.folder).filename() / (f + ".o"));
        }
    }
    (void)changed;

    // Build only what the overlay touches; the compiler runs sandboxed too (it reads files).
    std::vector<fs::path> hide = {fs::absolute(o.source), w.priv};
    for (const auto& s : all_specs) hide.push_back(w.src / s.folder / "hidden");
    // The output folders are hidden too, unless that would hide what the child needs (a
    // results file in /tmp); the grader writes its files after every child has exited anyway.
    for (const auto& p : {o.results, o.html}) {
        if (p.empty()) continue;
        const fs::path dir = fs::absolute(p).parent_path().lexically_normal();
        auto contains = [&](const fs::path& inner) {
            const auto rel = inner.lexically_relative(dir);
            return !rel.empty() && *rel.begin() != "..";
        };
        if (dir != "/" && dir != "/tmp" && !contains(scratch) && !contains(w.slot))
            hide.push_back(dir);
    }
    bool build_ok = true;
    std::string build_log;
    if (!g_interrupted) {
        RunSpec b;
        b.argv = {"/usr/bin/ninja", "-C", w.build.string()};
        if (const char* j = std::getenv("RT_GRADE_BUILD_JOBS"))
            b.argv.push_back("-j" + std::to_string(std::max(1, std::atoi(j))));
        for (const auto& t : targets) b.argv.push_back(t);
        b.working_dir = w.build;
        b.scratch_dir = scratch / "build";
        b.hide = {fs::absolute(o.source), w.priv};
        b.keep = {w.slot};
        b.keep_read_only = false;
        b.drop_uid = false;
        b.limits = {180, 300, 16384, 4096, 1024, 512, 256 * 1024};
        b.cancel = &g_interrupted;
        const RunResult r = run_sandboxed(b);
        build_ok = r.ok();
        build_log = clean_output(r.output);
        if (!build_ok && r.end != RunResult::End::Exited)
            build_log = "the build " + r.describe(b.limits) + "\n" + build_log;
    }
    // Student objects must not define main, test or framework symbols (their definitions would
    // replace the instructor's at link time).
    std::string symbol_problems;
    if (build_ok) {
        std::set<std::string> instructor;
        {
            std::istringstream s(read_text(w.priv / "symbols.txt"));
            std::string line;
            while (std::getline(s, line)) instructor.insert(line);
        }
        for (const auto& obj : student_objects) symbol_problems += object_problems(obj, instructor);
        if (!symbol_problems.empty()) build_ok = false;
    }
    if (!build_ok) {
        summary.build_failed = true;
        std::string first_errors;
        if (!symbol_problems.empty()) {
            first_errors = "Your files define symbols or sections the grader does not allow "
                           "(main, test code, framework or library functions, code that runs "
                           "before main). Remove them:\n" + symbol_problems;
        } else {
            std::istringstream lines(build_log);
            std::string line;
            int kept = 0;
            bool in_error = false;
            while (std::getline(lines, line) && kept < 40) {
                // Paths of the workspace are shown relative to the tree, as the student knows them.
                for (const auto& root : {w.src.string() + "/", w.build.string() + "/"}) {
                    std::size_t p;
                    while ((p = line.find(root)) != std::string::npos) line.erase(p, root.size());
                }
                if (line.find("error") != std::string::npos) in_error = true;
                if (in_error && !line.starts_with("[")) {
                    first_errors += line + "\n";
                    ++kept;
                }
            }
            if (first_errors.empty()) first_errors = build_log.substr(0, 3000);
        }
        if (g_interrupted) first_errors = "(grading was interrupted during the build)\n";
        TestOutcome note;
        note.name = "Build (compiling your files)";
        note.number = "0.1";
        note.tags = {"build"};
        note.output = "The build failed, so no test could run. The compiler's first errors:\n\n" +
                      first_errors;
        notes.insert(notes.begin(), note);
        for (auto& t : outcomes) t.output = "not run: the build failed (see the Build test)\n";
    }

    // Without namespaces the hidden tests are kept from the child (uid nobody) by permissions.
    if (isolation == Isolation::UidDrop)
        for (const auto& s : all_specs) {
            std::error_code ec;
            if (fs::exists(w.src / s.folder / "hidden", ec))
                fs::permissions(w.src / s.folder / "hidden", fs::perms::owner_all, ec);
        }

    // Run every test and render in its own sandboxed child, `jobs` at a time.
    if (build_ok) {
        std::vector<fs::path> run_hide = hide;
        std::atomic<std::size_t> next{0};
        const int jobs = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
        auto worker = [&]() {
            for (std::size_t i; (i = next++) < tasks.size();) {
                if (g_interrupted) break;
                const Task& task = tasks[i];
                TestOutcome& out = outcomes[task.outcome];
                const fs::path dir = scratch / std::to_string(i);
                fs::create_directories(dir);
                fs::permissions(dir, fs::perms::all);
                RunSpec r;
                r.limits.memory_mb = 512;  // Gradescope's default container has 768 MB
                r.working_dir = dir;
                r.scratch_dir = dir;
                r.hide = run_hide;
                r.keep = {w.src, w.build};
                r.cancel = &g_interrupted;
                if (!task.scene) {
                    r.argv = {(w.build / "bin" / task.binary).string(),
                              "--gtest_filter=" + task.test, "--gtest_color=no"};
                    r.limits.wall_seconds = o.time_limit > 0 ? o.time_limit : task.stage->test_seconds;
                    r.limits.cpu_seconds = int(std::ceil(r.limits.wall_seconds));
                    TestChannel channel;
                    open_channel(channel, dir);
                    r.env = {"RT_GRADE_NONCE_FD=" + std::to_string(kNonceFd),
                             "RT_GRADE_RESULT_FD=" + std::to_string(kResultFd)};
                    r.pass_fds = {{channel.nonce_read, kNonceFd}, {channel.results, kResultFd}};
                    const RunResult res = channel.ok ? run_sandboxed(r) : RunResult{};
                    std::string why = channel.ok ? "" : "the grader could not open the test channel";
                    const bool passed =
                        res.ok() && channel_passed(read_channel(channel), channel.nonce, task.test, why);
                    out.output = trim_gtest_output(res.output);
                    if (!passed) {
                        std::string head = res.ok() ? why : res.describe(r.limits);
                        if (res.end == RunResult::End::Exited && res.exit_code == 1)
                            head = "failed:";  // gtest's own verdict; its message follows
                        if (res.output_truncated) head += " (output truncated)";
                        out.output = head + "\n" + out.output;
                    }
                    out.status = passed ? "passed" : "failed";
                    out.score = passed ? out.max_score : 0;
                } else {
                    const fs::path exr = dir / "render.exr";
                    r.argv = {(w.build / "bin" / "rt").string(), "render",
                              (w.src / task.stage->folder / "scenes" / (task.scene->name + ".json")).string(),
                              "-o", exr.string(), "--threads", "1", "-q"};
                    r.limits.wall_seconds = o.time_limit > 0 ? o.time_limit : task.stage->render_seconds;
                    r.limits.cpu_seconds = int(std::ceil(r.limits.wall_seconds));
                    const RunResult res = run_sandboxed(r);
                    out.output = clean_output(res.output);
                    if (out.output.size() > 3000) out.output.resize(3000);
                    Image image;
                    std::string why;
                    if (!res.ok()) {
                        out.output = "the renderer " + res.describe(r.limits) + "\n" + out.output;
                    } else if (!read_render(exr, image, why)) {
                        out.output = why + "\n" + out.output;
                    } else {
                        const Image8 actual = to_image8(image);
                        const Image8 reference = read_image8(
                            w.priv / "reference_images" / fs::path(task.stage->folder).filename() /
                            (task.scene->name + ".png"));
                        const ImageScore sc = score_image(actual, reference, task.scene->thresholds);
                        out.student_png = png_bytes(actual, dir, "student");
                        out.reference_png = png_bytes(reference, dir, "reference");
                        out.output = sc.metrics + "\n" + out.output;
                        if (sc.compare.size_matches) {
                            out.diff_png = png_bytes(sc.compare.heat_map, dir, "diff");
                            out.score = std::round(out.max_score * sc.fraction * 100) / 100;
                            out.metrics = sc.metrics;
                            const double fraction = sc.fraction;
                            if (fraction >= 1) out.status = "passed";
                        }
                    }
                }
                // Workspace paths read as the student's tree: stages/..., framework/...
                for (const auto& root : {w.src.string() + "/", w.build.string() + "/"}) {
                    std::size_t p;
                    while ((p = out.output.find(root)) != std::string::npos)
                        out.output.erase(p, root.size());
                }
                for (const auto& hint : handout_hints(out.output))
                    out.output += "Read the handout: " + hint + "\n";
            }
        };
        std::vector<std::thread> pool;
        for (int j = 0; j < jobs; ++j) pool.emplace_back(worker);
        for (auto& t : pool) t.join();
    }
    if (g_interrupted) general += "Grading was interrupted: tests not run score 0.\n";

    if (!in.ignored.empty() || in.ignored_other > 0) {
        general += "Ignored files (only the student files of the graded stages are used):\n";
        for (const auto& ig : in.ignored) general += "  " + ig.path + ": " + ig.reason + "\n";
        if (in.ignored_other > 0)
            general += "  ... and " + std::to_string(in.ignored_other) + " more files outside the whitelist\n";
    }
    if (isolation != Isolation::Namespaces)
        general += "Sandbox: " + describe(isolation) + "\n";

    for (const auto& s : graded) {
        double got = 0;
        for (const auto& t : outcomes)
            if (t.stage == s.number) got += t.score;
        summary.stage_numbers.push_back(s.number);
        summary.stage_scores.push_back(got);
    }
    for (const auto& t : outcomes) {
        summary.score += t.score;
        summary.max_score += t.max_score;
    }
    summary.seconds = seconds_since(start);
    const Report report = to_report();
    if (!o.results.empty()) write_results_json(report, o.results);
    if (!o.html.empty()) write_html_report(report, o.html);
    if (!o.quiet) write_terminal_summary(report, log, o.reveal_hidden);

    std::error_code ec;
    fs::remove_all(scratch, ec);
    if (!in.temp.empty()) fs::remove_all(in.temp, ec);
    close(lock);
    return summary;
}

}  // namespace rt::grader
