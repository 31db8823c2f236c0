// `rt-bench view`: how quickly the lecture viewer (framework/view/) answers a camera change,
// measured on its own progressive renderer without a window: from the change to the first
// coarse frame on screen, and to the full-resolution frame.
#pragma once

#include <filesystem>
#include <ostream>

namespace rt::bench {

struct ViewLatencyConfig {
    std::filesystem::path scene;  // default: stages/05-recursion/scenes/whitted.json
    int width = 640, height = 480;
    int threads = 2;
    int changes = 20;  // camera changes (orbits of 3 degrees), each timed
    bool gpu = false;  // the viewer's GPU path (stage 09's shader on a headless context)
};

// Prints the figures as a Markdown table; returns false (with a line on `out`) when the scene
// cannot be loaded or the renderer reports an error.
bool run_view_latency(const ViewLatencyConfig& config, std::ostream& out);

}  // namespace rt::bench
