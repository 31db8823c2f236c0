#include "gl/headless_context.h"

#include "gl/gl_context.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>

namespace rt {
namespace {

using GetStringFn = const GLubyte* (*)(GLenum);
using GetIntegervFn = void (*)(GLenum, GLint*);

void read_strings(GetStringFn get_string, GetIntegervFn get_integer, GlInfo& info) {
    auto str = [&](GLenum name) {
        const GLubyte* s = get_string(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    info.vendor = str(GL_VENDOR);
    info.renderer = str(GL_RENDERER);
    info.version = str(GL_VERSION);
    info.glsl_version = str(0x8B8C /* GL_SHADING_LANGUAGE_VERSION */);
    get_integer(0x821B /* GL_MAJOR_VERSION */, &info.major);
    get_integer(0x821C /* GL_MINOR_VERSION */, &info.minor);
    info.ok = true;
}

}  // namespace

// The GPU stage's own OSMesa context (gl_context.h), asked for its strings: one place that
// knows how to make an OSMesa core context.
GlInfo query_headless_gl() {
    GlInfo info;
    const auto context = GlContext::create(GlKind::OsMesa, info.error);
    if (!context) return info;
    const GlApi& gl = context->gl();
    read_strings(gl.GetString, gl.GetIntegerv, info);
    return info;
}

GlInfo query_window_gl() {
    GlInfo info;
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) {
        info.error = "no display: run under a desktop or `xvfb-run`, or use the headless context";
        return info;
    }
    if (!glfwInit()) {
        info.error = "glfwInit failed (is the display reachable?)";
        return info;
    }
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    GLFWwindow* window = glfwCreateWindow(64, 64, "rt gl-info", nullptr, nullptr);
    if (!window) {
        info.error = "GLFW could not create a GL 4.3 core window";
    } else {
        glfwMakeContextCurrent(window);
        read_strings(reinterpret_cast<GetStringFn>(glfwGetProcAddress("glGetString")),
                     reinterpret_cast<GetIntegervFn>(glfwGetProcAddress("glGetIntegerv")), info);
        glfwDestroyWindow(window);
    }
    glfwTerminate();
    return info;
}

}  // namespace rt
