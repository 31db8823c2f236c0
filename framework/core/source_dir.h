// The course tree this program was built from: scenes, reference images, handouts, shaders.
// (The grading workspace builds its own copy of the tree, so there it names the copy.)
#pragma once

#include <filesystem>

namespace rt {

// Absolute; set once, in framework/CMakeLists.txt (source_dir.cpp's RT_SOURCE_DIR).
const std::filesystem::path& source_dir();

}  // namespace rt
