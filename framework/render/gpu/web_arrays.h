// rt export-web's large arrays. WebGL2 has no storage buffers, and a mesh, its BVH or an image
// baked as GLSL constants makes a shader of megabytes that a browser compiles for minutes (stage
// 06's meshes: 10-15 MB). So the page keeps them in RGBA32UI data textures, kDataTextureWidth
// texels a row, holding the storage buffers' very words (std430), and the page's accessors
// name_at(i), which every shader reads the scene's arrays through (shaders/scene_buffers.glsl),
// return what the storage buffer's element holds.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/gpu_scene.h"

namespace rt {

// One array as the page uploads it: 4 words a texel, the last texel padded with zeros.
struct DataArray {
    std::string name;                  // the GLSL array's name; its sampler is rt_data_<name>
    std::vector<std::uint32_t> words;  // a multiple of 4, at least 4 (a texture is never empty)
};

inline constexpr int kDataTextureWidth = 2048;  // WebGL2 guarantees textures this wide

// The arrays of `scene` that the page reads from data textures, in the order of their samplers.
// Throws GpuError when one needs more rows than kDataTextureWidth.
std::vector<DataArray> web_data_arrays(const gpu::GpuScene& scene);

// Whether `name` is one of those arrays (the export leaves out its constant).
bool is_web_data_array(std::string_view name);

// The GLSL of the samplers and the accessors (after scene_layout.glsl's structs).
std::string web_data_accessors();

}  // namespace rt
