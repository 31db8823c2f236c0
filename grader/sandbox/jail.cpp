// The jail of a sandboxed child: fresh namespaces, an empty tmpfs root holding only what the
// run names (docs/grading.md, "What the sandbox guarantees"). Runs in the child, after fork.
#include "sandbox/jail.h"

#include <fcntl.h>
#include <sched.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

bool write_file(const char* path, const std::string& text) {
    const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) return false;
    const bool ok = write(fd, text.data(), text.size()) == ssize_t(text.size());
    close(fd);
    return ok;
}

// Creates `path` (and its parents) inside the jail root as a directory, or as an empty file
// when `file`.
bool make_mount_point(const fs::path& path, bool file) {
    std::error_code ec;
    fs::create_directories(file ? path.parent_path() : path, ec);
    if (!file) return fs::is_directory(path, ec);
    if (fs::exists(fs::symlink_status(path, ec)))
        return fs::is_regular_file(fs::symlink_status(path));
    const int fd = open(path.c_str(), O_CREAT | O_WRONLY | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) return false;
    close(fd);
    return true;
}

bool bind(const fs::path& host, const fs::path& target, bool writable, bool devices = false) {
    struct stat st {};
    if (stat(host.c_str(), &st) != 0) return false;
    if (!make_mount_point(target, !S_ISDIR(st.st_mode))) return false;
    if (mount(host.c_str(), target.c_str(), nullptr, MS_BIND | MS_REC, nullptr) != 0) return false;
    unsigned long flags = MS_BIND | MS_REMOUNT | MS_NOSUID;
    if (!devices) flags |= MS_NODEV;
    if (!writable) flags |= MS_RDONLY;
    return mount(nullptr, target.c_str(), nullptr, flags, nullptr) == 0;
}

bool tmpfs(const fs::path& target, const char* options, bool read_only = false) {
    if (!make_mount_point(target, false)) return false;
    unsigned long flags = MS_NOSUID | MS_NODEV;
    if (read_only) flags |= MS_RDONLY;
    return mount("tmpfs", target.c_str(), "tmpfs", flags, options) == 0;
}

// The host's system folders: /usr bound read-only; the merged-/usr links recreated.
bool add_system(const fs::path& root) {
    if (!bind("/usr", root / "usr", false)) return false;
    for (const char* top : {"bin", "sbin", "lib", "lib32", "lib64", "libx32"}) {
        const fs::path host = fs::path("/") / top;
        std::error_code ec;
        const auto st = fs::symlink_status(host, ec);
        if (ec || !fs::exists(st)) continue;
        if (fs::is_symlink(st)) {
            fs::create_symlink(fs::read_symlink(host, ec), root / top, ec);
        } else if (fs::is_directory(st) && !bind(host, root / top, false)) {
            return false;
        }
    }
    // /etc: only what the dynamic loader and the compiler driver need, and accounts of its own.
    std::error_code ec;
    fs::create_directories(root / "etc", ec);
    for (const char* f : {"ld.so.cache", "ld.so.conf", "ld.so.conf.d", "alternatives"})
        if (fs::exists(fs::path("/etc") / f, ec) &&
            !bind(fs::path("/etc") / f, root / "etc" / f, false))
            return false;
    const std::string passwd =
        "root:x:0:0:root:/:/usr/sbin/nologin\n"
        "nobody:x:65534:65534:nobody:/nonexistent:/usr/sbin/nologin\n";
    const std::string group = "root:x:0:\nnogroup:x:65534:\n";
    if (!write_file((root / "etc/passwd").c_str(), passwd) ||
        !write_file((root / "etc/group").c_str(), group))
        return false;
    // /dev: the harmless character devices, a private /dev/shm.
    fs::create_directories(root / "dev", ec);
    for (const char* d : {"null", "zero", "full", "random", "urandom"})
        if (!bind(fs::path("/dev") / d, root / "dev" / d, true, true)) return false;
    for (const auto& [name, to] : {std::pair{"fd", "/proc/self/fd"},
                                   {"stdin", "/proc/self/fd/0"},
                                   {"stdout", "/proc/self/fd/1"},
                                   {"stderr", "/proc/self/fd/2"}})
        fs::create_symlink(to, root / "dev" / name, ec);
    if (!tmpfs(root / "dev/shm", "size=64m,mode=1777")) return false;
    if (!tmpfs(root / "tmp", "size=512m,mode=1777")) return false;
    if (!tmpfs(root / "var/tmp", "size=64m,mode=1777")) return false;
    fs::create_directories(root / "proc", ec);
    return true;
}

}  // namespace

// In the child, after fork: enter new namespaces. Returns false when the kernel refuses.
bool enter_namespaces() {
    const uid_t uid = getuid();
    const gid_t gid = getgid();
    int flags = CLONE_NEWNS | CLONE_NEWNET | CLONE_NEWPID | CLONE_NEWIPC | CLONE_NEWUTS;
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

// Builds the jail in `root` (an empty host folder) and makes it the root of this mount namespace.
bool enter_jail(const RunSpec& spec, const fs::path& root) {
    if (mount("tmpfs", root.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "size=4m,mode=0755") != 0)
        return false;
    if (!add_system(root)) return false;
    for (const auto& b : spec.binds) {
        const fs::path inside = b.inside.empty() ? b.host : b.inside;
        if (!bind(b.host, root / inside.relative_path(), b.writable)) return false;
    }
    for (const auto& d : spec.empty_dirs) {
        std::error_code ec;
        if (!fs::is_directory(root / d.relative_path(), ec)) continue;
        if (!tmpfs(root / d.relative_path(), "size=4k,mode=0755", true)) return false;
    }
    std::error_code ec;
    fs::create_directories(root / spec.working_dir.relative_path(), ec);
    if (chdir(root.c_str()) != 0 || syscall(SYS_pivot_root, ".", ".") != 0) return false;
    if (umount2(".", MNT_DETACH) != 0 || chdir("/") != 0) return false;
    // The jail's own top level is read-only too (its tmpfs, /tmp etc. stay writable).
    return mount(nullptr, "/", nullptr, MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV, nullptr) ==
           0;
}

}  // namespace rt::grader
