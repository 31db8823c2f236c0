// The TextureSystem half of the OpenImageIO plug-in (oiio_plugin.h).
#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif
#include <Imath/ImathVec.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/texture.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "image/oiio_plugin.h"

struct RtOiioTextures {
    OIIO::TextureSystem* system = nullptr;
    std::filesystem::path directory;  // the mip-mapped files, ours alone
    std::vector<OIIO::TextureSystem::TextureHandle*> handles;
};

namespace {

void report(char* error, std::size_t size, const std::string& why) {
    std::snprintf(error, size, "%s", why.c_str());
}

// Writes a tiled, mip-mapped file of the image (a lat-long environment map when `latlong`) and
// opens it: its index, or -1 and `error`.
int add_image(RtOiioTextures* textures, const float* rgb, int width, int height, bool latlong,
              char* error, std::size_t error_size) {
    const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    const OIIO::ImageBuf image(spec, const_cast<float*>(rgb));  // wraps, never writes
    const std::string file =
        (textures->directory / ("texture" + std::to_string(textures->handles.size()) + ".tx"))
            .string();
    OIIO::ImageSpec config;
    config.format = OIIO::TypeDesc::FLOAT;  // linear values: no 8-bit rounding of the levels
    config.attribute("maketx:filtername", "box");
    const auto kind =
        latlong ? OIIO::ImageBufAlgo::MakeTxEnvLatl : OIIO::ImageBufAlgo::MakeTxTexture;
    if (!OIIO::ImageBufAlgo::make_texture(kind, image, file, config)) {
        report(error, error_size, "make_texture failed for " + file + ": " + OIIO::geterror());
        return -1;
    }
    OIIO::TextureSystem::TextureHandle* handle =
        textures->system->get_texture_handle(OIIO::ustring(file));
    if (!handle) {
        report(error, error_size, "the TextureSystem cannot open " + file);
        return -1;
    }
    textures->handles.push_back(handle);
    return int(textures->handles.size()) - 1;
}

}  // namespace

extern "C" RtOiioTextures* rt_oiio_textures_create(char* error, std::size_t error_size) {
    std::error_code ec;
    std::string pattern = (std::filesystem::temp_directory_path(ec) / "rt-oiio-XXXXXX").string();
    if (ec || !mkdtemp(pattern.data())) {
        report(error, error_size,
               "cannot create a temporary directory for mip-mapped textures " + pattern +
                   " (set TMPDIR to a writable directory)");
        return nullptr;
    }
    auto* textures = new RtOiioTextures;
    textures->directory = pattern;
    // Private, so its cache and statistics are this render's only.
    textures->system = OIIO::TextureSystem::create(false);
    return textures;
}

extern "C" void rt_oiio_textures_lookup(RtOiioTextures* textures, int index, int wrap,
                                        int anisotropic, float s, float t, float dsdx, float dtdx,
                                        float dsdy, float dtdy, float* rgb) {
    OIIO::TextureOpt options;
    const OIIO::TextureOpt::Wrap mode = wrap == 1   ? OIIO::TextureOpt::WrapClamp
                                        : wrap == 2 ? OIIO::TextureOpt::WrapMirror
                                                    : OIIO::TextureOpt::WrapPeriodic;
    options.swrap = options.twrap = mode;
    // Bilinear within a level, so a magnified texture matches the student's sample_bilinear.
    options.interpmode = OIIO::TextureOpt::InterpBilinear;
    options.mipmode =
        anisotropic > 0 ? OIIO::TextureOpt::MipModeAniso : OIIO::TextureOpt::MipModeTrilinear;
    options.anisotropic = anisotropic > 0 ? anisotropic : 1;
    rgb[0] = rgb[1] = rgb[2] = 0;
    if (index < 0 || std::size_t(index) >= textures->handles.size()) return;
    textures->system->texture(textures->handles[std::size_t(index)], nullptr, options, s, t, dsdx,
                              dtdx, dsdy, dtdy, 3, rgb);
}

extern "C" int rt_oiio_textures_add(RtOiioTextures* textures, const float* rgb, int width,
                                    int height, char* error, std::size_t error_size) {
    return add_image(textures, rgb, width, height, false, error, error_size);
}

extern "C" int rt_oiio_environment_add(RtOiioTextures* textures, const float* rgb, int width,
                                       int height, char* error, std::size_t error_size) {
    return add_image(textures, rgb, width, height, true, error, error_size);
}

extern "C" void rt_oiio_environment_lookup(RtOiioTextures* textures, int index, float x, float y,
                                           float z, float* rgb) {
    OIIO::TextureOpt options;
    options.interpmode = OIIO::TextureOpt::InterpBilinear;
    options.mipmode = OIIO::TextureOpt::MipModeOneLevel;  // the finest level: no footprint
    rgb[0] = rgb[1] = rgb[2] = 0;
    if (index < 0 || std::size_t(index) >= textures->handles.size()) return;
    const Imath::V3f zero(0, 0, 0);
    textures->system->environment(textures->handles[std::size_t(index)], nullptr, options,
                                  Imath::V3f(x, y, z), zero, zero, 3, rgb);
}

extern "C" void rt_oiio_textures_destroy(RtOiioTextures* textures) {
    if (!textures) return;
#if defined(__SANITIZE_ADDRESS__)
    // OpenImageIO 2.4's TextureSystem::destroy frees its object with another size than it was
    // allocated with (AddressSanitizer's new-delete-type-mismatch, inside OpenImageIO). Under the
    // sanitizers (the debug preset) the system is kept to the end of the process instead, as a
    // root of LeakSanitizer's search: one per scene with OpenImageIO textures.
    __lsan_ignore_object(textures->system);
#else
    OIIO::TextureSystem::destroy(textures->system, true);
#endif
    std::error_code ec;
    std::filesystem::remove_all(textures->directory, ec);
    delete textures;
}
