#include "gpu/gpu_scene.h"

#include <algorithm>
#include <cstring>

namespace rt::gpu {
namespace {

glm::vec4 v4(const Vec3& v, float w = 0) {
    return glm::vec4(float(v.x), float(v.y), float(v.z), w);
}

}  // namespace

GpuScene pack_scene(const PreparedScene& scene) {
    GpuScene g;
    for (const Sphere& s : scene.spheres)
        g.spheres.push_back({v4(s.center, float(s.radius)), glm::ivec4(s.material, 0, 0, 0)});
    for (const Plane& p : scene.planes)
        g.planes.push_back({v4(p.point, int_bits(p.material)), v4(p.normal)});
    for (const Box& b : scene.boxes)
        g.boxes.push_back({v4(b.min, int_bits(b.material)), v4(b.max)});
    for (const Triangle& t : scene.triangles)
        g.triangles.push_back({glm::uvec4(t.v[0], t.v[1], t.v[2], std::uint32_t(t.material))});
    for (const Vec3& p : scene.vertices) g.positions.push_back(v4(p, 1));
    for (const Vec3& n : scene.normals) g.normals.push_back(v4(n));
    for (const Vec2& uv : scene.uvs) g.uvs.push_back(glm::vec2(float(uv.x), float(uv.y)));
    for (const Material& m : scene.materials) {
        GpuMaterial gm{v4(m.ambient),
                       v4(m.diffuse),
                       v4(m.specular, m.shininess),
                       v4(m.emissive, m.roughness),
                       v4(m.reflective, m.fuzz),
                       v4(m.transmissive, m.ior),
                       glm::ivec4(-1),
                       {}};
        const TextureSlot* slots[4] = {&m.diffuse_map, &m.specular_map, &m.emissive_map,
                                       &m.normal_map};
        for (int i = 0; i < 4; ++i) {
            gm.maps[i] = slots[i]->texture;
            gm.map_transform[i] = glm::vec4(slots[i]->scale[0], slots[i]->scale[1],
                                            slots[i]->offset[0], slots[i]->offset[1]);
        }
        g.materials.push_back(gm);
    }
    for (const Texture& t : scene.textures)
        g.textures.push_back({glm::ivec4(int(t.kind), t.image, int(t.filter), int(t.wrap)),
                              glm::vec4(t.a, t.srgb ? 1.0f : 0.0f), glm::vec4(t.b, t.scale)});
    for (const TextureImage& i : scene.texture_images)
        g.texture_images.push_back({glm::ivec4(i.width, i.height, int(i.first), 0)});
    for (const Color& c : scene.texels) g.texels.push_back(glm::vec4(c, 1));
    const Environment& e = scene.environment;
    g.environment.push_back({glm::ivec4(int(e.kind), e.image, 0, 0),
                             glm::ivec4(e.faces[0], e.faces[1], e.faces[2], e.faces[3]),
                             glm::ivec4(e.faces[4], e.faces[5], 0, 0),
                             glm::vec4(e.intensity, e.rotate_y, 0, 0)});
    // The reach mask of the scene's own materials only: a small int for a scene of few of them
    // (a Shadertoy export bakes it as a float's bits, which must not be a NaN).
    const std::size_t materials = std::min<std::size_t>(scene.materials.size(), kLinkedMaterials);
    const std::uint32_t present =
        materials == kLinkedMaterials ? ~std::uint32_t(0) : (std::uint32_t(1) << materials) - 1;
    for (const Light& l : scene.lights) {
        const int links =
            (l.reach_rest ? kLightReachRest : 0) | (l.casts_shadows ? kLightCastsShadows : 0);
        g.lights.push_back({v4(l.position, int_bits(l.kind == LightKind::Point ? 0 : 1)),
                            v4(l.direction, int_bits(int(l.reach_mask & present))),
                            v4(l.intensity, int_bits(links)), v4(l.attenuation)});
    }
    g.bvh_nodes = scene.bvh.nodes;
    g.bvh_primitives = scene.bvh.primitives;
    const SamplingSettings& s = scene.sampling;
    g.sampling.spp_filter_indirect =
        glm::ivec4(s.samples_per_pixel, int(s.filter), int(s.indirect), 0);
    g.sampling.seed_counts = glm::uvec4(std::uint32_t(s.seed), std::uint32_t(s.seed >> 32),
                                        std::uint32_t(scene.area_lights.size()),
                                        std::uint32_t(scene.moving_spheres.size()));
    g.sampling.lens_shutter = glm::vec4(float(s.aperture), float(s.focus_distance),
                                        float(s.shutter_open), float(s.shutter_close));
    g.sampling.occlusion = glm::vec4(float(s.occlusion_distance), 0, 0, 0);
    for (const AreaLight& a : scene.area_lights)
        g.area_lights.push_back({v4(a.corner, int_bits(a.kind == AreaLightKind::Rectangle ? 0 : 1)),
                                 v4(a.edge_u), v4(a.edge_v), v4(a.center, float(a.radius)),
                                 glm::vec4(a.radiance, 0)});
    for (const MovingSphere& m : scene.moving_spheres)
        g.moving_spheres.push_back({v4(m.velocity, int_bits(int(m.sphere)))});
    return g;
}

std::vector<unsigned char> sampled_block(const GpuScene& scene, int area_slots, int moving_slots) {
    std::vector<unsigned char> bytes(sizeof(GpuSampling) +
                                     std::size_t(area_slots) * sizeof(GpuAreaLight) +
                                     std::size_t(moving_slots) * sizeof(GpuMovingSphere));
    unsigned char* at = bytes.data();
    std::memcpy(at, &scene.sampling, sizeof(GpuSampling));
    at += sizeof(GpuSampling);
    std::memcpy(at, scene.area_lights.data(),
                std::min(scene.area_lights.size(), std::size_t(area_slots)) * sizeof(GpuAreaLight));
    at += std::size_t(area_slots) * sizeof(GpuAreaLight);
    std::memcpy(
        at, scene.moving_spheres.data(),
        std::min(scene.moving_spheres.size(), std::size_t(moving_slots)) * sizeof(GpuMovingSphere));
    return bytes;
}

}  // namespace rt::gpu
