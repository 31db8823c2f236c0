// Image textures through OpenImageIO's TextureSystem (`rt render --texture-filter oiio` and
// `oiio-aniso`): mip-mapped, filtered over the pixel's footprint in texture space, a reference
// for the student's nearest and bilinear lookups. OpenImageIO lives in the dlopen'd plug-in
// (image/oiio_plugin.h), loaded only when a render asks for this.
#pragma once

#include <memory>
#include <vector>

#include "scene/prepared_scene.h"

struct RtOiioTextures;

namespace rt {

namespace image_files {
struct OiioPlugin;
}

// How texture coordinates change from a pixel to its right (dx) and lower (dy) neighbour, in
// the units of the slot's uv (before its scale). Zero: no footprint (bilinear in the finest level).
struct TexcoordDerivatives {
    Vec2 dx{0};
    Vec2 dy{0};
};

class OiioTextures {
  public:
    // Mip-maps every image texture of `scene` (sRGB ones decoded to linear first, since averaging
    // encoded values darkens edges). Throws std::runtime_error, one line, when the plug-in is
    // missing or OpenImageIO fails.
    OiioTextures(const PreparedScene& scene, bool anisotropic);
    ~OiioTextures();
    OiioTextures(const OiioTextures&) = delete;
    OiioTextures& operator=(const OiioTextures&) = delete;

    // Linear colour of scene.textures[texture] (an image texture) at `uv` (after the slot's
    // scale and offset) over the footprint `d` (scaled likewise).
    Color lookup(std::size_t texture, Vec2 uv, const TexcoordDerivatives& d) const;

  private:
    const image_files::OiioPlugin* plugin_ = nullptr;
    RtOiioTextures* system_ = nullptr;
    std::vector<int> index_;  // per scene texture: its TextureSystem image, -1 if not an image
    std::vector<int> wrap_;   // per scene texture: the plug-in's wrap code
    int anisotropic_ = 0;     // 0: trilinear; else the largest anisotropy
};

// Sets scene.texture_lookup to Oiio (or OiioAniso) and builds scene.oiio_textures. Throws
// std::runtime_error naming --texture-filter when the plug-in cannot be loaded.
void use_oiio_textures(PreparedScene& scene, bool anisotropic);

}  // namespace rt
