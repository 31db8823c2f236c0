// Runs one untrusted command (a student-linked test binary, renderer or compiler) in a child
// process with resource limits, and reports how it ended. Part of the trusted grader.
//
// What the child can see, write, keep alive and share is bounded by construction, not by a
// list of known attacks (docs/grading.md, "What the sandbox guarantees"):
//   - see: a jail root built from scratch (new mount namespace, pivot_root): /usr and the
//     merged-/usr links, a few loader files of /etc, /dev/{null,zero,full,random,urandom}, a
//     fresh /proc of its own PID namespace, and exactly the `binds` of the RunSpec. Nothing else
//     of the host exists inside: no instructor tree, no other course copy, no /etc/shadow;
//   - write: its own empty /tmp, /var/tmp and /dev/shm (tmpfs, gone with it) and the binds
//     marked writable; everything else is read-only;
//   - keep alive: it is PID 1's child in a new PID namespace, and the namespace dies with it; a
//     reaper then kills whatever still runs under its uid (the only processes that could);
//   - share: it runs under a uid leased to this one run (distinct from every concurrent run),
//     so RLIMIT_NPROC and signals never reach another grading; in a session of its own, so the
//     kernel's autogroup scheduler shares the CPU between concurrent runs, not between their
//     processes; no network (new net namespace); only the descriptors of `pass_fds` are
//     inherited.
// Without namespaces (the kernel or a container forbids them: the container mode) the uid lease,
// the limits and the reaper remain, and Landlock and seccomp (confine.h) bound what the child
// reads, writes and reaches where the kernel offers them; the report says which guarantee is lost
// where one is missing. The seccomp filter applies in the jail too.
#pragma once

#include <sys/types.h>

#include <atomic>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace rt::grader {

struct Limits {
    double wall_seconds = 10;
    int cpu_seconds = 10;
    long long address_space_mb = 4096;
    long long memory_mb = 512;           // RLIMIT_DATA: heap and anonymous memory
    long long file_size_mb = 16;         // also caps captured stdout/stderr
    int processes = 16;                  // RLIMIT_NPROC of the run's own uid (threads count)
    long long output_bytes = 64 * 1024;  // what is kept of stdout+stderr for the report
};

struct RunResult {
    // CpuLimit: the run's processes together used more than Limits::cpu_seconds.
    enum class End { Exited, Signaled, TimedOut, CpuLimit, FailedToStart } end = End::FailedToStart;
    int exit_code = -1;
    int signal = 0;
    double wall_seconds = 0;
    std::string output;  // stdout then stderr, truncated to Limits::output_bytes
    bool output_truncated = false;
    int survivors = 0;  // processes of the run's uid still alive after the reaper
    uid_t uid = 0;      // the leased uid the program ran as (0: none, e.g. not root)
    // "exited with code 3", "crashed: SIGSEGV", "timed out after 10 s", "file size limit hit"...
    std::string describe(const Limits& limits) const;
    bool ok() const { return end == End::Exited && exit_code == 0; }
};

// A host path shown inside the jail at `inside` (the same path when empty).
struct Bind {
    std::filesystem::path host;
    std::filesystem::path inside;
    bool writable = false;  // writable binds are handed to the run's uid (chown) first
};

struct RunSpec {
    std::vector<std::string> argv;  // argv[0]: an absolute path inside the jail
    std::filesystem::path working_dir;
    std::filesystem::path capture_dir;  // trusted-only folder for stdout/stderr (never a bind)
    std::vector<Bind> binds;
    std::vector<std::filesystem::path> empty_dirs;  // inside binds: covered by an empty tmpfs
    const std::atomic<bool>* cancel = nullptr;      // set: the child is killed as on a timeout
    std::vector<std::string> env;  // KEY=VALUE; the child gets only these (plus PATH, HOME)
    Limits limits;
    // Descriptors of the grader passed to the program: {grader fd, fd number in the program}.
    // Every other descriptor of the grader is close-on-exec. Targets must be 3 or more.
    std::vector<std::pair<int, int>> pass_fds;
    int cpu = -1;  // >= 0: the program runs on this CPU only (cpu_lease.h)
};

enum class Isolation { Namespaces, UidDrop, None };
std::string describe(Isolation isolation);

// Finds out once which isolation the kernel permits (forks a probe child).
Isolation probe_isolation();

RunResult run_sandboxed(const RunSpec& spec);

// Processes currently running under `uid` (from /proc); zombies only when asked.
int count_processes_of(uid_t uid, bool zombies_too = false);

// CPU seconds (user and system) used by the processes of `uid`, zombies and the children they
// have waited for included: a run's CPU time, however many processes it made.
double cpu_seconds_of(uid_t uid);

}  // namespace rt::grader
