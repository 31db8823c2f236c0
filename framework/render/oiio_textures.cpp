#include "render/oiio_textures.h"

#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/diagnostics.h"
#include "image/image.h"
#include "image/oiio_loader.h"

namespace rt {
namespace {

// Larger ratios cost more lookups per pixel for little change on the course's scenes.
constexpr int kMaxAnisotropy = 16;

std::runtime_error failure(const std::string& why) {
    return std::runtime_error(one_line("--texture-filter oiio: " + why));
}

}  // namespace

OiioTextures::OiioTextures(const PreparedScene& scene, bool anisotropic)
    : anisotropic_(anisotropic ? kMaxAnisotropy : 0) {
    const image_files::OiioPlugin& plugin = image_files::oiio_plugin();
    if (!plugin.textures_create) throw failure("needs " + plugin.problem);
    plugin_ = &plugin;
    char error[512] = "";
    system_ = plugin.textures_create(error, sizeof error);
    if (!system_) throw failure(error);
    // One mip-mapped copy per (image, sRGB) pair: two textures may share an image.
    std::map<std::pair<int, bool>, int> made;
    index_.assign(scene.textures.size(), -1);
    wrap_.assign(scene.textures.size(), 0);
    std::vector<float> rgb;
    for (std::size_t i = 0; i < scene.textures.size(); ++i) {
        const Texture& t = scene.textures[i];
        wrap_[i] = t.wrap == TextureWrap::Clamp ? 1 : t.wrap == TextureWrap::Mirror ? 2 : 0;
        if (t.kind != TextureKind::Image || t.image < 0 ||
            std::size_t(t.image) >= scene.texture_images.size())
            continue;
        const auto key = std::make_pair(t.image, t.srgb);
        if (auto found = made.find(key); found != made.end()) {
            index_[i] = found->second;
            continue;
        }
        const TextureView view = scene.texture_view(std::size_t(t.image), t.srgb);
        rgb.resize(std::size_t(view.width) * view.height * 3);
        for (std::size_t k = 0; k < std::size_t(view.width) * view.height; ++k)
            for (int c = 0; c < 3; ++c) {
                const float stored = float(view.texels[k][c]);
                rgb[k * 3 + c] = t.srgb ? srgb_to_linear(stored) : stored;
            }
        const int index =
            plugin.textures_add(system_, rgb.data(), view.width, view.height, error, sizeof error);
        if (index < 0)
            throw failure(
                "texture \"" +
                (i < scene.texture_names.size() ? scene.texture_names[i] : std::to_string(i)) +
                "\": " + error);
        index_[i] = made[key] = index;
    }
}

OiioTextures::~OiioTextures() {
    if (system_) plugin_->textures_destroy(system_);
}

Color OiioTextures::lookup(std::size_t texture, Vec2 uv, const TexcoordDerivatives& d) const {
    if (texture >= index_.size() || index_[texture] < 0) return Color(1);
    float rgb[3];
    plugin_->textures_lookup(system_, index_[texture], wrap_[texture], anisotropic_, float(uv.x),
                             float(uv.y), float(d.dx.x), float(d.dx.y), float(d.dy.x),
                             float(d.dy.y), rgb);
    return Color(rgb[0], rgb[1], rgb[2]);
}

void use_oiio_textures(PreparedScene& scene, bool anisotropic) {
    scene.oiio_textures = std::make_shared<const OiioTextures>(scene, anisotropic);
    scene.texture_lookup = anisotropic ? TextureLookup::OiioAniso : TextureLookup::Oiio;
}

}  // namespace rt
