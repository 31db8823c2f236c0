// The grading-time steps on a prepared workspace: one submitted file compiled in the jail, and
// a graded stage's binaries linked from objects (workspace.h, steps 1 and 3); and the test
// binaries a preparation keeps.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "grading/stage_specs.h"
#include "sandbox/sandbox.h"
#include "util.h"
#include "workspace/workspace_build.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

std::vector<std::string> replaced(std::vector<std::string> argv, const std::string& from,
                                  const std::string& to) {
    for (auto& a : argv)
        if (a == from) a = to;
    return argv;
}

}  // namespace

bool compile_in_jail(const Workspace& w, const BuildPlan& plan, const std::string& key,
                     const std::string& text, const fs::path& work, const fs::path& object,
                     std::string& log) {
    const auto it = plan.compile.find(key);
    if (it == plan.compile.end()) {
        log = "no compile command for " + key;
        return false;
    }
    // `work` is trusted-only: the source copy and captures; `out` is the one folder the
    // compiler may write, owned by the sandbox uid for this run.
    std::error_code ec;
    fs::remove_all(work, ec);
    fs::create_directories(work / "out");
    fs::permissions(work, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
    write_text(work / "source.cpp", text);
    RunSpec r;
    r.argv = replaced(it->second, "@OUT@", (work / "out" / "student.o").string());
    if (probe_isolation() != Isolation::Namespaces) {
        // No jail to show the text at its own path: compile a copy the compiler's uid can read,
        // with quoted includes and __FILE__ as if it were in place.
        const fs::path copy = work / "out" / fs::path(key).filename();
        write_text(copy, text);
        r.argv = replaced(r.argv, (w.src / key).string(), copy.string());
        r.argv.insert(r.argv.begin() + 1,
                      {"-iquote", (w.src / key).parent_path().string(),
                       "-fmacro-prefix-map=" + copy.string() + "=" + (w.src / key).string()});
    }
    r.working_dir = work / "out";
    r.capture_dir = work / "capture";
    show_workspace(w, r, false);
    r.binds.insert(r.binds.end(),
                   {{work / "source.cpp", w.src / key, false}, {work / "out", {}, true}});
    r.empty_dirs = hidden_dirs(w);
    r.limits = {120, 120, 16384, 4096, 64, 64, 256 * 1024};
    const RunResult res = run_sandboxed(r);
    log = clean_output(res.output);
    for (const auto& root : {w.src.string() + "/", w.build.string() + "/"}) {
        std::size_t p;
        while ((p = log.find(root)) != std::string::npos) log.erase(p, root.size());
    }
    if (!res.ok()) {
        if (res.end != RunResult::End::Exited || log.empty())
            log = "the compiler " + res.describe(r.limits) + "\n" + log;
        return false;
    }
    // Read back through a descriptor that refuses symlinks: the folder was the child's.
    const int fd = open((work / "out" / "student.o").c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st {};
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size > (256 << 20)) {
        if (fd >= 0) close(fd);
        log = "the compiler wrote no object file\n" + log;
        return false;
    }
    std::string bytes(std::size_t(st.st_size), '\0');
    const bool read_all = pread(fd, bytes.data(), bytes.size(), 0) == ssize_t(bytes.size());
    close(fd);
    if (!read_all) return false;
    write_text(object, bytes);
    return true;
}

bool link_stage(const Workspace& w, const BuildPlan& plan, const std::vector<fs::path>& objects,
                const std::vector<std::string>& targets, const fs::path& bin, std::string& log) {
    fs::create_directories(bin);
    const fs::path archive = bin / "librt_stages.a";
    std::error_code ec;
    fs::remove(archive, ec);
    // Members are named by their file: copy under distinct names first.
    std::vector<std::string> ar{"/usr/bin/ar", "qcs", archive.string()};
    for (const auto& o : objects) ar.push_back(o.string());
    if (run_argv(ar, w.build, log) != 0) return false;
    for (const auto& t : targets) {
        const auto it = plan.link.find(t);
        if (it == plan.link.end()) {
            log += "no link command for " + t + "\n";
            return false;
        }
        auto argv = replaced(replaced(it->second, "@STAGES@", archive.string()), "@OUT@",
                             (bin / t).string());
        std::string out;
        if (run_argv(argv, w.build, out) != 0) {
            log += clean_output(out);
            return false;
        }
    }
    return true;
}

namespace {

// The test names `--gtest_list_tests` prints, as Suite.Test.
std::vector<std::string> listed_tests(const std::string& listing) {
    std::vector<std::string> names;
    std::istringstream lines(listing);
    std::string line, suite;
    while (std::getline(lines, line)) {
        if (line.empty() || line.starts_with("Running main")) continue;
        if (line[0] != ' ') {
            suite = line.substr(0, line.find_first_of(" #"));
        } else {
            std::string test = line.substr(2);
            names.push_back(suite + test.substr(0, test.find_first_of(" #")));
        }
    }
    return names;
}

}  // namespace

void keep_test_binaries(const Workspace& w, const std::vector<std::string>& targets) {
    fs::create_directories(w.priv / "judges");
    for (const auto& t : targets) {
        if (t == "rt" || t == kWorker) continue;
        if (is_judge_target(t))
            fs::copy_file(w.build / "bin" / t, w.priv / "judges" / t,
                          fs::copy_options::overwrite_existing);
        const std::string graded =
            is_judge_target(t) ? t.substr(0, t.size() - judge_target("").size()) : t;
        std::string out;
        run_argv({(w.build / "bin" / t).string(), "--gtest_list_tests"}, w.build, out);
        write_text(w.priv / "expected" / (graded + ".json"),
                   nlohmann::json(listed_tests(out)).dump(1));
    }
}

}  // namespace rt::grader
