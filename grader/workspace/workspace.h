// The grading workspace: the instructor's tree built once per change (trusted), and what a
// grading needs from it to turn untrusted student files into test binaries without ever
// compiling them outside the sandbox or linking them into trusted code.
//
//   CACHE/workspace/src     the tree without reference_images/, every student file a stub
//   CACHE/workspace/build   its build (framework, tests, hidden tests, all with stubs)
//   CACHE/private/          0700: references, pristine files, objects, commands, secrets
//
// A grading then (docs/grading.md, "How a submission is built"; workspace_build.h and
// object_check.h):
//   1. compiles each student file in the jail (`compile_in_jail`): a non-root sandbox uid that
//      sees the public framework and stage folders and writes one object file;
//   2. checks the object and keeps only the stage's API global (`check_and_localize`), so
//      nothing else it defines can replace or interpose a symbol of the framework, the tests
//      or a library;
//   3. links per graded stage (`link_stage`) an archive of solution objects for the stages
//      before it, the student's for it and stubs after it, exactly as when graded alone.
#pragma once

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "course/manifest.h"
#include "grading/grade.h"
#include "image/image.h"
#include "sandbox/sandbox.h"

namespace rt::grader {

struct Workspace {
    std::filesystem::path cache, root, src, build, priv;
    // A packaged workspace's runtime (package/bundle.h): lib/, the shared libraries the grading
    // machine lacks, and include/, the headers student files reach; empty when not packaged.
    std::filesystem::path runtime;
};

// How a packaged plan names the cache folder, which is wherever the package was unpacked.
inline constexpr const char* kCachePlaceholder = "@CACHE@";

// True for a workspace written by `rt-grade package`: complete, and never rebuilt (the grading
// machine has no build tools for the framework).
bool is_packaged(const Workspace& w);
Workspace workspace_paths(const GradeOptions& options);

// The workspace's lock (CACHE/workspace.lock): gradings hold it shared while they read the
// workspace, a preparation exclusively while it rebuilds. Released when it goes out of scope.
// Throws std::runtime_error when the lock file cannot be opened.
class WorkspaceLock {
  public:
    explicit WorkspaceLock(const std::filesystem::path& cache);
    ~WorkspaceLock();
    WorkspaceLock(const WorkspaceLock&) = delete;
    WorkspaceLock& operator=(const WorkspaceLock&) = delete;
    void shared();     // waits for a preparation to finish
    void exclusive();  // waits for every grading to finish

  private:
    int fd_ = -1;
};

// What prepare saved: commands with @OUT@ (and @STAGES@ for the stage archive).
struct BuildPlan {
    std::map<std::string, std::vector<std::string>> compile;  // "stages/NN/f.cpp" -> argv
    std::map<std::string, std::vector<std::string>> link;     // target -> argv (cwd: build)
    std::map<std::string, std::set<std::string>> api;         // "stages/NN/f.cpp" -> symbols
    std::set<std::string> instructor_symbols;                 // strong, framework and tests
    std::set<std::string> shipped_hashes;                     // 8-bit pixels of every reference
    std::string secret;                                       // per workspace, never shipped
    // Student files without solutions (a starter tree): their "solution" is the tree's current
    // text, compiled per grading; then there is no reference renderer either.
    std::set<std::string> solution_from_source;
    bool has_reference = false;
};
BuildPlan load_build_plan(const Workspace& w);

// What every child of a grading sees of the workspace: the public tree, read-only, named to the
// framework by RT_SOURCE_DIR (a packaged tree was built elsewhere, core/source_dir.h), and a
// packaged workspace's runtime: its headers, and with `libraries` its shared libraries found
// through LD_LIBRARY_PATH (not for the compiler, which runs on the machine's own). Appends to r.
void show_workspace(const Workspace& w, RunSpec& r, bool libraries = true);

// Folders of the workspace tree a child never sees (covered by an empty tmpfs in the jail).
std::vector<std::filesystem::path> hidden_dirs(const Workspace& w);

// The name of student file `key`'s objects in the private folder.
std::string object_name(const std::string& key);

// Pristine objects of every student file, compiled at prepare time.
std::filesystem::path solution_object(const Workspace& w, const std::string& key);
std::filesystem::path stub_object(const Workspace& w, const std::string& key);

// Hash of an 8-bit image's size and pixels (for "is this a shipped reference?").
std::string pixel_hash(const Image8& image);

// Folders for children's runs, in a grading's scratch folder.
std::filesystem::path trusted_dir(const std::filesystem::path& path);  // 0700, fresh
std::filesystem::path child_dir(const std::filesystem::path& path);    // handed to the child
// Workspace paths in `text` read as the student's tree: stages/..., framework/... `scratch` is
// the grading's folder; `glsl_dirs` (a GPU stage -> the folder of its graded GLSL) read as the
// folders of the `graded` stages.
void strip_workspace_roots(const Workspace& w, const std::filesystem::path& scratch,
                           const std::map<int, std::filesystem::path>& glsl_dirs,
                           const std::vector<StageSpec>& graded, std::string& text);

}  // namespace rt::grader
