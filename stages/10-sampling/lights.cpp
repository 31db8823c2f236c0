// Stage 10: distribution ray tracing, part 2: area lights and soft shadows, glossy reflection,
// ambient occlusion and one bounce of indirect light. Handout: stages/10-sampling/README.md.
// Conventions: docs/conventions.md#sampling (radiance, pdfs, the 1 / pi of diffuse light).
//
// You edit only this file and sampling.cpp. Tests: ctest --test-dir build -L stage10
// The contracts are in framework/stage_api/stage10.h. Stage 03's blinn_phong, stage 04's
// light_transmittance and stage 02's intersect_nearest do the shading and the visibility.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/not_implemented.h"
#include "geometry/onb.h"
#include "render/nearest_hit.h"
#include "stage_api/stage02.h"
#include "stage_api/stage04.h"
#include "stage_api/stage06.h"
#include "stage_api/stage10.h"

namespace rt {

// Uniform in area, turned into a density per solid angle by distance^2 / cos.
AreaSample sample_rectangle(const AreaLight& light, const Vec3& from, Vec2 u) {
    // BEGIN SOLUTION
    AreaSample s;
    s.point = light.corner + u.x * light.edge_u + u.y * light.edge_v;
    const Vec3 cross = glm::cross(light.edge_u, light.edge_v);
    const Real area = glm::length(cross);
    s.normal = cross / area;
    const Vec3 d = s.point - from;
    const Real distance2 = glm::dot(d, d);
    const Real cosine = std::abs(glm::dot(s.normal, d)) / std::sqrt(distance2);
    s.pdf = cosine > 0 ? distance2 / (cosine * area) : Real(0);
    return s;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#4-sampling-area-lights");
    // (void)light, (void)from, (void)u;
    // return {};
    // END SOLUTION
}

Real rectangle_pdf(const AreaLight& light, const Vec3& from, const Vec3& direction) {
    // BEGIN SOLUTION
    const Vec3 cross = glm::cross(light.edge_u, light.edge_v);
    const Real area = glm::length(cross);
    const Vec3 n = cross / area;
    const Real denominator = glm::dot(n, direction);
    if (denominator == 0) return 0;
    const Real t = glm::dot(n, light.corner - from) / denominator;
    if (!(t > 0)) return 0;
    const Vec3 p = from + t * direction - light.corner;  // the edges are perpendicular
    const Real s = glm::dot(p, light.edge_u) / glm::dot(light.edge_u, light.edge_u);
    const Real r = glm::dot(p, light.edge_v) / glm::dot(light.edge_v, light.edge_v);
    if (s < 0 || s > 1 || r < 0 || r > 1) return 0;
    return t * t / (std::abs(denominator) * area);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#4-sampling-area-lights");
    // (void)light, (void)from, (void)direction;
    // return 0;
    // END SOLUTION
}

// Uniform in the cone of directions that see the sphere (pbrt's sphere sampling).
AreaSample sample_sphere(const AreaLight& light, const Vec3& from, Vec2 u) {
    // BEGIN SOLUTION
    AreaSample s;
    const Vec3 to_center = light.center - from;
    const Real distance = glm::length(to_center);
    if (!(distance > light.radius)) return s;
    const Real sin2_max = light.radius * light.radius / (distance * distance);
    const Real cos_max = std::sqrt(std::max(Real(0), 1 - sin2_max));
    const Real one_minus_cos_max = sin2_max / (1 + cos_max);  // no cancellation for far spheres
    const Real cos_theta = 1 - u.x * one_minus_cos_max;
    const Real sin_theta = std::sqrt(std::max(Real(0), 1 - cos_theta * cos_theta));
    const Real phi = 2 * std::numbers::pi_v<Real> * u.y;
    const Onb frame = onb_around(to_center / distance);
    const Vec3 direction =
        frame.to_world(Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta));
    // The nearer intersection of that direction with the sphere.
    const Real half_chord = std::sqrt(std::max(
        Real(0), light.radius * light.radius - distance * distance * sin_theta * sin_theta));
    s.point = from + (distance * cos_theta - half_chord) * direction;
    s.normal = glm::normalize(s.point - light.center);
    s.pdf = 1 / (2 * std::numbers::pi_v<Real> * one_minus_cos_max);
    return s;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#4-sampling-area-lights");
    // (void)light, (void)from, (void)u;
    // return {};
    // END SOLUTION
}

Real sphere_pdf(const AreaLight& light, const Vec3& from, const Vec3& direction) {
    // BEGIN SOLUTION
    const Vec3 to_center = light.center - from;
    const Real distance = glm::length(to_center);
    if (!(distance > light.radius)) return 0;
    const Real sin2_max = light.radius * light.radius / (distance * distance);
    const Real cos_max = std::sqrt(std::max(Real(0), 1 - sin2_max));
    if (glm::dot(direction, to_center) / distance < cos_max) return 0;
    return 1 / (2 * std::numbers::pi_v<Real> * sin2_max / (1 + cos_max));
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#4-sampling-area-lights");
    // (void)light, (void)from, (void)direction;
    // return 0;
    // END SOLUTION
}

