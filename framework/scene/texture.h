// Textures as plain data (stage 07): a table of textures in the scene, referenced by index from
// the texture slots of a material. Image texels live in one flat array (Scene::texels), so the
// GPU stage uploads the table and the texels unchanged. Conventions (texture coordinates, rows,
// colour spaces, normal maps): docs/conventions.md#textures. File syntax:
// docs/scene-format.md#textures.
#pragma once

#include <cstdint>
#include <type_traits>

#include "core/real.h"

namespace rt {

enum class TextureKind : std::int32_t {
    Image,      // texels of Scene::texture_images[image]
    Checker2D,  // squares of side 1 in texture coordinates, colours a and b
    Checker3D,  // cubes of side `scale` in world space, colours a and b
    Marble,     // veins of gradient noise at `scale` in world space, between a and b
};
enum class TextureFilter : std::int32_t { Nearest, Bilinear };
enum class TextureWrap : std::int32_t { Repeat, Clamp, Mirror };
// How a render filters image textures: each by its own filter, or all of them nearest or
// bilinear (`rt render --texture-filter`, to compare them on one scene), or all through
// OpenImageIO's TextureSystem, mip-mapped (trilinear or anisotropic; render/oiio_textures.h),
// a reference the course does not ask students to write.
enum class TextureLookup : std::int32_t { PerTexture, Nearest, Bilinear, Oiio, OiioAniso };

// One image of the texture table: `width` x `height` texels, row-major from the top row, starting
// at Scene::texels[first]. The values are as the file stores them, scaled to [0, 1] for integer
// files (encoded: see Texture::srgb), linear for float files (EXR, HDR).
struct TextureImage {
    std::int32_t width = 0;
    std::int32_t height = 0;
    std::uint32_t first = 0;
};

struct Texture {
    TextureKind kind = TextureKind::Image;
    std::int32_t image = -1;  // Image: index into Scene::texture_images
    TextureFilter filter = TextureFilter::Bilinear;
    TextureWrap wrap = TextureWrap::Repeat;
    // Image: the texels are sRGB-encoded and lookups decode them to linear (colour textures in
    // 8- and 16-bit files); false for data (normal maps, float files).
    bool srgb = false;
    Color a{0};  // procedural textures: the two colours
    Color b{1};
    float scale = 1;  // Checker3D: cube side; Marble: feature size (world units)
};

// A material's use of a texture: which one (-1: none) and how its texture coordinates are mapped
// before lookup, uv' = uv * scale + offset (so scale (4, 4) repeats an image four times).
struct TextureSlot {
    std::int32_t texture = -1;
    float scale[2] = {1, 1};
    float offset[2] = {0, 0};

    bool used() const { return texture >= 0; }
};

static_assert(std::is_trivially_copyable_v<TextureImage> && std::is_trivially_copyable_v<Texture> &&
              std::is_trivially_copyable_v<TextureSlot>);

// A read-only view of one image's texels, as the stage 07 lookups receive it.
struct TextureView {
    const Color* texels = nullptr;  // width * height values, row 0 at the top
    int width = 0;
    int height = 0;
    bool srgb = false;  // texels are sRGB-encoded: decode each one before filtering

    // The stored (not decoded) value of texel (i, j): column i from the left, row j from the top.
    // No bounds check: i in [0, width), j in [0, height).
    const Color& stored(int i, int j) const { return texels[std::size_t(j) * width + i]; }
};

}  // namespace rt
