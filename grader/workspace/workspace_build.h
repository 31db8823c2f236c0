// The grading-time steps on a prepared workspace (workspace.h, steps 1 and 3): a submitted file
// compiled in the jail, a graded stage's binaries linked; and the test binaries a preparation
// keeps (workspace_build.cpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "workspace/workspace.h"

namespace rt::grader {

// Compiles `text` as the student file `key` into `object`. Returns false with the compiler's
// output (workspace paths shortened) in `log`.
bool compile_in_jail(const Workspace& w, const BuildPlan& plan, const std::string& key,
                     const std::string& text, const std::filesystem::path& work,
                     const std::filesystem::path& object, std::string& log);

// Archives `objects` and links `targets` into `bin`. Returns false with the linker's output.
bool link_stage(const Workspace& w, const BuildPlan& plan,
                const std::vector<std::filesystem::path>& objects,
                const std::vector<std::string>& targets, const std::filesystem::path& bin,
                std::string& log);

// After the workspace build: each judge copied where children never look (every grading copies
// it), and each graded binary's expected test list, from the instructor's binary.
void keep_test_binaries(const Workspace& w, const std::vector<std::string>& targets);

}  // namespace rt::grader