LightSample sample_area_light(const AreaLight& light, const Vec3& point, Vec2 u) {
    // BEGIN SOLUTION
    const AreaSample s = light.kind == AreaLightKind::Rectangle ? sample_rectangle(light, point, u)
                                                                : sample_sphere(light, point, u);
    LightSample out;
    if (!(s.pdf > 0)) return out;
    const Vec3 d = s.point - point;
    out.distance = glm::length(d);
    out.direction = d / out.distance;
    if (glm::dot(s.normal, out.direction) >= 0) return out;  // the unlit back of a rectangle
    out.intensity = light.radiance / float(std::numbers::pi_v<Real> * s.pdf);
    return out;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#5-soft-shadows");
    // (void)light, (void)point, (void)u;
    // return {};
    // END SOLUTION
}

Color area_light_estimate(const PreparedScene& scene, const Material& material,
                          const SurfacePoint& at, const Vec3& normal, const Vec3& to_viewer,
                          const AreaLight& light, Vec2 u) {
    // BEGIN SOLUTION
    const LightSample sample = sample_area_light(light, at.point, u);
    if (sample.intensity == Color(0)) return Color(0);
    const Color reflected =
        blinn_phong(material, normal, to_viewer, sample.direction, sample.intensity);
    if (reflected == Color(0)) return reflected;
    return reflected * light_transmittance(scene, at, sample);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#5-soft-shadows");
    // (void)scene, (void)material, (void)at, (void)normal, (void)to_viewer, (void)light, (void)u;
    // return Color(0);
    // END SOLUTION
}

Vec3 glossy_direction(const Vec3& mirror, Real fuzz, Vec2 u) {
    // BEGIN SOLUTION
    return glm::normalize(mirror + fuzz * sample_uniform_sphere(u));
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#6-glossy-reflection");
    // (void)fuzz, (void)u;
    // return mirror;
    // END SOLUTION
}

Ray cosine_ray(const SurfacePoint& at, const Vec3& normal, Vec2 u) {
    // BEGIN SOLUTION
    const Vec3 direction = onb_around(normal).to_world(sample_cosine_hemisphere(u));
    return spawn_ray(at, at.normal, direction);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#7-ambient-occlusion-and-indirect-light");
    // (void)at, (void)normal, (void)u;
    // return {};
    // END SOLUTION
}

Real ambient_occlusion(const PreparedScene& scene, const SurfacePoint& at, const Vec3& normal,
                       Real max_distance, Vec2 u) {
    // BEGIN SOLUTION
    Hit hit;
    return nearest_hit(scene, cosine_ray(at, normal, u), Interval{0, max_distance}, hit) ? Real(0)
                                                                                         : Real(1);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#7-ambient-occlusion-and-indirect-light");
    // (void)scene, (void)at, (void)normal, (void)max_distance, (void)u;
    // return 1;
    // END SOLUTION
}

// (k_d / pi) L cos / (cos / pi) = k_d L: cosine sampling cancels the cosine and the pi.
Color indirect_diffuse(const SurfacePoint& at, const Vec3& normal, const Material& material, Vec2 u,
                       const IncomingRadiance& incoming) {
    // BEGIN SOLUTION
    return material.diffuse * incoming(cosine_ray(at, normal, u));
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#7-ambient-occlusion-and-indirect-light");
    // (void)at, (void)normal, (void)material, (void)u, (void)incoming;
    // return Color(0);
    // END SOLUTION
}

// Optional (fog): Beer-Lambert over the distance travelled inside the medium.
Real medium_transmittance(const Medium& medium, const Ray& ray, Interval range) {
    // BEGIN SOLUTION
    const Interval inside = medium_interval(medium, ray, range);
    if (!(inside.min < inside.max)) return 1;
    const Real distance = (inside.max - inside.min) * glm::length(ray.direction);
    return std::exp(-medium.density * distance);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#optional-fog");
    // (void)medium, (void)ray, (void)range;
    // return 1;
    // END SOLUTION
}

// Optional (fog): a free flight from where the ray enters the medium.
FogEvent sample_fog(const Medium& medium, const Ray& ray, Real t_max, Real u) {
    // BEGIN SOLUTION
    FogEvent event;
    const Interval inside = medium_interval(medium, ray, Interval{0, t_max});
    if (!(inside.min < inside.max)) return event;
    const Real t = inside.min + sample_free_flight(medium.density, u) / glm::length(ray.direction);
    if (t < inside.max) {
        event.scattered = true;
        event.t = t;
    }
    return event;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#optional-fog");
    // (void)medium, (void)ray, (void)t_max, (void)u;
    // return {};
    // END SOLUTION
}

}  // namespace rt
