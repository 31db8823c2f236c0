#include "render/gpu/texel_arrays.h"

#include <array>

#include "gpu/gpu_scene.h"
#include "render/gpu/gpu_render.h"

namespace rt {
namespace {

// Each storage buffer (by binding) as texel_arrays.glsl reads it.
struct TexelArray {
    int binding;
    std::string_view name;
    GLenum format;
    int texel_bytes;
};

constexpr std::array<TexelArray, 15> kArrays = {{
    {gpu::kSpheres, "spheres", GL_RGBA32UI, 16},
    {gpu::kPlanes, "planes", GL_RGBA32UI, 16},
    {gpu::kBoxes, "boxes", GL_RGBA32UI, 16},
    {gpu::kTriangles, "triangles", GL_RGBA32UI, 16},
    {gpu::kPositions, "positions", GL_RGBA32UI, 16},
    {gpu::kNormals, "normals", GL_RGBA32UI, 16},
    {gpu::kUvs, "uvs", GL_RG32UI, 8},
    {gpu::kMaterials, "materials", GL_RGBA32UI, 16},
    {gpu::kLights, "lights", GL_RGBA32UI, 16},
    {gpu::kBvhNodes, "bvh_nodes", GL_RGBA32UI, 16},
    {gpu::kBvhPrimitives, "bvh_primitives", GL_R32UI, 4},
    {gpu::kTextures, "textures", GL_RGBA32UI, 16},
    {gpu::kTextureImages, "texture_images", GL_RGBA32UI, 16},
    {gpu::kTexels, "texels", GL_RGBA32UI, 16},
    {gpu::kEnvironment, "environment", GL_RGBA32UI, 16},
}};

}  // namespace

std::vector<GLuint> create_texel_views(const GlApi& gl, const std::vector<GLuint>& buffers) {
    GLint most = 0;  // texels a buffer texture may hold (GL 4.5 guarantees 65536)
    gl.GetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &most);
    std::vector<GLuint> textures(kArrays.size());
    gl.CreateTextures(GL_TEXTURE_BUFFER, GLsizei(textures.size()), textures.data());
    for (std::size_t i = 0; i < kArrays.size(); ++i) {
        const TexelArray& a = kArrays[i];
        GLint bytes = 0;
        gl.GetNamedBufferParameteriv(buffers[std::size_t(a.binding)], GL_BUFFER_SIZE, &bytes);
        if (bytes / a.texel_bytes > most) {
            gl.DeleteTextures(GLsizei(textures.size()), textures.data());
            throw GpuError("gpu: the scene's " + std::string(a.name) + " need " +
                           std::to_string(bytes / a.texel_bytes) + " texels of a buffer texture, " +
                           "and this driver reads at most " + std::to_string(most) +
                           " (GL_MAX_TEXTURE_BUFFER_SIZE): use a smaller mesh or image, or "
                           "render without --gpu");
        }
        gl.TextureBuffer(textures[i], a.format, buffers[std::size_t(a.binding)]);
        gl.BindTextureUnit(GLuint(a.binding), textures[i]);
    }
    return textures;
}

}  // namespace rt
