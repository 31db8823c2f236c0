#include "sandbox.h"

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <grp.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <thread>

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

constexpr uid_t kNobody = 65534;

bool write_file(const char* path, const std::string& text) {
    const int fd = open(path, O_WRONLY);
    if (fd < 0) return false;
    const bool ok = write(fd, text.data(), text.size()) == ssize_t(text.size());
    close(fd);
    return ok;
}

// In the child, after fork: enter new namespaces. Returns false when the kernel refuses.
bool enter_namespaces() {
    const uid_t uid = getuid();
    const gid_t gid = getgid();
    int flags = CLONE_NEWNS | CLONE_NEWNET | CLONE_NEWPID;
    if (uid != 0) flags |= CLONE_NEWUSER;
    if (unshare(flags) != 0) return false;
    if (uid != 0) {
        write_file("/proc/self/setgroups", "deny");
        if (!write_file("/proc/self/uid_map", "0 " + std::to_string(uid) + " 1\n")) return false;
        if (!write_file("/proc/self/gid_map", "0 " + std::to_string(gid) + " 1\n")) return false;
    }
    // Mounts made here must not propagate back to the host.
    return mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) == 0;
}

bool is_under(const fs::path& path, const fs::path& dir) {
    const auto rel = path.lexically_relative(dir);
    return !rel.empty() && *rel.begin() != "..";
}

