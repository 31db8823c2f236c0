// The window variant of GlContext: a hidden GLFW window's OpenGL 4.3 core context (rt view, and
// --gl window on a desktop). Left out of builds configured with RT_GL_WINDOW=OFF.
#include <GLFW/glfw3.h>

#include <cstdlib>

#include "gpu/gl/gl_context.h"

namespace rt {
namespace {

class WindowGlContext : public GlContext {
  public:
    WindowGlContext() : GlContext(GlKind::Window) {}
    ~WindowGlContext() override {
        if (window) glfwDestroyWindow(window);
        glfwTerminate();
    }
    GLFWwindow* window = nullptr;
};

void* glfw_loader(const char* name) {
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

}  // namespace

std::unique_ptr<GlContext> create_window_context(std::string& error) {
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) {
        error = "window: no display; run under a desktop or `xvfb-run`, or use --gl egl";
        return nullptr;
    }
    if (!glfwInit()) {
        error = "window: glfwInit failed (is the display reachable?)";
        return nullptr;
    }
    auto context = std::make_unique<WindowGlContext>();
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    context->window = glfwCreateWindow(64, 64, "rt", nullptr, nullptr);
    if (!context->window) {
        error =
            "window: no OpenGL 4.3 core context (compute shaders need 4.3+; macOS stops at "
            "OpenGL 4.1, which has none)";
        return nullptr;
    }
    glfwMakeContextCurrent(context->window);
    error = context->finish(&glfw_loader, "GLFW");
    if (!error.empty()) return nullptr;
    return context;
}

}  // namespace rt
