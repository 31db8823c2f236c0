// Reads the image formats that only OpenImageIO knows (JPEG, HDR, TIFF, ...) through its
// plug-in, loaded on first use (oiio_plugin.h says why).
#pragma once

#include <filesystem>

#include "image/decoded_image.h"

namespace rt::image_files {

// Throws ImageError naming the file when it cannot be read, or when the plug-in is missing.
DecodedImage read_with_oiio(const std::filesystem::path& file);

}  // namespace rt::image_files
