// One interface over the OpenGL contexts the GPU stage renders through: headless EGL (Mesa's
// surfaceless or device platform, the default), headless OSMesa, or a GLFW window. Whichever it
// is, the renderer sees a current GL 4.3+ core context and the functions of GlApi.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "gpu/gl/gl_api.h"

namespace rt {

enum class GlKind { Egl, OsMesa, Window };

const char* to_string(GlKind kind);                     // "egl", "osmesa", "window"
std::optional<GlKind> parse_gl_kind(std::string_view);  // the inverse

class GlContext {
  public:
    // A current context of `kind` with compute shaders, or null with `error` set to one line
    // that says what is missing and what to do.
    static std::unique_ptr<GlContext> create(GlKind kind, std::string& error);
    virtual ~GlContext() = default;

    GlKind kind() const { return kind_; }
    const GlApi& gl() const { return gl_; }
    const GlLimits& limits() const { return limits_; }
    // e.g. "egl (surfaceless): llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5, ..."
    std::string describe() const;

    // For the variants, once their context is current: loads the functions and checks for
    // compute; "" when the context is usable.
    std::string finish(GlProcLoader loader, std::string platform);

  protected:
    explicit GlContext(GlKind kind) : kind_(kind) {}

  private:
    GlKind kind_;
    GlApi gl_;
    GlLimits limits_;
    std::string platform_;
};

// The OSMesa variant (its own file: osmesa.h and glcorearb.h do not mix).
std::unique_ptr<GlContext> create_osmesa_context(std::string& error);

// The window variant (GLFW), in window_context.cpp; a build configured with RT_GL_WINDOW=OFF
// (the grading workspace, which needs no display) has no_window_context.cpp instead, which says so.
std::unique_ptr<GlContext> create_window_context(std::string& error);

}  // namespace rt
