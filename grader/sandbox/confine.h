// Confinement of a sandboxed child without a jail (the container mode: root without
// CAP_SYS_ADMIN, as on Gradescope and in Docker), with what the kernel offers without privileges
// (docs/grading.md, "What the sandbox guarantees"):
//   - Landlock: the child reads only /usr, the loader's files of /etc, a few devices, /proc and
//     the RunSpec's read-only binds, executes only /usr and the binds that are files (its
//     binary), and writes only its writable binds and a private scratch folder;
//   - seccomp: no socket but AF_UNIX (no network), no namespaces (unshare, setns, clone with
//     namespace flags, clone3), no ptrace or process_vm_readv/writev, no io_uring (which opens
//     sockets without the socket call), no SysV or POSIX message IPC, no kernel keyrings (all of
//     which outlive the run in a container).
// Both are applied in the child just before exec, after the uid drop and no_new_privs. The
// seccomp filter also applies in the jail (defence in depth: honest code never makes those calls).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sandbox/sandbox.h"

namespace rt::grader {

// What the kernel (and this build: seccomp needs libseccomp) offers, probed once.
struct Confinement {
    int landlock_abi = 0;  // 0: no Landlock
    bool seccomp = false;
};
Confinement probe_confinement();

// In the child, just before exec (no_new_privs set). False when a supported mechanism could not
// be applied: the child must not run then. A mechanism the kernel lacks is skipped (the report
// says so).
bool apply_landlock(const RunSpec& spec, const std::filesystem::path& scratch);
bool apply_seccomp();

// In the outer child of a run: closes every descriptor but `keep`, so none of another run's (a
// judge's socket end, forked into this process by chance) outlives that run's peer here.
void close_all_but(std::vector<int> keep);

}  // namespace rt::grader
