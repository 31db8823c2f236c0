// Landlock and seccomp for a sandboxed child without a jail (confine.h), applied in the child
// after fork and the uid drop, just before exec; and the probes of what the kernel permits
// (namespaces, Landlock, seccomp) with the report's text for each isolation (sandbox.h).
#include "sandbox/confine.h"
#include "sandbox/jail.h"

#include <fcntl.h>
#include <linux/landlock.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <mutex>

#ifdef RT_HAVE_SECCOMP
#include <sched.h>
#include <seccomp.h>
#include <sys/socket.h>
#endif

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

// Landlock's access rights (include/uapi/linux/landlock.h; Debian 12's headers stop at ABI 2, the
// values are the kernel's stable ABI).
constexpr std::uint64_t kExecute = 1ULL << 0, kWriteFile = 1ULL << 1, kReadFile = 1ULL << 2,
                        kReadDir = 1ULL << 3;
constexpr std::uint64_t kAbi1Fs = (1ULL << 13) - 1;  // execute ... make_sym
constexpr std::uint64_t kRefer = 1ULL << 13;         // ABI 2
constexpr std::uint64_t kTruncate = 1ULL << 14;      // ABI 3
constexpr std::uint64_t kIoctlDev = 1ULL << 15;      // ABI 5
// The only rights a rule on a file (not a folder) may carry.
constexpr std::uint64_t kFileRights = kExecute | kWriteFile | kReadFile | kTruncate | kIoctlDev;
constexpr std::uint64_t kNetBindTcp = 1ULL << 0, kNetConnectTcp = 1ULL << 1;       // ABI 4
constexpr std::uint64_t kScopeAbstractUnix = 1ULL << 0, kScopeSignal = 1ULL << 1;  // ABI 6

// struct landlock_ruleset_attr as of ABI 6; older kernels are given a shorter prefix of it.
struct RulesetAttr {
    std::uint64_t fs = 0, net = 0, scoped = 0;
};

// A Landlock ruleset that handles every right the kernel knows: what no rule allows is denied.
class Ruleset {
  public:
    explicit Ruleset(int abi) {
        RulesetAttr attr;
        attr.fs = kAbi1Fs | (abi >= 2 ? kRefer : 0) | (abi >= 3 ? kTruncate : 0) |
                  (abi >= 5 ? kIoctlDev : 0);
        handled_ = attr.fs;
        std::size_t size = sizeof attr.fs;
        if (abi >= 4) {  // TCP bind and connect, with no rule allowing any port
            attr.net = kNetBindTcp | kNetConnectTcp;
            size += sizeof attr.net;
        }
        if (abi >= 6) {  // abstract Unix sockets and signals stay within the run
            attr.scoped = kScopeAbstractUnix | kScopeSignal;
            size += sizeof attr.scoped;
        }
        fd_ = int(syscall(SYS_landlock_create_ruleset, &attr, size, 0));
    }
    Ruleset(const Ruleset&) = delete;
    Ruleset& operator=(const Ruleset&) = delete;
    ~Ruleset() {
        if (fd_ >= 0) close(fd_);
    }

    // Allows `access` beneath `path` (on it, for a file). A missing path fails only if required.
    void allow(const fs::path& path, std::uint64_t access, bool required) {
        const int fd = open(path.c_str(), O_PATH | O_CLOEXEC);
        if (fd < 0) {
            ok_ = ok_ && !required;
            return;
        }
        struct stat st {};
        if (fstat(fd, &st) != 0) ok_ = false;
        if (!S_ISDIR(st.st_mode)) access &= kFileRights;
        landlock_path_beneath_attr rule{access & handled_, fd};
        if (rule.allowed_access != 0 &&
            syscall(SYS_landlock_add_rule, fd_, LANDLOCK_RULE_PATH_BENEATH, &rule, 0) != 0)
            ok_ = false;
        close(fd);
    }

    bool restrict_self() const {
        return fd_ >= 0 && ok_ && syscall(SYS_landlock_restrict_self, fd_, 0) == 0;
    }

  private:
    int fd_ = -1;
    bool ok_ = true;
    std::uint64_t handled_ = 0;
};

// RT_GRADE_CONFINE=none|landlock|seccomp keeps only what it names (tests of the weaker modes).
bool wanted(const char* mechanism) {
    const char* keep = std::getenv("RT_GRADE_CONFINE");
    return keep == nullptr || std::string(keep).find(mechanism) != std::string::npos;
}

