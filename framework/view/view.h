// `rt view SCENE [--script FILE --out DIR]`: the lecture-demo viewer. A window with the
// progressively refined CPU render, a panel of settings that change what the renderer computes,
// orbit/pan/zoom, and the ray tree of a clicked pixel. docs/viewer.md describes its use.
#pragma once

#include <filesystem>
#include <string>

namespace rt::view {

struct ViewArgs {
    std::string scene;
    std::string script;               // "" for a person at the window
    std::filesystem::path out = ".";  // screenshots and saved renders
    int threads = 0;                  // 0: all cores
    int width = 0, height = 0;        // > 0: override the scene's image size (a lecture's)
};

// Opens the window and runs until it is closed or the script ends; the exit code.
// Throws std::runtime_error with one line for a bad scene, script or missing display.
int run_view(const ViewArgs& args);

}  // namespace rt::view
