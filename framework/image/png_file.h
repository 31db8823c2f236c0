// PNG files through libpng: the format every render, reference image and test image uses.
// Kept apart from OpenImageIO so that a process that only writes PNGs does not pay for loading
// OpenImageIO's dependency tree (about 0.3 s a process on Debian 12; docs/performance.md).
#pragma once

#include <filesystem>

#include "image/decoded_image.h"
#include "image/image.h"

namespace rt::image_files {

// 8-bit RGB with the sRGB, gAMA, cHRM, oFFs and text chunks OpenImageIO wrote before, at zlib
// level 6, so reference images stay byte-identical. Throws ImageError naming the file.
void write_png(const Image8& image, const std::filesystem::path& file);

// 1-4 channels, 1-16 bits, palette and transparency expanded. Throws ImageError naming the file.
DecodedImage read_png(const std::filesystem::path& file);

}  // namespace rt::image_files
