#include "scene/area_light_hit.h"

#include <cmath>

namespace rt {
namespace {

// t of the rectangle's plane, if the hit lies on the rectangle (edges perpendicular).
Real rectangle_t(const AreaLight& light, const Ray& ray) {
    const Vec3 n = glm::cross(light.edge_u, light.edge_v);
    const Real denominator = glm::dot(n, ray.direction);
    if (denominator == 0) return kInfinity;
    const Real t = glm::dot(n, light.corner - ray.origin) / denominator;
    const Vec3 p = ray.origin + t * ray.direction - light.corner;
    const Real s = glm::dot(p, light.edge_u) / glm::dot(light.edge_u, light.edge_u);
    const Real r = glm::dot(p, light.edge_v) / glm::dot(light.edge_v, light.edge_v);
    return s >= 0 && s <= 1 && r >= 0 && r <= 1 ? t : kInfinity;
}

// The smallest root of |origin + t direction - center| = radius within `range`.
Real sphere_t(const AreaLight& light, const Ray& ray, Interval range) {
    const Vec3 oc = ray.origin - light.center;
    const Real a = glm::dot(ray.direction, ray.direction);
    const Real half_b = glm::dot(oc, ray.direction);
    const Real c = glm::dot(oc, oc) - light.radius * light.radius;
    const Real discriminant = half_b * half_b - a * c;
    if (discriminant < 0) return kInfinity;
    const Real root = std::sqrt(discriminant);
    for (Real t : {(-half_b - root) / a, (-half_b + root) / a})
        if (t > range.min && t < range.max) return t;
    return kInfinity;
}

}  // namespace

AreaLightHit nearest_area_light(const Scene& scene, const Ray& ray, Interval t_range) {
    AreaLightHit hit;
    for (std::size_t i = 0; i < scene.area_lights.size(); ++i) {
        const AreaLight& light = scene.area_lights[i];
        const Real t = light.kind == AreaLightKind::Rectangle ? rectangle_t(light, ray)
                                                              : sphere_t(light, ray, t_range);
        if (!(t > t_range.min && t < t_range.max && t < hit.t)) continue;
        hit.light = int(i);
        hit.t = t;
        const bool lit_side = light.kind == AreaLightKind::Sphere ||
                              glm::dot(glm::cross(light.edge_u, light.edge_v), ray.direction) < 0;
        hit.radiance = lit_side ? light.radiance : Color(0);
    }
    return hit;
}

}  // namespace rt