#ifdef RT_HAVE_SECCOMP
bool refuse(scmp_filter_ctx ctx, int call, int error) {
    return seccomp_rule_add(ctx, SCMP_ACT_ERRNO(error), call, 0) == 0;
}

bool add_seccomp_rules(scmp_filter_ctx ctx) {
    // Sockets: AF_UNIX only (socketpair, the verdict channel's kind): no network of any kind.
    bool ok = true;
    for (const int call : {SCMP_SYS(socket), SCMP_SYS(socketpair)})
        ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EAFNOSUPPORT), call, 1,
                                    SCMP_A0(SCMP_CMP_NE, AF_UNIX)) == 0;
    // Namespaces, other processes' memory, and state that outlives the run outside a jail.
    for (const int call :
         {SCMP_SYS(unshare), SCMP_SYS(setns), SCMP_SYS(ptrace), SCMP_SYS(process_vm_readv),
          SCMP_SYS(process_vm_writev), SCMP_SYS(pidfd_getfd), SCMP_SYS(shmget), SCMP_SYS(semget),
          SCMP_SYS(msgget), SCMP_SYS(mq_open), SCMP_SYS(add_key), SCMP_SYS(request_key),
          SCMP_SYS(keyctl)})
        ok = ok && refuse(ctx, call, EPERM);
    // clone3's flags are in memory a filter cannot read: ENOSYS makes glibc fall back to clone.
    // io_uring performs socket and file operations without their system calls.
    for (const int call : {SCMP_SYS(clone3), SCMP_SYS(io_uring_setup), SCMP_SYS(io_uring_enter),
                           SCMP_SYS(io_uring_register)})
        ok = ok && refuse(ctx, call, ENOSYS);
    // clone's flags are its first argument on x86-64 and arm64.
    for (const std::uint64_t flag : {CLONE_NEWNS, CLONE_NEWUTS, CLONE_NEWIPC, CLONE_NEWUSER,
                                     CLONE_NEWPID, CLONE_NEWNET, CLONE_NEWCGROUP})
        ok = ok && seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(clone), 1,
                                    SCMP_A0(SCMP_CMP_MASKED_EQ, flag, flag)) == 0;
    return ok;
}
#endif

// The isolation the kernel permits: a probe child tries to build an empty jail.
Isolation forced_or_probed() {
    if (const char* f = std::getenv("RT_GRADE_ISOLATION")) {
        const std::string s = f;
        if (s == "none") return Isolation::None;
        if (s == "uid") return getuid() == 0 ? Isolation::UidDrop : Isolation::None;
    }
    char dir[] = "/tmp/rt-grade-probe-XXXXXX";
    if (!mkdtemp(dir)) return getuid() == 0 ? Isolation::UidDrop : Isolation::None;
    const pid_t pid = fork();
    if (pid == 0) {
        RunSpec probe;
        probe.working_dir = "/";
        const bool ok = enter_namespaces() && enter_jail(probe, dir);
        _exit(ok ? 0 : 1);
    }
    int status = 0;
    const bool ok =
        pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    rmdir(dir);
    if (ok) return Isolation::Namespaces;
    return getuid() == 0 ? Isolation::UidDrop : Isolation::None;
}

// The child's Landlock domain (confine.h).
bool restrict_landlock(int abi, const RunSpec& spec, const fs::path& scratch) {
    Ruleset rules(abi);
    const std::uint64_t read = kReadFile | kReadDir, run = read | kExecute, all = ~0ULL;
    rules.allow("/usr", run, true);
    for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"})
        rules.allow(top, run, false);  // merged /usr: links into /usr, already allowed
    // /etc: only the loader's files (and the alternatives' links), as in the jail.
    for (const char* f :
         {"/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/alternatives"})
        rules.allow(f, read, false);
    for (const char* d : {"/dev/null", "/dev/zero", "/dev/full"})
        rules.allow(d, kReadFile | kWriteFile | kTruncate, true);
    for (const char* d : {"/dev/random", "/dev/urandom"}) rules.allow(d, kReadFile, true);
    // /proc/self (the C library and Mesa read it) cannot be named apart from the host's /proc;
    // the CPU count for the thread pools.
    rules.allow("/proc", read, false);
    rules.allow("/sys/devices/system/cpu", read, false);
    for (const auto& b : spec.binds) {
        std::error_code ec;
        const bool folder = fs::is_directory(b.host, ec);
        rules.allow(b.host, b.writable ? all : folder ? read : run, true);
    }
    if (!scratch.empty()) rules.allow(scratch, all, true);
    return rules.restrict_self();
}

