// Scene text parsed as the loader parses a file, for the scene reader's tests.
#pragma once

#include <filesystem>
#include <string>

#include "scene/scene_loader.h"

namespace rt::testing {

inline Scene parse(const std::string& text, const std::filesystem::path& base_dir = {}) {
    return parse_scene(text, "test.json", base_dir);
}

// The SceneError message parsing `text` gives, or "" when it parses.
inline std::string error_of(const std::string& text, const std::filesystem::path& base_dir = {}) {
    try {
        parse(text, base_dir);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace rt::testing
