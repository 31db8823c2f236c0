// `rt-grade --prepare` (and the first grading after a change): the workspace built from the
// instructor's tree as a list of named steps (workspace.h says what it holds).
#include "workspace/workspace_prepare.h"

#include <sys/random.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <sstream>

#include "course/manifest.h"
#include "grading/stage_specs.h"
#include "release/release.h"
#include "util.h"
#include "workspace/build_settings.h"
#include "workspace/object_check.h"
#include "workspace/workspace.h"
#include "workspace/workspace_build.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt::grader {
namespace {

constexpr const char* kStagesArchive = "lib/librt_stages.a";

// What the workspace copies of the tree: what the build of its targets reads. A student's
// renders, reports and notes at the top of their tree must not count as a change of the
// framework. Every grading hashes these files: the instructor's tools (rt-bench, and the 3,500
// files of tools/web's node modules) and scripts are no part of a grading, and hashing them cost
// each grading a second (docs/performance.md).
bool skipped_top_level(const std::string& name) {
    static const std::set<std::string> kept = {
        "CMakeLists.txt", "CMakePresets.json", "cmake",    "framework", "stages", "grader",
        "shaders",        "reference_images",  ".rt-grade"};
    return !kept.count(name);
}

// A student file's text as the workspace builds it: the stub. The instructor's files carry
// solution markers (the stub is derived); a starter tree's files are the student's own work, and
// their stubs as released lie in kStarterStubs (or, failing that, the file is taken as is).
// `from_source` says the file holds no solution: its "solution" is whatever the tree has now.
std::string stub_text(const fs::path& source, const fs::path& key, const std::string& text,
                      bool& from_source) {
    const MarkerResult stub = process_markers(text, RegionMode::Strip);
    from_source = !stub.has_markers;
    if (stub.has_markers) return stub.errors.empty() ? stub.text : text;
    std::error_code ec;
    const fs::path released = source / kStarterStubs / key;
    return fs::is_regular_file(released, ec) ? read_text(released) : text;
}

// Every file of the instructor's tree the workspace depends on, and a hash of them all.
std::vector<fs::path> source_files(const fs::path& source, const std::set<fs::path>& student_keys,
                                   std::uint64_t& hash) {
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
    // Student files count by their stubs: editing one (self-grading in a starter tree) never
    // forces a rebuild of the workspace.
    hash = fnv1a("rt-grade workspace v4");
    for (const auto& f : files) {
        hash = fnv1a(f.string(), hash);
        std::string text = read_text(source / f);
        if (student_keys.count(f)) {
            bool from_source = false;
            text = stub_text(source, f, text, from_source);
        }
        hash = fnv1a(text, hash);
    }
    return files;
}

std::vector<std::string> split_words(const std::string& command) {
    std::vector<std::string> words;
    std::istringstream in(command);
    std::string w;
    while (in >> w) words.push_back(w);
    return words;
}

// A command of CMake's Ninja generator as argv; our paths never need shell quoting (checked).
std::vector<std::string> command_argv(std::string command, const std::string& what) {
    if (command.starts_with(": && ")) command = command.substr(5);
    if (const auto end = command.rfind(" && :");
        end != std::string::npos && end + 5 == command.size())
        command.resize(end);
    if (command.find_first_of("'\"\\$`;|&<>") != std::string::npos)
        throw std::runtime_error(
            "rt-grade: the " + what +
            " command needs a shell (a path with spaces or quotes?): " + command);
    return split_words(command);
}

// A trusted ninja run whose progress ("[12/80] ...") reaches the log every tenth of the way.
int run_with_progress(const std::string& command, std::string& output, std::ostream& log) {
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return -1;
    char line[8192];
    int shown = -1;
    while (std::fgets(line, sizeof line, pipe)) {
        output += line;
        int done = 0, total = 0;
        if (std::sscanf(line, "[%d/%d]", &done, &total) == 2 && total > 0 &&
            done * 10 / total > shown) {
            shown = done * 10 / total;
            log << "rt-grade: building the grading workspace: " << done << " of " << total
                << " steps\n"
                << std::flush;
        }
    }
    const int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// What the workspace builds: the renderer, the worker and each graded binary's judge.
std::vector<std::string> build_targets(const std::vector<StageSpec>& specs) {
    std::set<std::string> targets{"rt", kWorker};
    for (const auto& s : specs)
        for (const auto& g : s.groups) targets.insert(judge_target(g.binary));
    return {targets.begin(), targets.end()};
}

// One preparation's inputs and what its steps hand each other.
struct Preparation {
    explicit Preparation(const GradeOptions& options) : o(options), w(workspace_paths(options)) {}
    const GradeOptions& o;
    Workspace w;
    std::vector<StageSpec> specs;
    std::set<fs::path> student_keys;             // stages/NN-name/file
    std::vector<fs::path> files;                 // the tree's files the workspace depends on
    std::string key;                             // their hash: the workspace's version
    std::vector<std::string> targets;            // what the workspace builds
    std::set<std::string> solution_from_source;  // student files without solutions
    std::map<std::string, fs::path> built_stub;  // the build's own object of each stub
    std::vector<fs::path> solutions;             // the solution objects, for the reference renderer
    json plan = {{"compile", json::object()}, {"link", json::object()}, {"api", json::object()}};
};

std::string read_if_exists(const fs::path& f) {
    std::error_code ec;
    return fs::exists(f, ec) ? read_text(f) : std::string();
}

bool is_current(const Workspace& w, const std::string& key) {
    return read_if_exists(w.priv / "key") == key && read_if_exists(w.root / "key") == key;
}

// The private folder emptied of what a rebuild replaces, and the permissions that keep it private.
void reset_private(const Workspace& w) {
    std::error_code ec;
    fs::remove(w.priv / "key", ec);
    fs::remove_all(w.priv / "objects", ec);
    fs::remove_all(w.root / "build", ec);  // where the build was before workspace v4
    fs::create_directories(w.priv);
    fs::permissions(w.priv, fs::perms::owner_all);  // 0700
    fs::permissions(w.cache, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                 fs::perms::others_read | fs::perms::others_exec);
}

// Hidden tests as targets of their own (added to the workspace copy only), and every graded test
// binary with the trusted main (grader/test_main.cpp) instead of gtest_main, stripped: its
// verdicts come through the nonce channel.
std::string hidden_cmake(const Preparation& p) {
    std::string text = "# Written by rt-grade: hidden tests (never released).\n";
    for (const auto& s : p.specs)
        for (const auto& g : s.groups) {
            if (g.hidden_sources.empty()) continue;
            text += "rt_stage_tests(" + two_digits(s.number) + " " + g.binary + " SOURCES";
            for (const auto& h : g.hidden_sources) text += " " + s.folder + "/" + h;
            text += ")\n";
        }
    text += "# The trusted test main: verdicts through the nonce channel.\n";
    for (const auto& t : p.targets) {
        if (t == "rt" || t == kWorker) continue;
        text += "get_target_property(rt_grade_libs " + t + " LINK_LIBRARIES)\n" +
                "list(TRANSFORM rt_grade_libs REPLACE \"^GTest::gtest_main$\" \"GTest::gtest\")\n" +
                "set_property(TARGET " + t +
                " PROPERTY LINK_LIBRARIES ${rt_grade_libs} rt_grade_test_main)\n" +
                "target_link_options(" + t + " PRIVATE -s)\n";
    }
    return text;
}

// Files of the workspace tree that `wanted` does not list (the build folder aside) removed.
void remove_stale(const Workspace& w, const std::set<fs::path>& wanted) {
    std::error_code ec;
    std::vector<fs::path> stale;
    for (auto it = fs::recursive_directory_iterator(w.src, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (it->path() == w.build) {
            it.disable_recursion_pending();
            continue;
        }
        if (!it->is_directory() && !wanted.count(it->path().lexically_relative(w.src)))
            stale.push_back(it->path());
    }
    for (const auto& f : stale) fs::remove(f, ec);
}

// The tree: student files as stubs (public; solutions kept private), everything else as is;
// synced rather than copied afresh, so a change to the instructor's tree rebuilds incrementally.
void sync_tree(Preparation& p) {
    std::set<fs::path> wanted;
    auto sync = [&](const fs::path& rel, const std::string& text) {
        wanted.insert(rel);
        std::error_code e;
        if (fs::exists(p.w.src / rel, e) && read_text(p.w.src / rel) == text) return;
        write_text(p.w.src / rel, text);
    };
    for (const auto& f : p.files) {
        if (*f.begin() == "reference_images") continue;  // the child must never see them
        if (f == "CMakeLists.txt") continue;
        std::string text = read_text(p.o.source / f);
        if (p.student_keys.count(f)) {
            bool from_source = false;
            const std::string stub = stub_text(p.o.source, f, text, from_source);
            if (!from_source)
                write_text(p.w.priv / "pristine" / (f.string() + ".solution"), text);
            else if (is_compiled_student_file(f.string()))  // GLSL is never compiled here
                p.solution_from_source.insert(f.string());
            write_text(p.w.priv / "pristine" / (f.string() + ".stub"), stub);
            text = stub;
        }
        sync(f, text);
    }
    sync("grader_hidden.cmake", hidden_cmake(p));
    sync("CMakeLists.txt",
         read_text(p.o.source / "CMakeLists.txt") + "\ninclude(grader_hidden.cmake)\n");
    remove_stale(p.w, wanted);
}

// Configures and builds the workspace as the build rt-grade came from compiles, through its
// compiler cache: only the trusted build of the instructor's files uses the cache; a student's
// file is compiled in the jail by its saved command, which has no launcher.
bool configure_and_build(const Preparation& p, std::ostream& log) {
    std::string out;
    const BuildSettings& settings = this_build();
    std::string cmd = "cmake -S " + shell_quote(p.w.src.string()) + " -B " +
                      shell_quote(p.w.build.string()) +
                      " -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON" +
                      // Gradings open no window: no viewer, no GLFW, nothing of X11 to package.
                      " -DRT_VIEWER=OFF -DRT_GL_WINDOW=OFF" +
                      (settings.werror ? " -DRT_WERROR=ON" : " -DRT_WERROR=OFF");
    cmd += settings.ccache_dir.empty()
               ? " -DRT_CCACHE=OFF"
               : " -DRT_CCACHE=ON -DRT_CCACHE_DIR=" + shell_quote(settings.ccache_dir);
    if (run_trusted(cmd, &out) != 0) {
        log << "rt-grade: error: configuring the workspace failed:\n" << out;
        return false;
    }
    cmd = "ninja -C " + shell_quote(p.w.build.string());
    if (const char* j = std::getenv("RT_GRADE_BUILD_JOBS"))
        cmd += " -j " + std::to_string(std::atoi(j));
    for (const auto& t : p.targets) cmd += " " + t;
    out.clear();
    if (run_with_progress(cmd, out, log) != 0) {
        log << "rt-grade: error: building the instructor's tree failed:\n" << out;
        return false;
    }
    return true;
}

// The compile command of each compiled student file, the object redirected to @OUT@ (the jail
// replays it), and the object the build made from the stub with it.
void record_compile_commands(Preparation& p) {
    const json commands = json::parse(read_text(p.w.build / "compile_commands.json"));
    for (const auto& s : p.specs)
        for (const auto& f : s.student_files) {
            const std::string k = s.folder + "/" + f;
            if (!is_compiled_student_file(k)) continue;  // GLSL: read at run time
            for (const auto& c : commands)
                if (c.at("file").get<std::string>() == (p.w.src / k).string()) {
                    auto argv = command_argv(c.at("command").get<std::string>(), "compile");
                    // A warning in honest student code never fails its grading.
                    std::erase(argv, std::string("-Werror"));
                    for (std::size_t i = 0; i + 1 < argv.size(); ++i)
                        if (argv[i] == "-o") {
                            p.built_stub[k] = p.w.build / argv[i + 1];
                            argv[i + 1] = "@OUT@";
                        }
                    p.plan["compile"][k] = argv;
                }
            if (!p.plan["compile"].contains(k))
                throw std::runtime_error("rt-grade: no compile command for " + k);
        }
}

// The link command of each target that links student code, with the stage archive and the
// output as placeholders.
void record_link_commands(Preparation& p) {
    for (const auto& t : p.targets) {
        if (is_judge_target(t)) continue;  // built once, no student code
        std::string text;
        run_argv({"/usr/bin/ninja", "-C", p.w.build.string(), "-t", "commands", "bin/" + t}, "/",
                 text);
        std::string last;
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);)
            if (!line.empty()) last = line;
        auto argv = command_argv(last, "link");
        bool has_archive = false;
        for (std::size_t i = 0; i < argv.size(); ++i) {
            if (argv[i] == kStagesArchive) {
                argv[i] = "@STAGES@";
                has_archive = true;
            }
            if (argv[i] == "-o" && i + 1 < argv.size()) argv[i + 1] = "@OUT@";
        }
        if (!has_archive)
            throw std::runtime_error("rt-grade: " + t + " does not link " + kStagesArchive);
        p.plan["link"][t] = argv;
    }
}

// The instructor's strong symbols (framework libraries, tests): a student object defining one
// shows intent to replace framework or test code.
std::set<std::string> instructor_symbols(const Workspace& w) {
    std::set<std::string> instructor;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(w.build, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const fs::path f = it->path();
        if (f.string().find("rt_stages") != std::string::npos) continue;
        if (f.extension() != ".a" && f.extension() != ".o") continue;
        for (const auto& [name, type] : defined_symbols(f))
            if (strong(type)) instructor.insert(name);
    }
    return instructor;
}

// One pristine object (the solution or the stub of student file `k`), compiled as student files
// are; the stub's strong symbols become the file's API. `jail_compiled`: a file already compiled
// in the jail, proof that it works, after which the build's own object of a stub may be copied.
bool pristine_object(Preparation& p, const BuildPlan& partial, const std::string& k, bool solution,
                     bool& jail_compiled, std::ostream& log) {
    std::error_code ec;
    const std::string text =
        read_text(p.w.priv / "pristine" / (k + (solution ? ".solution" : ".stub")));
    const fs::path raw = p.w.priv / "objects" / (object_name(k) + ".raw.o");
    std::string compile_log;
    const auto built = p.built_stub.find(k);
    if (!solution && jail_compiled && built != p.built_stub.end() &&
        fs::is_regular_file(built->second, ec) && read_text(p.w.src / k) == text) {
        // The build compiled this very text with this very command: a copy saves a compilation
        // per student file (a second or more each, every preparation).
        fs::copy_file(built->second, raw, fs::copy_options::overwrite_existing, ec);
        if (ec) {
            log << "rt-grade: error: cannot copy " << built->second << ": " << ec.message() << "\n";
            return false;
        }
    } else if (!compile_in_jail(p.w, partial, k, text, p.w.root / "compile", raw, compile_log)) {
        log << "rt-grade: error: the " << (solution ? "solution" : "stub") << " of " << k
            << " does not compile in the sandbox:\n"
            << compile_log;
        return false;
    }
    jail_compiled = true;
    if (!solution) {
        std::set<std::string> api;
        for (const auto& [name, type] : defined_symbols(raw))
            if (strong(type)) api.insert(name);
        p.plan["api"][k] = api;
    }
    fs::rename(raw, solution ? solution_object(p.w, k) : stub_object(p.w, k));
    return true;
}

// Pristine objects of every compiled student file: its solution (unless it has none) and stub.
bool build_pristine_objects(Preparation& p, std::ostream& log) {
    BuildPlan partial;
    partial.compile = p.plan["compile"].get<decltype(partial.compile)>();
    fs::create_directories(p.w.priv / "objects");
    bool jail_compiled = false;
    for (const auto& s : p.specs)
        for (const auto& f : s.student_files) {
            const std::string k = s.folder + "/" + f;
            if (!is_compiled_student_file(k)) continue;
            for (const bool solution : {true, false}) {
                if (solution && p.solution_from_source.count(k)) continue;  // compiled per grading
                if (!pristine_object(p, partial, k, solution, jail_compiled, log)) return false;
            }
            p.solutions.push_back(solution_object(p.w, k));
        }
    return true;
}

// Every shipped reference image, by pixels: a render equal to one was handed in, not made.
std::set<std::string> shipped_hashes(const fs::path& source) {
    std::set<std::string> shipped;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(source / "reference_images", ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        if (it->path().extension() == ".png") shipped.insert(pixel_hash(read_image8(it->path())));
    return shipped;
}

// References of the graded scenes, where children never look.
void copy_references(const Preparation& p) {
    std::error_code ec;
    for (const auto& s : p.specs)
        for (const auto& sc : s.scenes) {
            const std::string stage = fs::path(sc.folder).filename().string();
            fs::create_directories(p.w.priv / "reference_images" / stage);
            fs::copy_file(p.o.source / "reference_images" / stage / (sc.name + ".png"),
                          p.w.priv / "reference_images" / stage / (sc.name + ".png"),
                          fs::copy_options::overwrite_existing, ec);
        }
}

// The secret that seeds the unseen views (a student never sees it), and the reference renderer
// (every solution) that renders them at grading time. A starter tree has no solutions: no
// reference renderer, no unseen views.
bool link_reference_renderer(const Preparation& p, std::ostream& log) {
    unsigned char bytes[32];
    if (getrandom(bytes, sizeof bytes, 0) != ssize_t(sizeof bytes)) return false;
    write_text(p.w.priv / "secret", std::string(reinterpret_cast<char*>(bytes), sizeof bytes));
    BuildPlan linkable;
    linkable.link = p.plan["link"].get<decltype(linkable.link)>();
    std::string link_log;
    std::error_code ec;
    fs::remove_all(p.w.priv / "bin", ec);
    if (p.solution_from_source.empty() &&
        !link_stage(p.w, linkable, p.solutions, {"rt"}, p.w.priv / "bin", link_log)) {
        log << "rt-grade: error: linking the reference renderer failed:\n" << link_log;
        return false;
    }
    return true;
}

// The build plan (plan.json): commands, symbols, pristine objects, reference hashes.
bool make_build_plan(Preparation& p, std::ostream& log) {
    try {
        record_compile_commands(p);
        record_link_commands(p);
    } catch (const std::exception& e) {
        log << e.what() << "\n";
        return false;
    }
    p.plan["instructor_symbols"] = instructor_symbols(p.w);
    if (!build_pristine_objects(p, log)) return false;
    p.plan["solution_from_source"] = p.solution_from_source;
    p.plan["shipped_hashes"] = shipped_hashes(p.o.source);
    write_text(p.w.priv / "plan.json", p.plan.dump(1));
    return true;
}

}  // namespace

bool prepare_workspace(const GradeOptions& o, std::ostream& log) {
    Preparation p(o);
    if (is_packaged(p.w)) return true;  // built where the package was made, and complete
    p.specs = load_stage_specs(o.source);
    for (const auto& s : p.specs)
        for (const auto& f : s.student_files) p.student_keys.insert(fs::path(s.folder) / f);
    std::uint64_t hash = 0;
    p.files = source_files(o.source, p.student_keys, hash);
    p.key = hex(hash);
    p.targets = build_targets(p.specs);
    // Gradings hold the lock shared while they run; checking the key needs no more. Only a
    // rebuild takes it exclusively (waiting for running gradings to finish).
    WorkspaceLock lock(p.w.cache);
    lock.shared();
    if (is_current(p.w, p.key)) return true;
    lock.exclusive();
    if (is_current(p.w, p.key)) return true;

    log << "rt-grade: preparing the grading workspace " << p.w.root.string()
        << " (once per framework version, about a minute on 2 cores; later gradings reuse it)\n";
    const auto start = std::chrono::steady_clock::now();
    reset_private(p.w);
    sync_tree(p);
    if (!configure_and_build(p, log) || !make_build_plan(p, log)) return false;
    copy_references(p);
    if (!link_reference_renderer(p, log)) return false;
    keep_test_binaries(p.w, p.targets);
    write_text(p.w.priv / "key", p.key);
    write_text(p.w.root / "key", p.key);
    log << "rt-grade: workspace ready in " << int(seconds_since(start)) << " s\n";
    return true;
}

}  // namespace rt::grader
