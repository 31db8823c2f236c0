// Reading scene files (docs/scene-format.md).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace rt {

// A mistake in a scene file. what() is one line in the compiler's shape:
//   scenes/x.json:12:17: error: "radius" must be > 0, got -1 (hint: ...)
class SceneError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Loads and validates a scene. Throws SceneError on any mistake; never crashes on bad input.
Scene load_scene(const std::filesystem::path& file);

// The same from text already in memory; `name` is used in messages and relative mesh paths are
// resolved against `base_dir`.
Scene parse_scene(const std::string& text, const std::string& name,
                  const std::filesystem::path& base_dir);

// The text of a scene file, with load_scene's checks and messages for the file itself (missing,
// a directory, unreadable, larger than 64 MiB). Throws SceneError.
std::string read_scene_text(const std::filesystem::path& file);

}  // namespace rt
