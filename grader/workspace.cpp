#include "workspace.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <sstream>

#include "build_settings.h"
#include "object_check.h"
#include "release.h"
#include "sandbox.h"
#include "util.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt::grader {
namespace {

constexpr const char* kStagesArchive = "lib/librt_stages.a";

// What the workspace copies of the tree: what a build reads. A student's renders, reports and
// notes at the top of their tree must not count as a change of the framework.
bool skipped_top_level(const std::string& name) {
    static const std::set<std::string> kept = {
        "CMakeLists.txt", "CMakePresets.json", "cmake", "framework", "stages",
        "grader",         "shaders",           "tools", "scripts",   "reference_images",
        ".rt-grade"};
    return !kept.count(name);
}

// Every file of the instructor's tree the workspace depends on, and a hash of them all.
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

std::string object_name(const std::string& key) {
    std::string name = key;
    std::replace(name.begin(), name.end(), '/', '_');
    return name;
}

}  // namespace

Workspace workspace_paths(const GradeOptions& o) {
    Workspace w;
    w.cache = o.cache.empty() ? o.source / "build" / "grader-cache" : o.cache;
    w.cache = fs::absolute(w.cache).lexically_normal();
    w.root = w.cache / "workspace";
    w.src = w.root / "src";
    // The build inside its tree, as every build of this project is laid out (SOURCE/build):
    // then the compiler cache hashes the workspace's files like those of the build rt-grade
    // came from and reuses its objects (cmake/compiler_cache.cmake). Children never see it
    // (hidden_dirs).
    w.build = w.src / "build";
    w.priv = w.cache / "private";
    return w;
}

std::vector<fs::path> hidden_dirs(const Workspace& w) {
    std::vector<fs::path> dirs = {w.build};
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(w.src / "stages", ec))
        if (fs::is_directory(e.path() / "hidden", ec)) dirs.push_back(e.path() / "hidden");
    return dirs;
}

fs::path solution_object(const Workspace& w, const std::string& key) {
    return w.priv / "objects" / (object_name(key) + ".solution.o");
}
fs::path stub_object(const Workspace& w, const std::string& key) {
    return w.priv / "objects" / (object_name(key) + ".stub.o");
}

std::string pixel_hash(const Image8& image) {
    std::uint64_t h = fnv1a(std::to_string(image.width) + "x" + std::to_string(image.height));
    const auto* bytes = reinterpret_cast<const char*>(image.data.data());
    h = fnv1a(std::string_view(bytes, image.data.size()), h);
    return hex(h);
}

BuildPlan load_build_plan(const Workspace& w) {
    BuildPlan plan;
    const json j = json::parse(read_text(w.priv / "plan.json"));
    plan.compile = j.at("compile").get<decltype(plan.compile)>();
    plan.link = j.at("link").get<decltype(plan.link)>();
    plan.api = j.at("api").get<decltype(plan.api)>();
    plan.instructor_symbols = j.at("instructor_symbols").get<std::set<std::string>>();
    plan.shipped_hashes = j.at("shipped_hashes").get<std::set<std::string>>();
    plan.secret = read_text(w.priv / "secret");
    plan.solution_from_source = j.at("solution_from_source").get<std::set<std::string>>();
    std::error_code ec;
    plan.has_reference = fs::exists(w.priv / "bin" / "rt", ec);
    return plan;
}

