// OpenEXR files through the OpenEXR library (linear float RGB: renders the grader scores, and
// float textures). Like png_file, kept apart from OpenImageIO for process start-up time.
#pragma once

#include <filesystem>

#include "image/decoded_image.h"
#include "image/image.h"

namespace rt::image_files {

// 32-bit float R, G, B channels, ZIP compression. Throws ImageError naming the file.
void write_exr(const Image& image, const std::filesystem::path& file);

// The R, G, B (or Y, grey) channels of the file's data window as float; other channels
// (alpha, depth, ...) are ignored. Throws ImageError naming the file.
DecodedImage read_exr(const std::filesystem::path& file);

}  // namespace rt::image_files
