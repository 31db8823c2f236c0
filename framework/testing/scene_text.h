// Scene-file tests without files: a scene from the body of a JSON object, and the error the
// loader gives for one, checked to be one line that names the place and a fix (stage 10's and
// stage 11's framework tests).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "render/prepare.h"
#include "scene/scene_loader.h"

namespace rt::testing {

// The prepared scene of the JSON object "{" + body + "}", read as "s.json".
inline PreparedScene scene_of(const std::string& body) {
    return prepare_scene(parse_scene("{" + body + "}", "s.json", "."));
}

// The loader's message for `body`, or "(no error)".
inline std::string error_of(const std::string& body) {
    try {
        scene_of(body);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

// Each (body, expected) pair: the error contains `expected`, is one line and names a fix.
template <std::size_t N>
void expect_scene_errors(const std::pair<const char*, const char*> (&cases)[N]) {
    for (auto [body, expected] : cases) {
        const std::string message = error_of(body);
        EXPECT_NE(message.find(expected), std::string::npos) << body << "\n  gave: " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
        EXPECT_NE(message.find("; "), std::string::npos) << "no fix named: " << message;
    }
}

}  // namespace rt::testing
