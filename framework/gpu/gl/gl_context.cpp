#include "gpu/gl/gl_context.h"

#include <cstdlib>

#include "gpu/gl/egl_context.h"

namespace rt {
namespace {

class EglGlContext : public GlContext {
  public:
    EglGlContext() : GlContext(GlKind::Egl) {}
    EglContext egl;
};

}  // namespace

const char* to_string(GlKind kind) {
    switch (kind) {
        case GlKind::Egl:
            return "egl";
        case GlKind::OsMesa:
            return "osmesa";
        case GlKind::Window:
            return "window";
    }
    return "?";
}

std::optional<GlKind> parse_gl_kind(std::string_view name) {
    for (GlKind k : {GlKind::Egl, GlKind::OsMesa, GlKind::Window})
        if (name == to_string(k)) return k;
    return std::nullopt;
}

std::string GlContext::finish(GlProcLoader loader, std::string platform) {
    platform_ = std::move(platform);
    const std::string missing = gl_.load(loader);
    if (!missing.empty()) return std::string(to_string(kind_)) + ": the driver has no " + missing;
    limits_ = gl_.query_limits();
    if (limits_.major * 10 + limits_.minor < 43)
        return std::string(to_string(kind_)) + ": OpenGL " + limits_.version +
               " has no compute shaders (4.3+ needed; macOS stops at OpenGL 4.1, which has "
               "none: use --gl osmesa with Mesa, or a Linux machine)";
    if (limits_.compute_storage_blocks < 16)
        return std::string(to_string(kind_)) + ": only " +
               std::to_string(limits_.compute_storage_blocks) +
               " storage buffers in a compute shader; the scene needs 16 "
               "(shaders/scene_buffers.glsl)";
    return "";
}

std::string GlContext::describe() const {
    return std::string(to_string(kind_)) + (platform_.empty() ? "" : " (" + platform_ + ")") +
           ": " + limits_.describe();
}

std::unique_ptr<GlContext> GlContext::create(GlKind kind, std::string& error) {
    error.clear();
    if (kind == GlKind::OsMesa) return create_osmesa_context(error);
    if (kind == GlKind::Egl) {
        auto context = std::make_unique<EglGlContext>();
        if (!context->egl.ok()) {
            error = context->egl.error();
            return nullptr;
        }
        error = context->finish(&EglContext::proc_address, context->egl.platform());
        return error.empty() ? std::move(context) : nullptr;
    }
    return create_window_context(error);
}

}  // namespace rt
