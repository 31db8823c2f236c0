// Reads the image formats that only OpenImageIO knows (JPEG, HDR, TIFF, ...) through its
// plug-in, loaded on first use (oiio_plugin.h says why).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/decoded_image.h"
#include "image/oiio_plugin.h"

namespace rt::image_files {

// The plug-in's entry points (all null when it could not be loaded, `problem` saying why).
struct OiioPlugin {
    decltype(&rt_oiio_read) read = nullptr;
    decltype(&rt_oiio_free) free = nullptr;
    decltype(&rt_oiio_textures_create) textures_create = nullptr;
    decltype(&rt_oiio_textures_add) textures_add = nullptr;
    decltype(&rt_oiio_textures_lookup) textures_lookup = nullptr;
    decltype(&rt_oiio_textures_destroy) textures_destroy = nullptr;
    decltype(&rt_oiio_environment_add) environment_add = nullptr;
    decltype(&rt_oiio_environment_lookup) environment_lookup = nullptr;
    std::string problem;  // "the ... plug-in ..., which was not found (tried ...); <fix>"
};

// Loads the first of `candidates` that is the plug-in (tests name a missing one).
OiioPlugin open_oiio_plugin(const std::vector<std::filesystem::path>& candidates);
// The process's plug-in, loaded once on first use: RT_OIIO_PLUGIN, else ../lib/librt_oiio.so
// beside the program, else where the build put it.
const OiioPlugin& oiio_plugin();

// Throws ImageError naming the file when it cannot be read, or when the plug-in is missing.
DecodedImage read_with_oiio(const std::filesystem::path& file);

}  // namespace rt::image_files
