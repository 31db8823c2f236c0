// Runs one untrusted command (a student-linked test binary, renderer or compiler) in a child
// process with resource limits, and reports how it ended. Part of the trusted grader.
//
// Isolation, strongest first, chosen once per process (Sandbox::probe):
//   - namespaces: new mount, network and PID namespaces (a user namespace too when not root);
//     the paths in `hide` are covered by empty tmpfs mounts, so the child cannot read the
//     instructor's tree, the reference images or hidden tests; killing the namespace's init kills
//     every process the child started (fork bombs included);
//   - uid drop (root without namespaces, e.g. Docker's default seccomp): the child runs as
//     nobody, so RLIMIT_NPROC applies and 0700 grader directories are unreadable;
//   - none: limits only (reported as such).
#pragma once

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
    long long memory_mb = 512;  // RLIMIT_DATA: heap and anonymous memory
    long long file_size_mb = 16;  // also caps captured stdout/stderr
    int processes = 64;
    long long output_bytes = 64 * 1024;  // what is kept of stdout+stderr for the report
};

struct RunResult {
    enum class End { Exited, Signaled, TimedOut, FailedToStart } end = End::FailedToStart;
    int exit_code = -1;
    int signal = 0;
    double wall_seconds = 0;
    std::string output;        // stdout then stderr, truncated to Limits::output_bytes
    bool output_truncated = false;
    // "exited with code 3", "crashed: SIGSEGV", "timed out after 10 s", "file size limit hit"...
    std::string describe(const Limits& limits) const;
    bool ok() const { return end == End::Exited && exit_code == 0; }
};

struct RunSpec {
    std::vector<std::string> argv;
    std::filesystem::path working_dir;
    std::filesystem::path scratch_dir;  // writable by the child; stdout/stderr land here
    std::vector<std::filesystem::path> hide;  // covered by an empty tmpfs in the child
    // Directories that must stay visible (read-only) even if they lie under a hidden path.
    std::vector<std::filesystem::path> keep;
    bool keep_read_only = true;  // false for the compiler, which writes the build tree
    const std::atomic<bool>* cancel = nullptr;  // set: the child is killed as on a timeout
    std::vector<std::string> env;  // KEY=VALUE; the child gets only these (plus PATH, HOME)
    Limits limits;
    bool drop_uid = true;  // as root, run as nobody (false for the compiler: it writes the build)
    // Descriptors of the grader passed to the program: {grader fd, fd number in the program}.
    // Every other descriptor of the grader is close-on-exec. Targets must be 3 or more.
    std::vector<std::pair<int, int>> pass_fds;
};

enum class Isolation { Namespaces, UidDrop, None };
std::string describe(Isolation isolation);

// Finds out once which isolation the kernel permits (forks a probe child).
Isolation probe_isolation();

RunResult run_sandboxed(const RunSpec& spec);

}  // namespace rt::grader
