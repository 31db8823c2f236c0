// The grading bundle: a prepared workspace (workspace/workspace.h) made to run on a machine that
// has only a compiler, Mesa and the packages of target_packages.txt (docs/grading.md, "The
// grading bundle"). Everything trusted is built here, on the instructor's Debian machine:
//
//   BUNDLE/bin/rt-grade                  finds its libraries through its RUNPATH
//   BUNDLE/cache/workspace/src/          the public tree: framework headers, stages, shaders
//   BUNDLE/cache/workspace/src/build/    only what the link commands read (objects, archives)
//   BUNDLE/cache/private/                judges, pristine objects, references, the plan
//   BUNDLE/cache/runtime/lib/            shared and static libraries the target lacks
//   BUNDLE/cache/runtime/include/        third-party headers a student file may include
//   BUNDLE/cache/package.json            what was packaged; marks the workspace as complete
//
// Only the student's files are compiled on the target, by the plan's commands, which name the
// cache as kCachePlaceholder and the compiler as /usr/bin/g++-12.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "workspace/workspace.h"

namespace rt::grader {

// One line of target_packages.txt: a package the grading machine installs by this name.
struct TargetPackage {
    std::string name;
    bool gpu_only = false;             // needed only when a GPU stage is graded
    std::vector<std::string> sonames;  // libraries a shipped binary may take from it
};
// Reads SOURCE/grader/package/target_packages.txt; throws with the file and line on bad input.
std::vector<TargetPackage> read_target_packages(const std::filesystem::path& source);

struct BundleRequest {
    std::filesystem::path source;         // the instructor's tree
    Workspace workspace;                  // prepared from it
    std::filesystem::path rt_grade;       // this program
    std::filesystem::path out;            // BUNDLE (created)
    std::vector<TargetPackage> packages;  // target_packages.txt
};

// Throws, naming the program and its Debian package, when a program that packaging runs is not
// on PATH (patchelf, readelf, nm, ldd, dpkg, zip, tar): before minutes of workspace are spent.
void require_packaging_tools();

// Writes the bundle, saying what it ships in `log`; false (and why, in `err`) when a step fails.
bool write_bundle(const BundleRequest& request, std::ostream& log, std::ostream& err);

// Runs grader/package/audit_bundle.sh on a bundle: true when it passes. Its findings go to `log`.
bool audit_bundle(const std::filesystem::path& source, const std::filesystem::path& bundle,
                  std::ostream& log);

}  // namespace rt::grader
