// OpenGL contexts for the GPU stage: headless through OSMesa (CI, graders, machines without a
// GPU) and windowed through GLFW (lectures). Stage 09 renders through these; for now they are
// created and queried (`rt gl-info`).
#pragma once

#include <string>

namespace rt {

struct GlInfo {
    bool ok = false;
    std::string error;  // why no context could be made, and what to install or set
    std::string vendor, renderer, version, glsl_version;
    int major = 0, minor = 0;
};

// Creates an off-screen OSMesa context (core profile, the newest of 4.6 / 4.5 / 4.3),
// makes it current on a small buffer, reads the strings and destroys it.
GlInfo query_headless_gl();

// Opens a hidden GLFW window with a 4.3+ core context and reads the same strings. Needs a
// display (a desktop, or Xvfb); returns ok = false with the reason otherwise.
GlInfo query_window_gl();

}  // namespace rt
