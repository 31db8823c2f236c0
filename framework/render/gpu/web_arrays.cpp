#include "render/gpu/web_arrays.h"

#include <algorithm>
#include <array>
#include <cctype>
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

bool identifier_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// The index of the ']' that closes the '[' at `open` within its statement, or npos.
std::size_t closing_bracket(const std::string& code, std::size_t open) {
    int depth = 0;
    for (std::size_t i = open; i < code.size(); ++i) {
        if (code[i] == ';' || code[i] == '{' || code[i] == '}') return std::string::npos;
        if (code[i] == '[') ++depth;
        if (code[i] == ']' && --depth == 0) return i;
    }
    return std::string::npos;
}

// The GLSL: one sampler an array, and each accessor for int and uint indices (the stage 09 code
// indexes with both). Texel i of an array sits at (i % width, i / width).
const char* const kAccessors = R"(
// rt export-web (framework/render/gpu/web_arrays.h): the scene's large arrays in data textures,
// the storage buffers' words 4 to a texel; name[i] reads as name_at(i).
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

std::string read_through_accessors(std::string code) {
    return read_through_accessors(std::move(code), {kNames.begin(), kNames.end()});
}

std::string read_through_accessors(std::string code, const std::vector<std::string_view>& names) {
    for (std::size_t i = 0; i < code.size(); ++i) {
        if (!identifier_char(code[i]) || (i > 0 && identifier_char(code[i - 1]))) continue;
        std::size_t end = i;
        while (end < code.size() && identifier_char(code[end])) ++end;
        const std::string_view word(code.data() + i, end - i);
        std::size_t open = end;
        while (open < code.size() && code[open] == ' ') ++open;
        if (open < code.size() && code[open] == '[' &&
            std::find(names.begin(), names.end(), word) != names.end()) {
            // Unclosed (a typo): left as it is, for the compiler to report at its file and line.
            const std::size_t close = closing_bracket(code, open);
            if (close != std::string::npos) {
                code[close] = ')';
                code.replace(end, open + 1 - end, "_at(");
            }
        }
        i = end - 1;  // the index expression is scanned next, for nested arrays
    }
    return code;
}

}  // namespace rt
