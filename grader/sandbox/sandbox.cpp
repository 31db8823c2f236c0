#include "sandbox/sandbox.h"
#include "sandbox/confine.h"
#include "sandbox/cpu_lease.h"
#include "sandbox/jail.h"

#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <linux/capability.h>
#include <pwd.h>
#include <sched.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

// ---------------------------------------------------------------- uid leases

// Sandbox uids: none of them is a user of the machine; each is leased to one run at a time
// through an flock on a file in a root-only folder, so concurrent gradings (batch jobs, two
// instructors, CI) never share a uid, and with it RLIMIT_NPROC or the right to signal.
constexpr uid_t kUidBase = 2'000'000;
constexpr int kUidCount = 4096;

struct UidLease {
    uid_t uid = 0;
    int fd = -1;
    UidLease() = default;
    UidLease(const UidLease&) = delete;
    UidLease& operator=(const UidLease&) = delete;
    ~UidLease() {
        if (fd >= 0) close(fd);
    }
};

bool lease_uid(UidLease& lease) {
    const char* dir = "/run/rt-grade-uids";
    mkdir(dir, 0700);
    struct stat st {};
    // A folder someone else could have planted (or a symlink) is not trusted.
    if (lstat(dir, &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != 0 || (st.st_mode & 077))
        return false;
    const int dfd = open(dir, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (dfd < 0) return false;
    // Start at a random place: fewer collisions between processes starting together.
    const int start = int(getpid() % kUidCount);
    for (int i = 0; i < kUidCount; ++i) {
        const int k = (start + i) % kUidCount;
        const uid_t uid = kUidBase + uid_t(k);
        if (getpwuid(uid) != nullptr) continue;  // a real account: never
        // Any task of the uid (zombies too: they count against RLIMIT_NPROC) means an earlier
        // run left something behind that nobody reaped: a fresh uid is better.
        if (count_processes_of(uid, true) > 0) continue;
        const std::string name = std::to_string(k) + ".lock";
        const int fd = openat(dfd, name.c_str(), O_CREAT | O_RDWR | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd < 0) continue;
        if (flock(fd, LOCK_EX | LOCK_NB) == 0) {
            lease.uid = uid;
            lease.fd = fd;
            close(dfd);
            return true;
        }
        close(fd);
    }
    close(dfd);
    return false;
}

// Kills every process running under `uid`: a helper that becomes `uid` and signals -1 reaches
// exactly the processes that uid owns, wherever they were started (setsid, double forks).
void reap_uid(uid_t uid) {
    for (int round = 0; round < 50 && count_processes_of(uid) > 0; ++round) {
        const pid_t pid = fork();
        if (pid == 0) {
            if (setresgid(uid, uid, uid) != 0 || setresuid(uid, uid, uid) != 0) _exit(1);
            kill(-1, SIGKILL);
            _exit(0);
        }
        if (pid > 0) waitpid(pid, nullptr, 0);
        std::this_thread::sleep_for(std::chrono::milliseconds(round < 5 ? 2 : 20));
    }
}

void set_limit(int resource, rlim_t soft, rlim_t hard) {
    rlimit limit{soft, hard};
    setrlimit(resource, &limit);
}

// No capability survives into the program (matters when the jail runs in a user namespace,
// where the program would otherwise be root of it).
void drop_capabilities() {
    for (int cap = 0; cap <= 63; ++cap) prctl(PR_CAPBSET_DROP, cap, 0, 0, 0);
    __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
    __user_cap_data_struct data[2] = {};
    syscall(SYS_capset, &header, data);
}

[[noreturn]] void refuse_to_run(const char* what) {
    const std::string text = std::string("sandbox setup failed: ") + what + "\n";
    if (write(2, text.data(), text.size()) < 0) _exit(126);
    _exit(126);
}

// `scratch`: the program's private folder when it runs without a jail (Landlock confines it
// then), empty in the jail.
[[noreturn]] void exec_program(const RunSpec& spec, int out_fd, int err_fd,
                               const std::vector<std::pair<int, int>>& passed, uid_t uid,
                               const fs::path& scratch) {
    const Limits& l = spec.limits;
    set_limit(RLIMIT_CPU, rlim_t(l.cpu_seconds), rlim_t(l.cpu_seconds + 1));
    // RLIMIT_DATA counts the heap and anonymous mappings (what a memory hog grows) but not the
    // shared libraries' mappings, which are large for the renderer (OpenImageIO, OSMesa/LLVM);
    // RLIMIT_AS stays as a coarse backstop.
    set_limit(RLIMIT_DATA, rlim_t(l.memory_mb) << 20, rlim_t(l.memory_mb) << 20);
    set_limit(RLIMIT_AS, rlim_t(l.address_space_mb) << 20, rlim_t(l.address_space_mb) << 20);
    set_limit(RLIMIT_FSIZE, rlim_t(l.file_size_mb) << 20, rlim_t(l.file_size_mb) << 20);
    set_limit(RLIMIT_CORE, 0, 0);
    pin_to_cpu(spec.cpu);
    set_limit(RLIMIT_NPROC, rlim_t(l.processes), rlim_t(l.processes));
    if (uid != 0) {
        // Root ignores RLIMIT_NPROC, so untrusted code never runs as root.
        if (setgroups(0, nullptr) != 0 || setresgid(uid, uid, uid) != 0 ||
            setresuid(uid, uid, uid) != 0)
            _exit(125);
    }
    drop_capabilities();
    prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);  // setuid programs in /usr cannot give root back
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
    const std::string tmp = scratch.empty() ? "/tmp" : scratch.string();
    env.insert(env.end(), {"PATH=/usr/bin:/bin", "HOME=" + tmp, "TMPDIR=" + tmp});
    std::vector<char*> envp;
    for (auto& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);
    // Last, so nothing above needs more than the program will be allowed.
    if (!scratch.empty() && !apply_landlock(spec, scratch)) refuse_to_run("Landlock");
    if (!apply_seccomp()) refuse_to_run("seccomp");
    execve(argv[0], argv.data(), envp.data());
    _exit(127);
}

std::string read_capped(int fd, long long cap, bool& truncated) {
    std::string text(std::size_t(cap) + 1, '\0');
    std::size_t got = 0;
    while (got < text.size()) {
        const ssize_t n = pread(fd, text.data() + got, text.size() - got, off_t(got));
        if (n <= 0) break;
        got += std::size_t(n);
    }
    text.resize(got);
    if (text.size() > std::size_t(cap)) {
        text.resize(std::size_t(cap));
        truncated = true;
    }
    return text;
}

}  // namespace

