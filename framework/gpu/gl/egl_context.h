// A headless OpenGL 4.5 core context through EGL, with GL functions loaded by libepoxy. Works
// without a GPU or X (Mesa's llvmpipe on the surfaceless or device platform) and is what
// remains on Mesa 25.1+, which removed OSMesa. The GPU stage and the layout tests use it.
#pragma once

#include <string>

namespace rt {

class EglContext {
  public:
    // Creates the context and makes it current on this thread; ok() says whether it worked and
    // error() why not (one line naming what to install or set).
    EglContext();
    ~EglContext();
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    bool ok() const { return context_ != nullptr; }
    const std::string& error() const { return error_; }
    const std::string& platform() const { return platform_; }  // "surfaceless" or "device"
    // eglGetProcAddress: GL entry points of the current EGL context (GlContext loads them).
    static void* proc_address(const char* name);

  private:
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string error_, platform_;
};

}  // namespace rt
