// The course tree this program was built from: scenes, reference images, handouts, shaders.
// (The grading workspace builds its own copy of the tree, so there it names the copy.)
#pragma once

#include <filesystem>

namespace rt {

// Absolute; set once, in framework/CMakeLists.txt (source_dir.cpp's RT_SOURCE_DIR). The
// environment variable RT_SOURCE_DIR names another copy of the tree: the grader sets it for a
// workspace packaged on one machine and unpacked on another (docs/grading.md).
const std::filesystem::path& source_dir();

}  // namespace rt