namespace {
// Calls `visit` with the fields of /proc/PID/stat after the command name (from field 3, the
// state) of every process of `uid`.
template <class Visit>
void for_each_process_of(uid_t uid, Visit visit) {
    DIR* proc = opendir("/proc");
    if (!proc) return;
    while (const dirent* e = readdir(proc)) {
        if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
        struct stat st {};
        const std::string path = std::string("/proc/") + e->d_name;
        if (stat(path.c_str(), &st) != 0 || st.st_uid != uid) continue;
        std::ifstream stat_file(path + "/stat");
        std::string text;
        std::getline(stat_file, text);
        const auto close = text.rfind(')');
        visit(close != std::string::npos && close + 2 < text.size() ? text.substr(close + 2)
                                                                    : std::string());
    }
    closedir(proc);
}

}  // namespace

int count_processes_of(uid_t uid, bool zombies_too) {
    int count = 0;
    for_each_process_of(uid, [&](const std::string& fields) {
        // A zombie is dead already (killed, waiting for whoever adopted it to reap it).
        if (zombies_too || fields.empty() || fields[0] != 'Z') ++count;
    });
    return count;
}

double cpu_seconds_of(uid_t uid) {
    // Fields 14-17 of /proc/PID/stat: user and system time of the process and of the children
    // it has waited for. Zombies keep theirs until reaped, and the run's init reaps only the
    // program, at the very end: so the sum over the uid's processes is the run's CPU time.
    static const double tick = double(sysconf(_SC_CLK_TCK));
    double ticks = 0;
    for_each_process_of(uid, [&](const std::string& text) {
        std::istringstream fields(text);
        std::string field;
        for (int i = 3; i <= 17 && fields >> field; ++i)
            if (i >= 14) ticks += std::strtod(field.c_str(), nullptr);
    });
    return ticks / tick;
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
        case End::CpuLimit:
            std::snprintf(text, sizeof text, "CPU time limit hit (%d s, all its processes)",
                          limits.cpu_seconds);
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

namespace {

// What the forked side of a run needs.
struct RunContext {
    const RunSpec& spec;
    Isolation isolation;
    uid_t uid;
    int out_fd, err_fd, status_fd;
    const char* root_dir;  // the jail's mount point (nullptr: none)
    fs::path scratch;      // the program's private folder without a jail
};

// Outer child: a session of its own (so the kernel's autogroup scheduling shares the CPU fairly
// between concurrent runs, whatever one of them forks), namespaces, the jail; then an init
// process that runs the program and reports its wait status, so every descendant dies with it.
[[noreturn]] void run_outer_child(const RunContext& c) {
    if (setsid() < 0) setpgid(0, 0);
    // Only what this run needs stays open: a descriptor of another run (a judge's socket,
    // forked into this process by chance) would otherwise outlive that run's peer here.
    std::vector<int> keep{0, 1, 2, c.out_fd, c.err_fd, c.status_fd};
    for (const auto& [from, to] : c.spec.pass_fds) keep.push_back(from);
    close_all_but(keep);
    const bool jail = c.isolation == Isolation::Namespaces;
    if (jail && (!c.root_dir || !enter_namespaces() || !enter_jail(c.spec, c.root_dir))) _exit(124);
    const pid_t init = fork();
    if (init == 0) {
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        // Without a PID namespace, orphans (daemons) are adopted here rather than by the
        // machine's init, which may never reap them: reaped zombies do not pile up against the
        // uid's RLIMIT_NPROC.
        if (!jail) prctl(PR_SET_CHILD_SUBREAPER, 1);
        if (jail) mount("proc", "/proc", "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr);
        const pid_t program = fork();
        if (program == 0) {
            // File descriptors are dup2'ed without CLOEXEC inside exec_program.
            const int o = fcntl(c.out_fd, F_DUPFD, 10), e = fcntl(c.err_fd, F_DUPFD, 10);
            std::vector<std::pair<int, int>> passed;
            for (const auto& [from, to] : c.spec.pass_fds)
                passed.push_back({fcntl(from, F_DUPFD_CLOEXEC, 20), to});
            exec_program(c.spec, o, e, passed, c.uid, jail ? fs::path() : c.scratch);
        }
        int status = 0;
        while (waitpid(program, &status, 0) < 0 && errno == EINTR) {
        }
        if (write(c.status_fd, &status, sizeof status) != sizeof status) _exit(1);
        if (!jail && c.uid != 0) {
            // Kill what the program left running (as its uid: nothing else can be hit), then
            // reap every adopted orphan.
            if (setresgid(c.uid, c.uid, c.uid) == 0 && setresuid(c.uid, c.uid, c.uid) == 0)
                kill(-1, SIGKILL);
            while (waitpid(-1, nullptr, 0) > 0 || errno == EINTR) {
            }
        }
        _exit(0);  // as PID 1 of the namespace, this kills every leftover process
    }
    int status = 0;
    while (init > 0 && waitpid(init, &status, 0) < 0 && errno == EINTR) {
    }
    _exit(0);
}

// Without a jail, the program's temporary files (TMPDIR, HOME) go to a folder of its own,
// not to the host's /tmp: 0700, owned by the run's uid, removed after the run.
bool make_scratch(uid_t uid, fs::path& scratch) {
    char dir[] = "/tmp/rt-grade-tmp-XXXXXX";
    if (!mkdtemp(dir)) return false;
    scratch = dir;
    return uid == 0 || chown(dir, uid, uid) == 0;
}

struct Supervision {
    bool timed_out = false, cpu_exceeded = false;
    int outer_status = 0;
};

// RLIMIT_CPU bounds each process; the run as a whole (every process of its leased uid, a fork
// bomb's included) gets the same budget, checked here every tenth of a second.
Supervision supervise(pid_t outer, const RunSpec& spec, uid_t uid,
                      std::chrono::steady_clock::time_point start) {
    Supervision s;
    double next_cpu_check = 0.1;
    for (;;) {
        const pid_t done = waitpid(outer, &s.outer_status, WNOHANG);
        if (done == outer) break;
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (uid != 0 && elapsed >= next_cpu_check) {
            next_cpu_check = elapsed + 0.1;
            s.cpu_exceeded = cpu_seconds_of(uid) > spec.limits.cpu_seconds;
        }
        if (s.cpu_exceeded || elapsed > spec.limits.wall_seconds ||
            (spec.cancel && spec.cancel->load())) {
            s.timed_out = !s.cpu_exceeded;
            kill(-outer, SIGKILL);
            kill(outer, SIGKILL);
            waitpid(outer, &s.outer_status, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(elapsed < 1 ? 2 : 20));
    }
    return s;
}

// How the program ended, from the supervision and the status its init reported.
void set_end(RunResult& result, const Supervision& s, bool have_status, int status) {
    if (s.timed_out) {
        result.end = RunResult::End::TimedOut;
    } else if (s.cpu_exceeded) {
        result.end = RunResult::End::CpuLimit;
    } else if (!have_status) {
        result.end = RunResult::End::FailedToStart;
        if (WIFEXITED(s.outer_status) && WEXITSTATUS(s.outer_status) == 124)
            result.output = "sandbox setup failed\n";
    } else if (WIFEXITED(status)) {
        result.end = RunResult::End::Exited;
        result.exit_code = WEXITSTATUS(status);
        if (result.exit_code == 127) result.end = RunResult::End::FailedToStart;
    } else if (WIFSIGNALED(status)) {
        result.end = RunResult::End::Signaled;
        result.signal = WTERMSIG(status);
    }
}

// Appends the captured stdout then stderr to the result, within Limits::output_bytes.
void collect_output(RunResult& result, int out_fd, int err_fd, long long cap) {
    bool truncated = false;
    std::string out = read_capped(out_fd, cap, truncated);
    std::string err = read_capped(err_fd, cap, truncated);
    result.output += out;
    if (!err.empty()) {
        if (!out.empty() && out.back() != '\n') result.output.push_back('\n');
        result.output.append(err);
    }
    if (result.output.size() > std::size_t(cap)) {
        result.output.resize(std::size_t(cap));
        truncated = true;
    }
    result.output_truncated = truncated;
}

// Creates the unlinked capture files of stdout and stderr in the trusted-only capture folder
// (created exclusively, never followed).
bool open_captures(const fs::path& capture_dir, int& out_fd, int& err_fd) {
    std::error_code ec;
    fs::create_directories(capture_dir, ec);
    std::string out_t = (capture_dir / "stdout-XXXXXX").string();
    std::string err_t = (capture_dir / "stderr-XXXXXX").string();
    out_fd = mkostemp(out_t.data(), O_CLOEXEC);
    err_fd = mkostemp(err_t.data(), O_CLOEXEC);
    if (out_fd >= 0) unlink(out_t.c_str());
    if (err_fd >= 0) unlink(err_t.c_str());
    if (out_fd >= 0 && err_fd >= 0) return true;
    if (out_fd >= 0) close(out_fd);
    if (err_fd >= 0) close(err_fd);
    return false;
}

}  // namespace

RunResult run_sandboxed(const RunSpec& spec) {
    RunResult result;
    const Isolation isolation = probe_isolation();
    UidLease lease;
    if (getuid() == 0 && isolation != Isolation::None && !lease_uid(lease)) {
        result.output = "sandbox setup failed: no sandbox uid free\n";
        return result;
    }
    result.uid = lease.uid;
    // Writable binds belong to the run's uid (it is not root and must write there).
    for (const auto& b : spec.binds)
        if (b.writable && lease.uid != 0 && chown(b.host.c_str(), lease.uid, lease.uid) != 0) {
            result.output =
                "sandbox setup failed: cannot hand " + b.host.string() + " to the sandbox\n";
            return result;
        }
    RunContext c{spec, isolation, lease.uid, -1, -1, -1, nullptr, {}};
    int status_pipe[2];
    if (!open_captures(spec.capture_dir, c.out_fd, c.err_fd)) {
        result.output = "sandbox setup failed: cannot capture output\n";
        return result;
    }
    std::error_code ec;
    if (pipe2(status_pipe, O_CLOEXEC) != 0 ||
        (isolation != Isolation::Namespaces && !make_scratch(lease.uid, c.scratch))) {
        if (!c.scratch.empty()) fs::remove_all(c.scratch, ec);
        close(c.out_fd);
        close(c.err_fd);
        result.output = "sandbox setup failed: cannot make the run's folders\n";
        return result;
    }
    c.status_fd = status_pipe[1];
    char root_dir[] = "/tmp/rt-grade-root-XXXXXX";
    if (isolation == Isolation::Namespaces && mkdtemp(root_dir)) c.root_dir = root_dir;

    const auto start = std::chrono::steady_clock::now();
    const pid_t outer = fork();
    if (outer == 0) {
        close(status_pipe[0]);
        run_outer_child(c);
    }
    close(status_pipe[1]);
    Supervision s;
    if (outer > 0) {
        setpgid(outer, outer);  // also from the parent, against the race with the child's setpgid
        s = supervise(outer, spec, lease.uid, start);
        kill(-outer, SIGKILL);  // stragglers of the group (without a PID namespace)
    }
    if (lease.uid != 0) {
        reap_uid(lease.uid);
        result.survivors = count_processes_of(lease.uid);
    }
    result.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    int status = 0;
    const bool have_status = read(status_pipe[0], &status, sizeof status) == sizeof status;
    close(status_pipe[0]);
    if (c.root_dir) rmdir(root_dir);  // the jail's mounts lived in the child's namespace only
    // Only once nothing of the run's uid is left to race the removal (symlinks swapped in).
    if (!c.scratch.empty() && result.survivors == 0) fs::remove_all(c.scratch, ec);
    if (outer > 0) set_end(result, s, have_status, status);
    collect_output(result, c.out_fd, c.err_fd, spec.limits.output_bytes);
    close(c.out_fd);
    close(c.err_fd);
    return result;
}

}  // namespace rt::grader
