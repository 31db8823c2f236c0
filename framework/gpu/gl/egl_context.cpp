#include "gpu/gl/egl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

namespace rt {
namespace {

// Mesa's surfaceless platform first (no device needed), then the first EGL device.
EGLDisplay open_display(std::string& platform) {
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY) {
            platform = "surfaceless";
            return d;
        }
    }
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") &&
        epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (eglQueryDevicesEXT(8, devices, &count) && count > 0) {
            EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
            if (d != EGL_NO_DISPLAY) {
                platform = "device";
                return d;
            }
        }
    }
    return EGL_NO_DISPLAY;
}

}  // namespace

EglContext::EglContext() {
    EGLDisplay display = open_display(platform_);
    if (display == EGL_NO_DISPLAY) {
        error_ =
            "EGL: no surfaceless or device platform (install libegl-mesa0, or run where a GPU "
            "driver is)";
        return;
    }
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        error_ = "EGL: eglInitialize failed on the " + platform_ + " platform";
        return;
    }
    display_ = display;
    if (!eglBindAPI(EGL_OPENGL_API)) {
        error_ = "EGL: this EGL has no desktop OpenGL (eglBindAPI(EGL_OPENGL_API) failed)";
        return;
    }
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!eglChooseConfig(display, config_attributes, &config, 1, &configs) || configs < 1)
        config = nullptr;
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         4,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         5,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
    if (context == EGL_NO_CONTEXT) {
        error_ = "EGL: no OpenGL 4.5 core context (compute shaders need 4.3+; macOS stops at 4.1)";
        return;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        error_ =
            "EGL: the context cannot be made current without a surface "
            "(EGL_KHR_surfaceless_context)";
        return;
    }
    context_ = context;
}

void* EglContext::proc_address(const char* name) {
    return reinterpret_cast<void*>(eglGetProcAddress(name));
}

EglContext::~EglContext() {
    if (!display_) return;
    const EGLDisplay display = static_cast<EGLDisplay>(display_);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
}

}  // namespace rt
