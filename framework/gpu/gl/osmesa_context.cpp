// The OSMesa variant of GlContext (Mesa's off-screen library: no EGL, no display). Mesa 25.1
// removed OSMesa; EGL is the default for that reason.
#include <GL/osmesa.h>

#include <vector>

#include "gpu/gl/gl_context.h"

namespace rt {
namespace {

class OsMesaGlContext : public GlContext {
  public:
    OsMesaGlContext() : GlContext(GlKind::OsMesa) {}
    ~OsMesaGlContext() override {
        if (context) OSMesaDestroyContext(context);
    }
    OSMesaContext context = nullptr;
    std::vector<unsigned char> buffer = std::vector<unsigned char>(4 * 4 * 4);
};

void* osmesa_loader(const char* name) {
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context(std::string& error) {
    auto c = std::make_unique<OsMesaGlContext>();
    for (int minor_version : {6, 5, 3}) {
        const int attributes[] = {OSMESA_FORMAT,
                                  OSMESA_RGBA,
                                  OSMESA_PROFILE,
                                  OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION,
                                  4,
                                  OSMESA_CONTEXT_MINOR_VERSION,
                                  minor_version,
                                  0};
        c->context = OSMesaCreateContextAttribs(attributes, nullptr);
        if (c->context) break;
    }
    if (!c->context) {
        error =
            "osmesa: no OpenGL 4.3+ core context (compute shaders need 4.3; is libosmesa6 "
            "installed? Mesa 25.1+ has no OSMesa: use --gl egl)";
        return nullptr;
    }
    if (!OSMesaMakeCurrent(c->context, c->buffer.data(), GL_UNSIGNED_BYTE, 4, 4)) {
        error = "osmesa: OSMesaMakeCurrent failed";
        return nullptr;
    }
    error = c->finish(&osmesa_loader, "");
    return error.empty() ? std::move(c) : nullptr;
}

}  // namespace rt
