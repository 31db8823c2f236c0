// The OpenImageIO plug-in's C interface. Formats other than PNG and EXR (JPEG, HDR, TIFF, ...)
// are read by OpenImageIO, which the framework loads with dlopen on first use: OpenImageIO's
// dependency tree costs about 0.3 s of start-up in every process that links it, and most
// processes (tests, grading children, `rt render`) only ever touch PNG and EXR files.
#pragma once

#include <cstddef>

extern "C" {

struct RtOiioImage {
    int width;
    int height;
    int channels;
    int floating;   // 1 for float formats (linear), 0 for integer formats scaled to [0, 1]
    int bits;       // bits per channel in the file
    float* values;  // width * height * channels, row 0 at the top; free with rt_oiio_free
};

// Reads `path`; on failure returns 0 and writes a one-line reason into `error`.
// Images with a side over `max_side` or more than `max_pixels` pixels are refused before their
// pixels are allocated.
int rt_oiio_read(const char* path, long long max_side, long long max_pixels, RtOiioImage* out,
                 char* error, std::size_t error_size);
void rt_oiio_free(RtOiioImage* image);

// OpenImageIO's TextureSystem over the scene's own texels (`rt render --texture-filter oiio`):
// each image is written once as a tiled, mip-mapped file into a private temporary directory
// (make_texture), since OIIO 2.4's TextureSystem only reads through its ImageCache, which reads
// files. Removed by rt_oiio_textures_destroy.
struct RtOiioTextures;

// A TextureSystem of its own (not OIIO's shared one); null with a one-line reason in `error`.
RtOiioTextures* rt_oiio_textures_create(char* error, std::size_t error_size);
// Adds an image of width * height linear RGB texels (row 0 at the top): mip levels are averaged
// from these, so sRGB texels must be decoded first. Returns its index, or -1 and `error`.
int rt_oiio_textures_add(RtOiioTextures* textures, const float* rgb, int width, int height,
                         char* error, std::size_t error_size);
// Filtered lookup at (s, t) = (u, v) with the footprint's derivatives in texture coordinates
// (all 0: bilinear in the finest level). wrap: 0 periodic, 1 clamp, 2 mirror. anisotropic: 0
// trilinear, else the largest anisotropy ratio. Thread-safe. Writes linear RGB into `rgb`.
void rt_oiio_textures_lookup(RtOiioTextures* textures, int index, int wrap, int anisotropic,
                             float s, float t, float dsdx, float dtdx, float dsdy, float dtdy,
                             float* rgb);
// A lat-long environment map (OpenImageIO's y-up convention; docs/conventions.md), added like
// a texture, and its bilinear lookup in the finest level along the direction (x, y, z).
int rt_oiio_environment_add(RtOiioTextures* textures, const float* rgb, int width, int height,
                            char* error, std::size_t error_size);
void rt_oiio_environment_lookup(RtOiioTextures* textures, int index, float x, float y, float z,
                                float* rgb);
void rt_oiio_textures_destroy(RtOiioTextures* textures);

}  // extern "C"
