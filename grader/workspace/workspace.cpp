#include "workspace/workspace.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <sstream>
#include <string_view>

#include "util.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt::grader {
std::string object_name(const std::string& key) {
    std::string name = key;
    std::replace(name.begin(), name.end(), '/', '_');
    return name;
}

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
    std::error_code ec;
    if (fs::is_directory(w.cache / "runtime" / "lib", ec)) w.runtime = w.cache / "runtime";
    return w;
}

bool is_packaged(const Workspace& w) {
    std::error_code ec;
    return fs::is_regular_file(w.cache / "package.json", ec);
}

void show_workspace(const Workspace& w, RunSpec& r, bool libraries) {
    r.binds.push_back({w.src, {}, false});
    r.env.push_back("RT_SOURCE_DIR=" + w.src.string());
    if (w.runtime.empty()) return;
    r.binds.push_back({w.runtime, {}, false});
    if (libraries) r.env.push_back("LD_LIBRARY_PATH=" + (w.runtime / "lib").string());
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

namespace {

// A packaged plan's commands name the cache as kCachePlaceholder (package/bundle.h): the
// package is unpacked wherever the platform puts it.
std::map<std::string, std::vector<std::string>> relocated(
    std::map<std::string, std::vector<std::string>> commands, const fs::path& cache) {
    for (auto& [name, argv] : commands)
        for (auto& arg : argv)
            for (std::size_t p; (p = arg.find(kCachePlaceholder)) != std::string::npos;)
                arg.replace(p, std::string_view(kCachePlaceholder).size(), cache.string());
    return commands;
}

}  // namespace

BuildPlan load_build_plan(const Workspace& w) {
    BuildPlan plan;
    const json j = json::parse(read_text(w.priv / "plan.json"));
    plan.compile = relocated(j.at("compile").get<decltype(plan.compile)>(), w.cache);
    plan.link = relocated(j.at("link").get<decltype(plan.link)>(), w.cache);
    plan.api = j.at("api").get<decltype(plan.api)>();
    plan.instructor_symbols = j.at("instructor_symbols").get<std::set<std::string>>();
    plan.shipped_hashes = j.at("shipped_hashes").get<std::set<std::string>>();
    plan.secret = read_text(w.priv / "secret");
    plan.solution_from_source = j.at("solution_from_source").get<std::set<std::string>>();
    std::error_code ec;
    plan.has_reference = fs::exists(w.priv / "bin" / "rt", ec);
    return plan;
}

fs::path trusted_dir(const fs::path& path) {
    std::error_code ec;
    fs::remove_all(path, ec);
    fs::create_directories(path);
    fs::permissions(path, fs::perms::owner_all);
    return path;
}

// Handed to the child's uid by the sandbox; its parents allow passing through (0711) but not
// listing, for the uid-drop mode without a jail.
fs::path child_dir(const fs::path& path) {
    return trusted_dir(path);
}

void strip_workspace_roots(const Workspace& w, const fs::path& scratch,
                           const std::map<int, fs::path>& glsl_dirs,
                           const std::vector<StageSpec>& graded, std::string& text) {
    // A GPU stage's graded GLSL is named as the student knows it: stages/NN-name/file.glsl.
    for (const auto& [number, dir] : glsl_dirs)
        for (const auto& s : graded) {
            if (s.number != number) continue;
            const std::string from = dir.string() + "/", to = s.folder + "/";
            for (std::size_t p = text.find(from); p != std::string::npos; p = text.find(from, p)) {
                text.replace(p, from.size(), to);
                p += to.size();
            }
        }
    for (const auto& root :
         {w.src.string() + "/", w.build.string() + "/", scratch.string() + "/"}) {
        std::size_t p;
        while ((p = text.find(root)) != std::string::npos) text.erase(p, root.size());
    }
}

WorkspaceLock::WorkspaceLock(const fs::path& cache) {
    fs::create_directories(cache);
    fd_ = open((cache / "workspace.lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd_ < 0)
        throw std::runtime_error("rt-grade: error: cannot open " +
                                 (cache / "workspace.lock").string() + ": " + std::strerror(errno));
}

WorkspaceLock::~WorkspaceLock() {
    close(fd_);
}

void WorkspaceLock::shared() {
    flock(fd_, LOCK_UN);
    flock(fd_, LOCK_SH);
}

void WorkspaceLock::exclusive() {
    flock(fd_, LOCK_UN);
    flock(fd_, LOCK_EX);
}

}  // namespace rt::grader
