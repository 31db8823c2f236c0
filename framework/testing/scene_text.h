// Scene-file tests without files: a scene from its text (the scene reader's tests) or from the
// body of a JSON object (stage 10's and stage 11's framework tests), and the error the loader
// gives for one.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include "render/prepare.h"
#include "scene/scene_loader.h"

namespace rt::testing {

// `text` parsed as the loader parses a file named test.json in `base_dir`.
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

// The prepared scene of the JSON object "{" + body + "}", read as "s.json".
inline PreparedScene scene_of(const std::string& body) {
    return prepare_scene(parse_scene("{" + body + "}", "s.json", "."));
}

// The message reading or preparing the scene of `body` gives, or "" when it renders.
inline std::string body_error_of(const std::string& body) {
    try {
        scene_of(body);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

// Each (body, expected) pair: the error contains `expected`, is one line and names a fix.
template <std::size_t N>
void expect_scene_errors(const std::pair<const char*, const char*> (&cases)[N]) {
    for (auto [body, expected] : cases) {
        const std::string message = body_error_of(body);
        EXPECT_NE(message.find(expected), std::string::npos)
            << body << "\n  gave: " << (message.empty() ? "(no error)" : message);
        EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
        EXPECT_NE(message.find("; "), std::string::npos) << "no fix named: " << message;
    }
}

}  // namespace rt::testing