#ifdef RT_HAVE_SECCOMP
bool load_seccomp() {
    const scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
    if (ctx == nullptr) return false;
    const bool ok = add_seccomp_rules(ctx) && seccomp_load(ctx) == 0;
    seccomp_release(ctx);
    return ok;
}
#endif

// Whether a mechanism the kernel announces really applies here (a container's own seccomp
// profile may refuse its calls): a child tries it. Otherwise every run would fail to start.
template <class Apply>
bool works_in_child(Apply apply) {
    const pid_t pid = fork();
    if (pid == 0) {
        prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);
        _exit(apply() ? 0 : 1);
    }
    int status = 0;
    return pid > 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
           WEXITSTATUS(status) == 0;
}

}  // namespace

Confinement probe_confinement() {
    static const Confinement found = [] {
        Confinement c;
        const long abi =
            syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
        if (abi > 0 && wanted("landlock") &&
            works_in_child([abi] { return restrict_landlock(int(abi), RunSpec(), {}); }))
            c.landlock_abi = int(abi);
#ifdef RT_HAVE_SECCOMP
        c.seccomp = wanted("seccomp") && prctl(PR_GET_SECCOMP) >= 0 && seccomp_api_get() >= 1 &&
                    works_in_child(load_seccomp);
#endif
        return c;
    }();
    return found;
}

bool apply_landlock(const RunSpec& spec, const fs::path& scratch) {
    const int abi = probe_confinement().landlock_abi;
    return abi == 0 || restrict_landlock(abi, spec, scratch);
}

bool apply_seccomp() {
#ifdef RT_HAVE_SECCOMP
    return !probe_confinement().seccomp || load_seccomp();
#else
    return true;
#endif
}

namespace {
// What confines a child without a jail, and which guarantee is lost where Landlock or seccomp
// is missing (or too old).
std::string describe_confinement() {
    const Confinement c = probe_confinement();
    std::string text;
    if (c.landlock_abi > 0) {
        text = "Landlock (ABI " + std::to_string(c.landlock_abi) +
               ") limits its files to /usr, its inputs, its output and a scratch folder";
        if (c.landlock_abi < 6) text += ", but not abstract Unix sockets or signals (ABI < 6)";
    } else {
        text =
            "no Landlock: host files are protected only by permissions (the host's /tmp, "
            "/var/tmp and /dev/shm are writable)";
    }
    if (c.seccomp)
        text += "; seccomp refuses network sockets, namespaces and ptrace";
    else if (c.landlock_abi >= 4)
        text +=
            "; no seccomp: TCP is blocked by Landlock, UDP (DNS) is not; ptrace of its own "
            "processes and SysV IPC are allowed";
    else
        text +=
            "; no seccomp: the network is reachable, ptrace of its own processes and SysV "
            "IPC are allowed";
    return text;
}
}  // namespace

std::string describe(Isolation isolation) {
    switch (isolation) {
        case Isolation::Namespaces:
            return "namespaces (a jail of its own: no network, no host files but the system's, "
                   "process tree contained)";
        case Isolation::UidDrop:
            return "uid drop to a sandbox uid (the kernel refused namespaces; " +
                   describe_confinement() + ")";
        case Isolation::None:
            return "NONE (not root and no user namespaces: resource limits; " +
                   describe_confinement() + ")";
    }
    return "?";
}

Isolation probe_isolation() {
    static std::once_flag once;
    static Isolation result = Isolation::None;
    std::call_once(once, [] {
        result = forced_or_probed();
        probe_confinement();  // here, not first in a child after fork
    });
    return result;
}

void close_all_but(std::vector<int> keep) {
    std::sort(keep.begin(), keep.end());
    unsigned from = 0;
    for (const int fd : keep) {
        if (fd < 0 || unsigned(fd) < from) continue;
        if (unsigned(fd) > from) close_range(from, unsigned(fd) - 1, 0);
        from = unsigned(fd) + 1;
    }
    close_range(from, ~0u, 0);
}

}  // namespace rt::grader
