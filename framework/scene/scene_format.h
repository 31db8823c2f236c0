// The canonical text of a scene file (docs/scene-format.md#canonical-form), which `rt fmt`
// writes and `rt fmt --check` (a CTest test over stages/*/scenes) enforces.
#pragma once

#include <filesystem>
#include <string>

namespace rt {

// The scene `text` in canonical form: top-level sections in a fixed order, one per line; every
// material, surface and light on one line; keys in a fixed order; numbers as integers or the
// shortest text that reads back as the same double. The scene is first read with parse_scene
// (`name` and `base_dir` as there), so anything the loader refuses throws its SceneError; the
// result is checked to hold exactly the same values as `text` (and throws SceneError if not).
std::string canonical_scene_text(const std::string& text, const std::string& name,
                                 const std::filesystem::path& base_dir);

// A number as the canonical form writes it: `integer` text for JSON integers, otherwise the
// shortest decimal that reads back as `value` ("0.1", "-1.5999999999999996", "1e-07"; -0 as
// "-0.0", so it does not read back as the integer 0).
std::string canonical_number(double value);

}  // namespace rt
