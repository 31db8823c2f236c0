#include "gl/headless_context.h"

#define GL_GLEXT_PROTOTYPES 0
#include <GL/osmesa.h>
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <vector>

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

GlInfo query_headless_gl() {
    GlInfo info;
    OSMesaContext context = nullptr;
    for (int minor_version : {6, 5, 3}) {
        const int attributes[] = {OSMESA_FORMAT,
                                  OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS,
                                  24,
                                  OSMESA_PROFILE,
                                  OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION,
                                  4,
                                  OSMESA_CONTEXT_MINOR_VERSION,
                                  minor_version,
                                  0};
        context = OSMesaCreateContextAttribs(attributes, nullptr);
        if (context) break;
    }
    if (!context) {
        info.error =
            "OSMesa could not create a GL 4.3+ core context; install libosmesa6 "
            "(Mesa's llvmpipe) or set LIBGL_ALWAYS_SOFTWARE=1";
        return info;
    }
    constexpr int kSize = 16;
    std::vector<unsigned char> buffer(kSize * kSize * 4);
    if (!OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
        info.error = "OSMesaMakeCurrent failed";
    } else {
        auto get_string = reinterpret_cast<GetStringFn>(OSMesaGetProcAddress("glGetString"));
        auto get_integer = reinterpret_cast<GetIntegervFn>(OSMesaGetProcAddress("glGetIntegerv"));
        if (get_string && get_integer)
            read_strings(get_string, get_integer, info);
        else
            info.error = "OSMesa has no glGetString";
    }
    OSMesaDestroyContext(context);
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
