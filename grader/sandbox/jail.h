// The jail a sandboxed child enters (jail.cpp). Both run in the child, after fork, before exec.
#pragma once

#include <filesystem>

#include "sandbox/sandbox.h"

namespace rt::grader {

// New user (when not root), mount, PID, IPC, UTS and network namespaces. False when the kernel
// refuses (the caller falls back to a weaker isolation, docs/grading.md).
bool enter_namespaces();

// Builds the jail in `root` (an empty host folder) from `spec`'s binds and makes it the root of
// this mount namespace.
bool enter_jail(const RunSpec& spec, const std::filesystem::path& root);

}  // namespace rt::grader
