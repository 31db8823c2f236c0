// What an image file holds before it becomes an `Image` or `Image8`: the per-format readers
// (png_file, exr_file, the OpenImageIO plug-in) return this, image.cpp converts it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace rt::image_files {

// Larger images are refused before anything is allocated (a damaged or hostile header must not
// cost gigabytes): 16384 per side, 64 Mpixel in all.
constexpr std::int64_t kMaxSide = 16384;
constexpr std::int64_t kMaxPixels = std::int64_t(8192) * 8192;

struct DecodedImage {
    int width = 0;
    int height = 0;
    int channels = 0;       // 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
    bool floating = false;  // float file (EXR, HDR): values are linear light
    int bits = 8;           // 8 or 16 for integer files
    // Row-major, channels interleaved, row 0 at the top: one of the two is filled. `bytes` holds
    // an 8-bit file's samples as stored (exact, for Image8); `values` everything else, integer
    // files scaled to [0, 1].
    std::vector<float> values;
    std::vector<std::uint8_t> bytes;

    // Sample i scaled to [0, 1] for integer files, linear for float files.
    float value(std::size_t i) const {
        return bytes.empty() ? values[i] : float(bytes[i]) / 255.0f;
    }
};

// What is wrong with a size that is zero, negative or over the limits above (an ImageError's
// problem), or "".
std::string size_problem(std::int64_t width, std::int64_t height, int channels);

}  // namespace rt::image_files
