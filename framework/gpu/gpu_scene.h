// The scene as the GPU stage binds it: one std430 storage buffer per array, every struct a
// whole number of vec4s, floats even in the `double` preset. shaders/scene_layout.glsl declares
// the same structs; Framework.GpuLayout.* compiles that file with the driver and compares its
// offsets and strides with these, so the two sides cannot drift apart silently.
//
// Integers that share a vec4 with floats (material indices, light kinds) are stored as their
// bit patterns (GLSL: floatBitsToInt). Host code writes them with int_bits.
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

#include <glm/glm.hpp>

#include "scene/prepared_scene.h"

namespace rt::gpu {

// Storage-buffer bindings of the packed scene (scene_buffers.glsl and texel_arrays.glsl use them
// through the prelude's RT_BINDING_* names).
enum Binding : int {
    kSpheres = 0,
    kPlanes = 1,
    kBoxes = 2,
    kTriangles = 3,
    kPositions = 4,
    kNormals = 5,
    kUvs = 6,
    kMaterials = 7,
    kLights = 8,
    kBvhNodes = 9,
    kBvhPrimitives = 10,
    kTextures = 11,
    kTextureImages = 12,
    kTexels = 13,
    kEnvironment = 14,
};

struct alignas(16) GpuSphere {
    glm::vec4 center_radius;  // xyz centre, w radius
    glm::ivec4 material;      // x material index
};
struct alignas(16) GpuPlane {
    glm::vec4 point_material;  // xyz a point, w material (int bits)
    glm::vec4 normal;          // xyz unit normal
};
struct alignas(16) GpuBox {
    glm::vec4 min_material;  // xyz corner, w material (int bits)
    glm::vec4 max;
};
struct alignas(16) GpuTriangle {
    glm::uvec4 vertices_material;  // xyz vertex indices, w material
};
struct alignas(16) GpuMaterial {
    glm::vec4 ambient;
    glm::vec4 diffuse;
    glm::vec4 specular_shininess;  // xyz k_s, w n_s
    glm::vec4 emissive;            // xyz k_e, w roughness (stage 11's GGX lobe)
    glm::vec4 reflective;          // xyz k_r, w fuzz (stage 10's glossy reflection)
    glm::vec4 transmissive_ior;    // xyz k_t, w index of refraction
    glm::ivec4 maps;               // texture of the diffuse, specular, emissive, normal slot (-1)
    glm::vec4 map_transform[4];    // per slot: xy scale, zw offset
};
struct alignas(16) GpuTexture {
    glm::ivec4 kind_image_filter_wrap;  // TextureKind, image index, TextureFilter, TextureWrap
    glm::vec4 a_srgb;                   // xyz colour a, w 1 when the texels are sRGB-encoded
    glm::vec4 b_scale;                  // xyz colour b, w scale
};
struct alignas(16) GpuTextureImage {
    glm::ivec4 width_height_first;  // x width, y height, z first texel, w unused
};
// Always exactly one (kind None when the scene has none); images index texture_images.
struct alignas(16) GpuEnvironment {
    glm::ivec4 kind_image;         // x EnvironmentKind, y lat-long image, zw unused
    glm::ivec4 faces_px_nx_py_ny;  // cube-face images, OpenGL's order
    glm::ivec4 faces_pz_nz;        // xy the last two faces, zw unused
    glm::vec4 intensity_rotate_y;  // x intensity, y rotate_y in degrees, zw unused
};
struct alignas(16) GpuLight {
    glm::vec4 position_kind;  // xyz position, w kind (int bits: 0 point, 1 directional)
    glm::vec4 direction;      // w: Light::reach_mask (int bits)
    glm::vec4 intensity;      // w: the flags below (int bits)
    glm::vec4 attenuation;
};
// GpuLight::intensity.w's bits: Light::reach_rest and Light::casts_shadows.
inline constexpr int kLightReachRest = 1;
inline constexpr int kLightCastsShadows = 2;
// BvhNode (accel/bvh.h) goes as it is: {vec3 min; uint first; vec3 max; uint count}.

// Stage 10, in the uniform block SampledScene (binding 0, std140: only vec4 members, so the same
// offsets as std430). An area light; corner_kind.w int bits: 0 rectangle, 1 sphere.
struct alignas(16) GpuAreaLight {
    glm::vec4 corner_kind;    // xyz corner (rectangles), w kind
    glm::vec4 edge_u;         // xyz
    glm::vec4 edge_v;         // xyz
    glm::vec4 center_radius;  // spheres: xyz centre, w radius
    glm::vec4 radiance;       // rgb L_e
};
struct alignas(16) GpuMovingSphere {
    glm::vec4 velocity_sphere;  // xyz velocity, w the index in spheres (int bits)
};
struct alignas(16) GpuSampling {
    glm::ivec4 spp_filter_indirect;  // samples per pixel, PixelFilter, IndirectLight, unused
    glm::uvec4 seed_counts;          // seed low and high words, area lights, moving spheres
    glm::vec4 lens_shutter;          // aperture, focus distance, shutter open, shutter close
    glm::vec4 occlusion;             // x occlusion distance
};

#define RT_GPU_CHECK(T, size)                                                     \
    static_assert(sizeof(T) == (size), #T " must stay " #size " bytes (std430)"); \
    static_assert(std::is_trivially_copyable_v<T>, #T " must be trivially copyable")
RT_GPU_CHECK(GpuSphere, 32);
RT_GPU_CHECK(GpuPlane, 32);
RT_GPU_CHECK(GpuBox, 32);
RT_GPU_CHECK(GpuTriangle, 16);
RT_GPU_CHECK(GpuMaterial, 176);
RT_GPU_CHECK(GpuTexture, 48);
RT_GPU_CHECK(GpuTextureImage, 16);
RT_GPU_CHECK(GpuEnvironment, 64);
RT_GPU_CHECK(GpuLight, 64);
RT_GPU_CHECK(BvhNode, 32);
RT_GPU_CHECK(GpuAreaLight, 80);
RT_GPU_CHECK(GpuMovingSphere, 16);
RT_GPU_CHECK(GpuSampling, 64);
static_assert(sizeof(glm::vec4) == 16 && sizeof(glm::vec2) == 8, "GLSL vec4 / vec2 sizes");
static_assert(offsetof(BvhNode, first) == 12 && offsetof(BvhNode, max) == 16 &&
                  offsetof(BvhNode, count) == 28,
              "BvhNode must match GLSL {vec3 min; uint first; vec3 max; uint count}");
#undef RT_GPU_CHECK

inline float int_bits(int value) {
    float f;
    std::memcpy(&f, &value, sizeof f);
    return f;
}

struct GpuScene {
    std::vector<GpuSphere> spheres;
    std::vector<GpuPlane> planes;
    std::vector<GpuBox> boxes;
    std::vector<GpuTriangle> triangles;
    std::vector<glm::vec4> positions, normals;  // normals: w 0; empty when the scene has none
    std::vector<glm::vec2> uvs;                 // empty when the scene has none
    std::vector<GpuMaterial> materials;
    std::vector<GpuLight> lights;
    std::vector<BvhNode> bvh_nodes;
    std::vector<std::uint32_t> bvh_primitives;
    std::vector<GpuTexture> textures;
    std::vector<GpuTextureImage> texture_images;
    std::vector<glm::vec4> texels;            // w 1
    std::vector<GpuEnvironment> environment;  // one entry
    // Stage 10 (empty arrays when the scene has none); `sampling` always filled.
    GpuSampling sampling{};
    std::vector<GpuAreaLight> area_lights;
    std::vector<GpuMovingSphere> moving_spheres;
};

// The uniform block SampledScene as bytes: sampling, then `area_slots` area lights and
// `moving_slots` moving spheres (the shader's MAX_AREA_LIGHTS, MAX_MOVING_SPHERES; unused slots
// zero).
std::vector<unsigned char> sampled_block(const GpuScene& scene, int area_slots, int moving_slots);

// Every array of `scene`, converted to float and packed as above.
GpuScene pack_scene(const PreparedScene& scene);

}  // namespace rt::gpu
