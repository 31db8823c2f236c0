// The OSMesa variant of GlContext (Mesa's off-screen library: no EGL, no display). Mesa 25.1
// removed OSMesa; EGL is the default for that reason.
//
// libOSMesa is opened when a context is first asked for, not linked: it pulls in Mesa's LLVM
// (libLLVM, libz3, ICU, ...), and loading those cost every `rt` run about 20 ms of start-up,
// CPU renders included (docs/performance.md).
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <vector>

#include "gpu/gl/gl_context.h"

namespace rt {
namespace {

// The four entry points this file uses, from the library opened once per process.
struct OsMesaApi {
    decltype(&OSMesaCreateContextAttribs) create = nullptr;
    decltype(&OSMesaMakeCurrent) make_current = nullptr;
    decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
    decltype(&OSMesaDestroyContext) destroy = nullptr;
    std::string error;  // why the library could not be used
};

template <class F>
void resolve(void* library, const char* name, F& function, std::string& error) {
    function = reinterpret_cast<F>(dlsym(library, name));
    if (!function && error.empty()) error = std::string("osmesa: libOSMesa has no ") + name;
}

const OsMesaApi& osmesa() {
    static const OsMesaApi api = [] {
        OsMesaApi a;
        void* library = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
        if (!library) library = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
        if (!library) {
            a.error =
                "osmesa: cannot load libOSMesa.so.8 (install libosmesa6: "
                "scripts/install-deps.sh; or use --gl egl)";
            return a;
        }
        resolve(library, "OSMesaCreateContextAttribs", a.create, a.error);
        resolve(library, "OSMesaMakeCurrent", a.make_current, a.error);
        resolve(library, "OSMesaGetProcAddress", a.get_proc_address, a.error);
        resolve(library, "OSMesaDestroyContext", a.destroy, a.error);
        return a;  // the library stays open: contexts and GL functions live in it
    }();
    return api;
}

class OsMesaGlContext : public GlContext {
  public:
    OsMesaGlContext() : GlContext(GlKind::OsMesa) {}
    ~OsMesaGlContext() override {
        if (context) osmesa().destroy(context);
    }
    OSMesaContext context = nullptr;
    std::vector<unsigned char> buffer = std::vector<unsigned char>(4 * 4 * 4);
};

void* osmesa_loader(const char* name) {
    return reinterpret_cast<void*>(osmesa().get_proc_address(name));
}

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context(std::string& error) {
    const OsMesaApi& api = osmesa();
    if (!api.error.empty()) {
        error = api.error;
        return nullptr;
    }
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
        c->context = api.create(attributes, nullptr);
        if (c->context) break;
    }
    if (!c->context) {
        error =
            "osmesa: no OpenGL 4.3+ core context (compute shaders need 4.3; is libosmesa6 "
            "installed? Mesa 25.1+ has no OSMesa: use --gl egl)";
        return nullptr;
    }
    if (!api.make_current(c->context, c->buffer.data(), GL_UNSIGNED_BYTE, 4, 4)) {
        error = "osmesa: OSMesaMakeCurrent failed";
        return nullptr;
    }
    error = c->finish(&osmesa_loader, "");
    return error.empty() ? std::move(c) : nullptr;
}

}  // namespace rt
