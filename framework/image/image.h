// Images: linear float RGB in memory; written as sRGB-encoded 8-bit PNG for viewing or as
// linear EXR for data (docs/conventions.md#colour). PNG and EXR are read and written by libpng
// and OpenEXR; other formats are read by OpenImageIO, loaded only when one is met
// (image/oiio_plugin.h says why).
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/real.h"

namespace rt {

// Linear RGB, row-major, row 0 at the top of the picture.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<Color> pixels;

    Image() = default;
    Image(int w, int h, Color fill = Color(0))
        : width(w), height(h), pixels(std::size_t(w) * h, fill) {}
    Color& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
    const Color& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
};

// 8-bit sRGB-encoded RGB, the form of images on disk: what graders compare.
struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> data;  // 3 bytes a pixel

    const std::uint8_t* at(int x, int y) const { return &data[(std::size_t(y) * width + x) * 3]; }
    std::uint8_t* at(int x, int y) { return &data[(std::size_t(y) * width + x) * 3]; }
};

// An image file that cannot be read or written. what() is the whole message on one line,
// "<file>: error: <problem>"; problem() is what is wrong and what to do, for a caller that names
// the file its own way (a scene file's line, the grader's report).
class ImageError : public std::runtime_error {
  public:
    ImageError(const std::filesystem::path& file, const std::string& problem);
    const std::string& problem() const { return problem_; }

  private:
    std::string problem_;
};

// The sRGB transfer function (IEC 61966-2-1), for one linear value clamped to [0, 1].
float linear_to_srgb(float linear);
float srgb_to_linear(float encoded);

// Linear to 8-bit sRGB with rounding to nearest. NaN becomes 0; values outside [0, 1] clamp.
Image8 to_image8(const Image& image);
// One channel as to_image8 stores it: lround(linear_to_srgb(linear) * 255), the same bit for
// bit, from a table instead of pow (image/image.cpp says how).
std::uint8_t encode_srgb8(float linear);

// Writes by extension: .png (8-bit sRGB) or .exr (linear float). Throws ImageError naming the
// file on failure (unknown extension, unwritable folder, ...).
void write_image(const Image& image, const std::filesystem::path& file);
void write_image8(const Image8& image, const std::filesystem::path& file);
// Throws the ImageError write_image would, for a bad extension or a missing folder, before any
// work is done (a long render must not end in "cannot write").
void check_image_output(const std::filesystem::path& file);

// Reads any image read_image can, as 8-bit values: exact for 8-bit files, rounded from other
// depths (alpha is dropped; grey is expanded). Throws ImageError naming the file when it is
// missing or unreadable.
Image8 read_image8(const std::filesystem::path& file);

// How stored values map to linear light. Float files (EXR, HDR) are linear already; integer
// files (8- or 16-bit PNG, JPEG) hold sRGB-encoded colour (textures) or plain data (normal
// maps, height maps): the caller says which (docs/conventions.md#colour).
enum class Encoding { Srgb, Data };

// EXR, 8- or 16-bit PNG, and what OpenImageIO reads (HDR, JPEG, TIFF, ...), as linear float RGB
// (grey is spread to three channels, alpha dropped). Throws ImageError naming the file for a
// missing or unreadable file, an impossible size, or NaN/infinite pixels.
// What the file held, for callers that care (a normal map needs three channels).
struct ImageInfo {
    int channels = 0;       // 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
    bool floating = false;  // a float file (EXR, HDR): linear values
};
Image read_image(const std::filesystem::path& file, Encoding integer_encoding = Encoding::Srgb,
                 ImageInfo* info = nullptr);

// Pixels with a NaN or infinite channel (a 0/0, 0 * inf or inf - inf in the shading), which the
// PNG writer would otherwise turn black or white without a word: mark_non_finite_pixels paints
// them magenta, as render() paints a stub's pixel, and counts them. `rt render` and the gallery
// print describe().
struct NonFinitePixels {
    long long count = 0;
    int first_x = -1, first_y = -1;  // the first in reading order

    // One line naming the scene, the count, the first pixel and the command that shows it.
    std::string describe(const std::string& scene) const;
};
NonFinitePixels mark_non_finite_pixels(Image& image);

}  // namespace rt