bool hide(const fs::path& path) {
    struct stat st {};
    if (lstat(path.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) return true;
    return mount("tmpfs", path.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "size=64k,mode=0755") == 0;
}

// Kept directories are set aside (bind mounts), hidden paths above them covered, then the kept
// ones bound back read-only; hidden paths inside kept directories are covered last.
bool hide_paths(const RunSpec& spec, const fs::path& stash) {
    std::vector<fs::path> stashed;
    for (std::size_t i = 0; i < spec.keep.size(); ++i) {
        std::string name = std::to_string(i);
        name.insert(name.begin(), 'k');  // not "k" + ...: GCC 12's -Wrestrict false positive
        const fs::path dir = stash / name;
        mkdir(dir.c_str(), 0700);
        if (mount(spec.keep[i].c_str(), dir.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0)
            return false;
        stashed.push_back(dir);
    }
    auto above_a_keep = [&](const fs::path& h) {
        for (const auto& k : spec.keep)
            if (k == h || is_under(k, h)) return true;
        return false;
    };
    for (const auto& path : spec.hide)
        if (above_a_keep(path) && !hide(path)) return false;
    for (std::size_t i = 0; i < spec.keep.size(); ++i) {
        std::error_code ec;
        fs::create_directories(spec.keep[i], ec);
        const char* k = spec.keep[i].c_str();
        if (mount(stashed[i].c_str(), k, nullptr, MS_BIND | MS_REC, nullptr) != 0) return false;
        if (spec.keep_read_only &&
            mount(nullptr, k, nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY | MS_REC, nullptr) != 0)
            return false;
    }
    for (const auto& path : spec.hide)
        if (!above_a_keep(path) && !hide(path)) return false;
    return true;
}

void set_limit(int resource, rlim_t soft, rlim_t hard) {
    rlimit limit{soft, hard};
    setrlimit(resource, &limit);
}

[[noreturn]] void exec_program(const RunSpec& spec, int out_fd, int err_fd,
                               const std::vector<std::pair<int, int>>& passed, bool drop_uid) {
    const Limits& l = spec.limits;
    set_limit(RLIMIT_CPU, rlim_t(l.cpu_seconds), rlim_t(l.cpu_seconds + 1));
    // RLIMIT_DATA counts the heap and anonymous mappings (what a memory hog grows) but not the
    // shared libraries' mappings, which are large for the renderer (OpenImageIO, OSMesa/LLVM);
    // RLIMIT_AS stays as a coarse backstop.
    set_limit(RLIMIT_DATA, rlim_t(l.memory_mb) << 20, rlim_t(l.memory_mb) << 20);
    set_limit(RLIMIT_AS, rlim_t(l.address_space_mb) << 20, rlim_t(l.address_space_mb) << 20);
    set_limit(RLIMIT_FSIZE, rlim_t(l.file_size_mb) << 20, rlim_t(l.file_size_mb) << 20);
    set_limit(RLIMIT_CORE, 0, 0);
    set_limit(RLIMIT_NPROC, rlim_t(l.processes), rlim_t(l.processes));
    if (drop_uid) {
        // Root ignores RLIMIT_NPROC, so untrusted code never runs as root.
        if (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0) _exit(125);
    }
    if (chdir(spec.working_dir.c_str()) != 0) _exit(126);
    dup2(out_fd, 1);
    dup2(err_fd, 2);
    const int devnull = open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, 0);
    // Moved above 20 beforehand, so no target can overwrite a source still to be placed.
    for (const auto& [from, to] : passed) {
        if (to < 3 || dup2(from, to) != to) _exit(126);
        close(from);
    }
    std::vector<char*> argv;
    for (const auto& a : spec.argv) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::vector<std::string> env = spec.env;
    env.push_back("PATH=/usr/bin:/bin");
    env.push_back("HOME=" + spec.scratch_dir.string());
    std::vector<char*> envp;
    for (auto& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    execve(argv[0], argv.data(), envp.data());
    _exit(127);
}

Isolation forced_or_probed() {
    if (const char* f = std::getenv("RT_GRADE_ISOLATION")) {
        const std::string s = f;
        if (s == "none") return Isolation::None;
        if (s == "uid") return getuid() == 0 ? Isolation::UidDrop : Isolation::None;
    }
    const pid_t pid = fork();
    if (pid == 0) {
        char dir[] = "/tmp/rt-grade-probe-XXXXXX";
        if (!mkdtemp(dir)) _exit(1);
        const bool ok = enter_namespaces() && mount("tmpfs", dir, "tmpfs", 0, "size=4k") == 0;
        umount(dir);
        rmdir(dir);
        _exit(ok ? 0 : 1);
    }
    int status = 0;
    if (pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0)
        return Isolation::Namespaces;
    return getuid() == 0 ? Isolation::UidDrop : Isolation::None;
}

std::string read_capped(const fs::path& file, long long cap, bool& truncated) {
    std::ifstream in(file, std::ios::binary);
    std::string text(std::size_t(cap) + 1, '\0');
    in.read(text.data(), std::streamsize(text.size()));
    text.resize(std::size_t(in.gcount()));
    if (text.size() > std::size_t(cap)) {
        text.resize(std::size_t(cap));
        truncated = true;
    }
    return text;
}

}  // namespace

std::string describe(Isolation isolation) {
    switch (isolation) {
        case Isolation::Namespaces:
            return "namespaces (no network, instructor files hidden, process tree contained)";
        case Isolation::UidDrop:
            return "uid drop to nobody (the kernel refused namespaces: network not blocked)";
        case Isolation::None:
            return "NONE (not root and no user namespaces: resource limits only)";
    }
    return "?";
}

Isolation probe_isolation() {
    static std::once_flag once;
    static Isolation result = Isolation::None;
    std::call_once(once, [] { result = forced_or_probed(); });
    return result;
}

std::string RunResult::describe(const Limits& limits) const {
    char text[160];
    switch (end) {
        case End::Exited:
            std::snprintf(text, sizeof text, "exited with code %d", exit_code);
            return text;
        case End::TimedOut:
            std::snprintf(text, sizeof text, "timed out after %g s", limits.wall_seconds);
            return text;
        case End::FailedToStart:
            return "could not be started";
        case End::Signaled:
            break;
    }
    switch (signal) {
        case SIGXCPU:
            std::snprintf(text, sizeof text, "CPU time limit hit (%d s)", limits.cpu_seconds);
            return text;
        case SIGXFSZ:
            std::snprintf(text, sizeof text, "file size limit hit (%lld MB): too much output?",
                          limits.file_size_mb);
            return text;
        case SIGKILL:
            return "killed (SIGKILL): CPU or memory limit";
    }
    const char* name = sigabbrev_np(signal);
    std::snprintf(text, sizeof text, "crashed: SIG%s%s", name ? name : "?",
                  signal == SIGABRT ? " (an uncaught exception or assertion; out of memory?)" : "");
    return text;
}

RunResult run_sandboxed(const RunSpec& spec) {
    RunResult result;
    const Isolation isolation = probe_isolation();
    std::error_code ec;
    fs::create_directories(spec.scratch_dir, ec);
    const fs::path out_file = spec.scratch_dir / ".stdout", err_file = spec.scratch_dir / ".stderr";
    const int out_fd = open(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const int err_fd = open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    int status_pipe[2];
    if (out_fd < 0 || err_fd < 0 || pipe2(status_pipe, O_CLOEXEC) != 0) return result;
    char stash[] = "/tmp/rt-grade-keep-XXXXXX";
    const bool have_stash = mkdtemp(stash) != nullptr;

    const bool was_root = getuid() == 0;
    const auto start = std::chrono::steady_clock::now();
    const pid_t outer = fork();
    if (outer == 0) {
        // Outer child: new process group, namespaces, hidden paths; then an init process that
        // runs the program and reports its wait status, so every descendant dies with it.
        setpgid(0, 0);
        close(status_pipe[0]);
        const bool drop = spec.drop_uid && was_root && isolation != Isolation::None;
        if (isolation == Isolation::Namespaces) {
            if (!enter_namespaces() || !have_stash || !hide_paths(spec, stash)) _exit(124);
        }
        const pid_t init = fork();
        if (init == 0) {
            prctl(PR_SET_PDEATHSIG, SIGKILL);
            const pid_t program = fork();
            if (program == 0) {
                // File descriptors are dup2'ed without CLOEXEC inside exec_program.
                const int o = fcntl(out_fd, F_DUPFD, 10), e = fcntl(err_fd, F_DUPFD, 10);
                std::vector<std::pair<int, int>> passed;
                for (const auto& [from, to] : spec.pass_fds)
                    passed.push_back({fcntl(from, F_DUPFD_CLOEXEC, 20), to});
                exec_program(spec, o, e, passed, drop);
            }
            int status = 0;
            while (waitpid(program, &status, 0) < 0 && errno == EINTR) {
            }
            if (write(status_pipe[1], &status, sizeof status) != sizeof status) _exit(1);
            _exit(0);  // as PID 1 of the namespace, this kills every leftover process
        }
        int status = 0;
        while (init > 0 && waitpid(init, &status, 0) < 0 && errno == EINTR) {
        }
        _exit(0);
    }
    close(status_pipe[1]);
    close(out_fd);
    close(err_fd);
    if (outer < 0) {
        close(status_pipe[0]);
        return result;
    }
    setpgid(outer, outer);  // also from the parent, against the race with the child's setpgid

    bool timed_out = false;
    int outer_status = 0;
    for (;;) {
        const pid_t done = waitpid(outer, &outer_status, WNOHANG);
        if (done == outer) break;
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (elapsed > spec.limits.wall_seconds || (spec.cancel && spec.cancel->load())) {
            timed_out = true;
            kill(-outer, SIGKILL);
            kill(outer, SIGKILL);
            waitpid(outer, &outer_status, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(elapsed < 1 ? 2 : 20));
    }
    kill(-outer, SIGKILL);  // stragglers of the group (without a PID namespace)
    result.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int status = 0;
    const bool have_status = read(status_pipe[0], &status, sizeof status) == sizeof status;
    close(status_pipe[0]);
    if (have_stash) rmdir(stash);  // the k* mount points live in the child's namespace only
    for (const auto& entry : fs::directory_iterator(stash, ec)) fs::remove(entry.path(), ec);
    fs::remove(stash, ec);

    if (timed_out) {
        result.end = RunResult::End::TimedOut;
    } else if (!have_status) {
        result.end = RunResult::End::FailedToStart;
        if (WIFEXITED(outer_status) && WEXITSTATUS(outer_status) == 124)
            result.output = "sandbox setup failed\n";
    } else if (WIFEXITED(status)) {
        result.end = RunResult::End::Exited;
        result.exit_code = WEXITSTATUS(status);
        if (result.exit_code == 127) result.end = RunResult::End::FailedToStart;
    } else if (WIFSIGNALED(status)) {
        result.end = RunResult::End::Signaled;
        result.signal = WTERMSIG(status);
    }
    bool truncated = false;
    std::string out = read_capped(out_file, spec.limits.output_bytes, truncated);
    std::string err = read_capped(err_file, spec.limits.output_bytes, truncated);
    result.output += out;
    if (!err.empty()) {
        if (!out.empty() && out.back() != '\n') result.output.push_back('\n');
        result.output.append(err);
    }
    if (result.output.size() > std::size_t(spec.limits.output_bytes)) {
        result.output.resize(std::size_t(spec.limits.output_bytes));
        truncated = true;
    }
    result.output_truncated = truncated;
    fs::remove(out_file, ec);
    fs::remove(err_file, ec);
    return result;
}

}  // namespace rt::grader