bool prepare_workspace(const GradeOptions& o, std::ostream& log) {
    const Workspace w = workspace_paths(o);
    const auto specs = load_stage_specs(o.source);
    std::set<fs::path> student_keys;
    for (const auto& s : specs)
        for (const auto& f : s.student_files) student_keys.insert(fs::path(s.folder) / f);
    std::uint64_t hash = 0;
    const auto files = source_files(o.source, student_keys, hash);
    const std::string key = hex(hash);
    fs::create_directories(w.cache);
    const int lock =
        open((w.cache / "workspace.lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC | O_NOFOLLOW, 0600);
    struct Unlock {
        int fd;
        ~Unlock() { close(fd); }
    } unlock{lock};
    auto read_key = [](const fs::path& f) {
        std::error_code ec;
        return fs::exists(f, ec) ? read_text(f) : std::string();
    };
    // Gradings hold the lock shared while they run; checking the key needs no more. Only a
    // rebuild takes it exclusively (waiting for running gradings to finish).
    flock(lock, LOCK_SH);
    if (read_key(w.priv / "key") == key && read_key(w.root / "key") == key) return true;
    flock(lock, LOCK_UN);
    flock(lock, LOCK_EX);
    if (read_key(w.priv / "key") == key && read_key(w.root / "key") == key) return true;

    log << "rt-grade: preparing the grading workspace " << w.root.string()
        << " (once per framework version, about a minute on 2 cores; later gradings reuse it)\n";
    const auto start = std::chrono::steady_clock::now();
    std::error_code ec;
    fs::remove(w.priv / "key", ec);
    fs::remove_all(w.priv / "objects", ec);
    fs::remove_all(w.root / "build", ec);  // where the build was before workspace v4
    fs::create_directories(w.priv);
    fs::permissions(w.priv, fs::perms::owner_all);  // 0700
    fs::permissions(w.cache, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                 fs::perms::others_read | fs::perms::others_exec);

    // The tree: student files as stubs (public), everything else as is; synced rather than
    // copied afresh, so a change to the instructor's tree rebuilds incrementally.
    std::set<fs::path> wanted;
    std::set<std::string> solution_from_source;
    auto sync = [&](const fs::path& rel, const std::string& text) {
        wanted.insert(rel);
        std::error_code e;
        if (fs::exists(w.src / rel, e) && read_text(w.src / rel) == text) return;
        write_text(w.src / rel, text);
    };
    for (const auto& f : files) {
        if (*f.begin() == "reference_images") continue;  // the child must never see them
        if (f == "CMakeLists.txt") continue;
        std::string text = read_text(o.source / f);
        if (student_keys.count(f)) {
            bool from_source = false;
            const std::string stub = stub_text(o.source, f, text, from_source);
            if (!from_source)
                write_text(w.priv / "pristine" / (f.string() + ".solution"), text);
            else if (is_compiled_student_file(f.string()))  // GLSL is never compiled here
                solution_from_source.insert(f.string());
            write_text(w.priv / "pristine" / (f.string() + ".stub"), stub);
            text = stub;
        }
        sync(f, text);
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
        if (t == "rt" || t == kWorker) continue;
        hidden_cmake +=
            "get_target_property(rt_grade_libs " + t +
            " LINK_LIBRARIES)\n"
            "list(TRANSFORM rt_grade_libs REPLACE \"^GTest::gtest_main$\" \"GTest::gtest\")\n"
            "set_property(TARGET " +
            t +
            " PROPERTY LINK_LIBRARIES ${rt_grade_libs} rt_grade_test_main)\n"
            "target_link_options(" +
            t + " PRIVATE -s)\n";
    }
    sync("grader_hidden.cmake", hidden_cmake);
    sync("CMakeLists.txt",
         read_text(o.source / "CMakeLists.txt") + "\ninclude(grader_hidden.cmake)\n");
    {
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
        for (const auto& p : stale) fs::remove(p, ec);
    }
    std::string out;
    // Compiled as the build rt-grade came from compiles, through its compiler cache: only the
    // trusted build of the instructor's files uses the cache; a student's file is compiled in
    // the jail by its saved command, which has no launcher (stages/CMakeLists.txt).
    const BuildSettings& settings = this_build();
    std::string cmd = "cmake -S " + shell_quote(w.src.string()) + " -B " +
                      shell_quote(w.build.string()) +
                      " -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON" +
                      (settings.werror ? " -DRT_WERROR=ON" : " -DRT_WERROR=OFF");
    cmd += settings.ccache_dir.empty()
               ? " -DRT_CCACHE=OFF"
               : " -DRT_CCACHE=ON -DRT_CCACHE_DIR=" + shell_quote(settings.ccache_dir);
    if (run_trusted(cmd, &out) != 0) {
        log << "rt-grade: error: configuring the workspace failed:\n" << out;
        return false;
    }
    const auto targets = build_targets(specs);
    cmd = "ninja -C " + shell_quote(w.build.string());
    if (const char* j = std::getenv("RT_GRADE_BUILD_JOBS"))
        cmd += " -j " + std::to_string(std::atoi(j));
    for (const auto& t : targets) cmd += " " + t;
    out.clear();
    if (run_with_progress(cmd, out, log) != 0) {
        log << "rt-grade: error: building the instructor's tree failed:\n" << out;
        return false;
    }

    json plan = {{"compile", json::object()}, {"link", json::object()}, {"api", json::object()}};
    // The objects the build above compiled from the workspace's student files, which are the
    // stubs: the same command the jail replays, so they are the stubs' pristine objects.
    std::map<std::string, fs::path> built_stub;
    try {
        // Compile commands of the student files, with the object redirected to @OUT@.
        const json commands = json::parse(read_text(w.build / "compile_commands.json"));
        for (const auto& s : specs)
            for (const auto& f : s.student_files) {
                const std::string k = s.folder + "/" + f;
                if (!is_compiled_student_file(k)) continue;  // GLSL: read at run time
                for (const auto& c : commands)
                    if (c.at("file").get<std::string>() == (w.src / k).string()) {
                        auto argv = command_argv(c.at("command").get<std::string>(), "compile");
                        // A warning in honest student code never fails its grading.
                        std::erase(argv, std::string("-Werror"));
                        for (std::size_t i = 0; i + 1 < argv.size(); ++i)
                            if (argv[i] == "-o") {
                                built_stub[k] = w.build / argv[i + 1];
                                argv[i + 1] = "@OUT@";
                            }
                        plan["compile"][k] = argv;
                    }
                if (!plan["compile"].contains(k))
                    throw std::runtime_error("rt-grade: no compile command for " + k);
            }
        // Link commands, with the stage archive and the output as placeholders.
        for (const auto& t : targets) {
            if (is_judge_target(t)) continue;  // built once, no student code
            std::string text;
            run_argv({"/usr/bin/ninja", "-C", w.build.string(), "-t", "commands", "bin/" + t}, "/",
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
            plan["link"][t] = argv;
        }
    } catch (const std::exception& e) {
        log << e.what() << "\n";
        return false;
    }
    // The instructor's strong symbols (framework libraries, tests): a student object defining
    // one shows intent to replace framework or test code.
    std::set<std::string> instructor;
    for (auto it = fs::recursive_directory_iterator(w.build, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const fs::path p = it->path();
        if (p.string().find("rt_stages") != std::string::npos) continue;
        if (p.extension() != ".a" && p.extension() != ".o") continue;
        for (const auto& [name, type] : defined_symbols(p))
            if (strong(type)) instructor.insert(name);
    }
    plan["instructor_symbols"] = instructor;

    // Pristine objects, compiled the way student files are, and the API of each file: the
    // global functions its stub defines.
    BuildPlan partial;
    partial.compile = plan["compile"].get<decltype(partial.compile)>();
    fs::create_directories(w.priv / "objects");
    std::vector<fs::path> solutions;
    bool jail_compiled = false;  // the first file still compiles in the jail: proof that it works
    for (const auto& s : specs)
        for (const auto& f : s.student_files) {
            const std::string k = s.folder + "/" + f;
            if (!is_compiled_student_file(k)) continue;
            for (const bool solution : {true, false}) {
                if (solution && solution_from_source.count(k)) continue;  // compiled per grading
                const std::string text =
                    read_text(w.priv / "pristine" / (k + (solution ? ".solution" : ".stub")));
                const fs::path raw = w.priv / "objects" / (object_name(k) + ".raw.o");
                std::string compile_log;
                const auto built = built_stub.find(k);
                if (!solution && jail_compiled && built != built_stub.end() &&
                    fs::is_regular_file(built->second, ec) && read_text(w.src / k) == text) {
                    // The build compiled this very text with this very command: a copy saves a
                    // compilation per student file (a second or more each, every preparation).
                    fs::copy_file(built->second, raw, fs::copy_options::overwrite_existing, ec);
                    if (ec) {
                        log << "rt-grade: error: cannot copy " << built->second << ": "
                            << ec.message() << "\n";
                        return false;
                    }
                } else if (!compile_in_jail(w, partial, k, text, w.root / "compile", raw,
                                            compile_log)) {
                    log << "rt-grade: error: the " << (solution ? "solution" : "stub") << " of "
                        << k << " does not compile in the sandbox:\n"
                        << compile_log;
                    return false;
                }
                jail_compiled = true;
                if (!solution) {
                    std::set<std::string> api;
                    for (const auto& [name, type] : defined_symbols(raw))
                        if (strong(type)) api.insert(name);
                    plan["api"][k] = api;
                }
                fs::rename(raw, solution ? solution_object(w, k) : stub_object(w, k));
            }
            solutions.push_back(solution_object(w, k));
        }
    plan["solution_from_source"] = solution_from_source;
    // Every shipped reference image, by pixels: a render equal to one was handed in, not made.
    std::set<std::string> shipped;
    for (auto it = fs::recursive_directory_iterator(o.source / "reference_images", ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        if (it->path().extension() == ".png") shipped.insert(pixel_hash(read_image8(it->path())));
    plan["shipped_hashes"] = shipped;
    write_text(w.priv / "plan.json", plan.dump(1));
    // References of the graded scenes, where children never look.
    for (const auto& s : specs)
        for (const auto& sc : s.scenes) {
            const std::string stage = fs::path(sc.folder).filename().string();
            fs::create_directories(w.priv / "reference_images" / stage);
            fs::copy_file(o.source / "reference_images" / stage / (sc.name + ".png"),
                          w.priv / "reference_images" / stage / (sc.name + ".png"),
                          fs::copy_options::overwrite_existing, ec);
        }
    // The reference renderer (every solution) renders the unseen views at grading time.
    {
        // The secret seeds the unseen views; a student never sees it.
        unsigned char bytes[32];
        if (getrandom(bytes, sizeof bytes, 0) != ssize_t(sizeof bytes)) return false;
        write_text(w.priv / "secret", std::string(reinterpret_cast<char*>(bytes), sizeof bytes));
        BuildPlan linkable;
        linkable.link = plan["link"].get<decltype(linkable.link)>();
        std::string link_log;
        fs::remove_all(w.priv / "bin", ec);
        // A starter tree has no solutions: no reference renderer, no unseen views.
        if (solution_from_source.empty() &&
            !link_stage(w, linkable, solutions, {"rt"}, w.priv / "bin", link_log)) {
            log << "rt-grade: error: linking the reference renderer failed:\n" << link_log;
            return false;
        }
    }
    keep_test_binaries(w, targets);
    write_text(w.priv / "key", key);
    write_text(w.root / "key", key);
    log << "rt-grade: workspace ready in " << int(seconds_since(start)) << " s\n";
    return true;
}

}  // namespace rt::grader
