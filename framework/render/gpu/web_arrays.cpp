#include "render/gpu/web_arrays.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "render/gpu/gpu_render.h"

namespace rt {
namespace {

constexpr std::array<std::string_view, 8> kNames = {
    "triangles", "positions",      "normals",        "uvs",
    "bvh_nodes", "bvh_primitives", "texture_images", "texels"};

// The words of a vector of std430 elements (every element type here is a whole number of words).
template <typename T>
DataArray words_of(std::string_view name, const std::vector<T>& items) {
    static_assert(sizeof(T) % 4 == 0);
    DataArray array{std::string(name), {}};
    const std::size_t words = items.size() * sizeof(T) / 4;
    array.words.assign(std::max<std::size_t>(4, (words + 3) / 4 * 4), 0u);
    if (words > 0) std::memcpy(array.words.data(), items.data(), words * 4);
    const std::size_t rows = array.words.size() / 4 / kDataTextureWidth + 1;
    if (rows > std::size_t(kDataTextureWidth))
        throw GpuError("the scene's " + array.name + " need " + std::to_string(rows) +
                       " rows of a data texture, and a page can count on " +
                       std::to_string(kDataTextureWidth) + ": use a smaller mesh or image");
    return array;
}

// The GLSL: one sampler an array, and each accessor for int and uint indices (the stage 09 code
// indexes with both). Texel i of an array sits at (i % width, i / width).
const char* const kAccessors = R"(
// rt export-web (framework/render/gpu/web_arrays.h): the scene's large arrays in data textures,
// the storage buffers' words 4 to a texel, read through name_at(i) (shaders/scene_buffers.glsl).
uniform highp usampler2D rt_data_triangles, rt_data_positions, rt_data_normals, rt_data_uvs,
    rt_data_bvh_nodes, rt_data_bvh_primitives, rt_data_texture_images, rt_data_texels;
uvec4 rt_texel(highp usampler2D words, int i) {
    return texelFetch(words, ivec2(i % RT_DATA_WIDTH, i / RT_DATA_WIDTH), 0);
}
Triangle triangles_at(int i) { return Triangle(rt_texel(rt_data_triangles, i)); }
vec4 positions_at(int i) { return uintBitsToFloat(rt_texel(rt_data_positions, i)); }
vec4 normals_at(int i) { return uintBitsToFloat(rt_texel(rt_data_normals, i)); }
vec2 uvs_at(int i) {
    uvec4 t = rt_texel(rt_data_uvs, i / 2);
    return uintBitsToFloat(i % 2 == 0 ? t.xy : t.zw);
}
BvhNode bvh_nodes_at(int i) {
    uvec4 a = rt_texel(rt_data_bvh_nodes, 2 * i), b = rt_texel(rt_data_bvh_nodes, 2 * i + 1);
    return BvhNode(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz), b.w);
}
uint bvh_primitives_at(int i) {
    uvec4 t = rt_texel(rt_data_bvh_primitives, i / 4);
    int k = i % 4;
    return k == 0 ? t.x : k == 1 ? t.y : k == 2 ? t.z : t.w;
}
TextureImage texture_images_at(int i) {
    return TextureImage(ivec4(rt_texel(rt_data_texture_images, i)));
}
vec4 texels_at(int i) { return uintBitsToFloat(rt_texel(rt_data_texels, i)); }
Triangle triangles_at(uint i) { return triangles_at(int(i)); }
vec4 positions_at(uint i) { return positions_at(int(i)); }
vec4 normals_at(uint i) { return normals_at(int(i)); }
vec2 uvs_at(uint i) { return uvs_at(int(i)); }
BvhNode bvh_nodes_at(uint i) { return bvh_nodes_at(int(i)); }
uint bvh_primitives_at(uint i) { return bvh_primitives_at(int(i)); }
TextureImage texture_images_at(uint i) { return texture_images_at(int(i)); }
vec4 texels_at(uint i) { return texels_at(int(i)); }
)";

}  // namespace

std::vector<DataArray> web_data_arrays(const gpu::GpuScene& g) {
    return {words_of(kNames[0], g.triangles),      words_of(kNames[1], g.positions),
            words_of(kNames[2], g.normals),        words_of(kNames[3], g.uvs),
            words_of(kNames[4], g.bvh_nodes),      words_of(kNames[5], g.bvh_primitives),
            words_of(kNames[6], g.texture_images), words_of(kNames[7], g.texels)};
}

bool is_web_data_array(std::string_view name) {
    return std::find(kNames.begin(), kNames.end(), name) != kNames.end();
}

std::string web_data_accessors() {
    return "#define RT_DATA_WIDTH " + std::to_string(kDataTextureWidth) + "\n" + kAccessors;
}

}  // namespace rt
