// The window variant of GlContext in a build without GLFW (RT_GL_WINDOW=OFF: the grading
// workspace, whose programs never open a window).
#include "gpu/gl/gl_context.h"

namespace rt {

std::unique_ptr<GlContext> create_window_context(std::string& error) {
    error =
        "window: this build has no windowed OpenGL (configured with RT_GL_WINDOW=OFF, as the "
        "grading workspace is); use --gl egl or --gl osmesa";
    return nullptr;
}

}  // namespace rt
