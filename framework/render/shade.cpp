#include "render/shade.h"

#include "render/accelerate.h"
#include "student/stage02.h"
#include "student/stage03.h"
#include "student/stage04.h"
#include "student/stage05.h"

namespace rt {
namespace {

bool nonzero(const Color& c) {
    return c.r > 0 || c.g > 0 || c.b > 0;
}

}  // namespace

const char* to_string(RayNode::Kind kind) {
    switch (kind) {
        case RayNode::Kind::Camera:
            return "camera";
        case RayNode::Kind::Reflection:
            return "reflection";
        case RayNode::Kind::Refraction:
            return "refraction";
    }
    return "?";
}

Color trace_ray(const Scene& scene, const Ray& ray, int depth, RayNode* node, const Color& weight) {
    if (node) node->depth = depth, node->ray = ray, node->weight = weight;
    Hit hit;
    if (!nearest_hit(scene, ray, Interval{0, kInfinity}, hit)) {
        if (node) node->local = scene.background, node->contribution = weight * scene.background;
        return scene.background;
    }
    // A scene built in code may lack materials; an out-of-range index must not crash.
    static const Material kDefaultMaterial;
    const bool known = hit.material >= 0 && std::size_t(hit.material) < scene.materials.size();
    const Material& material =
        known ? scene.materials[std::size_t(hit.material)] : kDefaultMaterial;
    const SurfacePoint at = surface_point(scene, ray, hit);
    const Vec3 to_viewer = -glm::normalize(ray.direction);
    // Meshes with vertex normals are lit with the interpolated normal (smooth shading); ray
    // origins and mirror directions keep the geometric one, which the offsets are built on.
    Vec3 lighting_normal = at.normal;
    if (!scene.normals.empty()) {
        std::size_t index = 0;
        if (scene.primitive_kind(hit.primitive, index) == Scene::Kind::Triangle) {
            const Vec3 smooth = shading_normal(scene, index, hit.uv);
            if (smooth != Vec3(0)) lighting_normal = hit.front_face ? smooth : -smooth;
        }
    }

    Color local;
    if (scene.features.shadows) {
        // With a BVH and nothing transparent, a shadow ray only asks whether anything is in the
        // way: stage 06's any-hit query, which gives what light_transmittance would, faster.
        const bool any_hit_shadows = uses_bvh(scene) && !scene.features.refraction;
        auto visibility = [&](std::size_t light, const LightSample& sample) {
            Color transmittance;
            if (any_hit_shadows) {
                const ShadowRay shadow = shadow_ray(at, sample);
                transmittance = Color(bvh_intersect_any(scene, shadow.ray, shadow.t_range) ? 0.0f : 1.0f);
            } else {
                transmittance = light_transmittance(scene, at, sample);
            }
            if (node) {
                // The debugger also names the first surface in the way (framework's own query).
                ShadowRecord record;
                record.light = light;
                const ShadowRay shadow = shadow_ray(at, sample);
                record.ray = shadow.ray, record.t_range = shadow.t_range;
                record.transmittance = transmittance;
                Hit blocker;
                if (nearest_hit(scene, shadow.ray, shadow.t_range, blocker))
                    record.blocked_by = blocker.primitive, record.blocked_t = blocker.t;
                node->shadows.push_back(record);
            }
            return transmittance;
        };
        local = direct_light(scene, material, at.point, lighting_normal, to_viewer,
                             LightFilter(visibility));
    } else {
        local = direct_light(scene, material, at.point, lighting_normal, to_viewer);
    }
    if (node) {
        node->hit = true, node->hit_record = hit, node->surface = at;
        node->local = local, node->contribution = weight * local;
    }

    Color colour = local;
    const bool recursive_material = (scene.features.reflection && nonzero(material.reflective)) ||
                                    (scene.features.refraction && nonzero(material.transmissive));
    if (depth < scene.max_depth && recursive_material) {
        const SecondaryRays rays = secondary_rays(ray, at, material, scene.fresnel);
        const std::pair<const SecondaryRay*, RayNode::Kind> branches[] = {
            {&rays.reflected, RayNode::Kind::Reflection},
            {&rays.refracted, RayNode::Kind::Refraction}};
        for (const auto& [secondary, kind] : branches) {
            if (!secondary->valid) continue;
            RayNode* child = nullptr;
            if (node) {
                child = &node->children.emplace_back();
                child->kind = kind, child->ray_weight = secondary->weight;
            }
            colour += secondary->weight * trace_ray(scene, secondary->ray, depth + 1, child,
                                                    weight * secondary->weight);
        }
    }
    return colour;
}

Color shade_pixel(const Scene& scene, int x, int y, RayNode* tree) {
    const Ray ray =
        camera_ray(scene.camera, Vec2(Real(x) + Real(0.5), Real(y) + Real(0.5)), scene.image);
    if (tree) *tree = RayNode{};
    return trace_ray(scene, ray, 0, tree);
}

}  // namespace rt
