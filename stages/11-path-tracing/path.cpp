// Stage 11: path tracing, part 2: multiple importance sampling, next-event estimation and the
// path tracer. Handout: stages/11-path-tracing/README.md. Conventions:
// docs/conventions.md#path-tracing.
//
// You edit only this file and bsdf.cpp. Tests: ctest --test-dir build -L stage11
// The contracts are in framework/stage_api/stage11.h. Stage 10's sample_rectangle,
// sample_sphere and their pdfs sample the lights; stage 06's nearest_hit finds surfaces, the
// framework's nearest_area_light (scene/area_light_hit.h) finds lights.
#include <algorithm>
#include <cmath>

#include "core/not_implemented.h"
#include "render/background.h"
#include "render/nearest_hit.h"
#include "scene/area_light_hit.h"
#include "stage_api/stage06.h"
#include "stage_api/stage10.h"
#include "stage_api/stage11.h"

namespace rt {

Real balance_heuristic(Real pdf_f, Real pdf_g) {
    // BEGIN SOLUTION
    return pdf_f + pdf_g > 0 ? pdf_f / (pdf_f + pdf_g) : Real(0);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#4-multiple-importance-sampling");
    // (void)pdf_f, (void)pdf_g;
    // return 0;
    // END SOLUTION
}

Real power_heuristic(Real pdf_f, Real pdf_g) {
    // BEGIN SOLUTION
    const Real f2 = pdf_f * pdf_f, g2 = pdf_g * pdf_g;
    return f2 + g2 > 0 ? f2 / (f2 + g2) : Real(0);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#4-multiple-importance-sampling");
    // (void)pdf_f, (void)pdf_g;
    // return 0;
    // END SOLUTION
}

// BEGIN SOLUTION
namespace {

// The solid-angle density with which light sampling picks `direction` from `from`: the light's
// own (stage 10) over the number of lights.
Real light_pdf(const PreparedScene& scene, const AreaLight& light, const Vec3& from,
               const Vec3& direction) {
    const Real pdf = light.kind == AreaLightKind::Rectangle ? rectangle_pdf(light, from, direction)
                                                            : sphere_pdf(light, from, direction);
    return pdf / Real(scene.area_lights.size());
}

}  // namespace
// STUB
// // Helper functions of your own may go here (an anonymous namespace keeps them in this file).
// END SOLUTION

Color sample_light_mis(const PreparedScene& scene, const SurfacePoint& at, const Onb& frame,
                       const Material& material, const Vec3& wo, Real u_light, Vec2 u) {
    // BEGIN SOLUTION
    const std::size_t count = scene.area_lights.size();
    if (count == 0) return Color(0);
    const AreaLight& light =
        scene.area_lights[std::min(count - 1, std::size_t(u_light * Real(count)))];
    const AreaSample a = light.kind == AreaLightKind::Rectangle
                             ? sample_rectangle(light, at.point, u)
                             : sample_sphere(light, at.point, u);
    if (!(a.pdf > 0)) return Color(0);
    const Vec3 to_light = a.point - at.point;
    const Real distance = glm::length(to_light);
    const Vec3 direction = to_light / distance;
    if (glm::dot(a.normal, direction) >= 0) return Color(0);  // the back of a rectangle
    const Vec3 wi = frame.to_local(direction);
    const Color f = eval_bsdf(material, wo, wi);
    if (f == Color(0)) return Color(0);
    Hit blocker;
    const Vec3 side = glm::dot(direction, at.normal) > 0 ? at.normal : -at.normal;
    if (nearest_hit(scene, spawn_ray(at, side, direction), Interval{0, distance * Real(0.9999)},
                    blocker))
        return Color(0);
    const Real p_light = a.pdf / Real(count);
    const Real weight = power_heuristic(p_light, bsdf_pdf(material, wo, wi));
    return f * light.radiance * float(std::abs(wi.z) * weight / p_light);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#5-next-event-estimation");
    // (void)scene, (void)at, (void)frame, (void)material, (void)wo, (void)u_light, (void)u;
    // return Color(0);
    // END SOLUTION
}

Color path_radiance(const PreparedScene& scene, const Ray& camera_ray, SampleStream& stream) {
    // BEGIN SOLUTION
    Color radiance(0), throughput(1);
    Ray ray = camera_ray;
    bool full_weight = true;  // the camera ray, or a delta bounce: no light sampling competed
    Real bounce_pdf = 0;
    for (int depth = 0;; ++depth) {
        Hit hit;
        const bool found = nearest_hit(scene, ray, Interval{0, kInfinity}, hit);
        const AreaLightHit light = nearest_area_light(scene, ray, Interval{0, hit.t});
        if (light.light >= 0) {
            const AreaLight& l = scene.area_lights[std::size_t(light.light)];
            const Vec3 d = glm::normalize(ray.direction);
            const Real weight =
                full_weight ? 1 : power_heuristic(bounce_pdf, light_pdf(scene, l, ray.origin, d));
            radiance += throughput * light.radiance * float(weight);
            break;
        }
        if (!found) {
            radiance += throughput * background(scene, ray.direction);  // the sky, if any
            break;
        }
        const SurfacePoint at = surface_point(scene, ray, hit);
        const Material& material = scene.materials[std::size_t(hit.material)];
        radiance += throughput * material.emissive;  // never light-sampled: full weight
        if (depth >= scene.max_depth) break;
        const Onb frame = onb_around(at.front_face ? at.normal : -at.normal);
        const Vec3 wo = frame.to_local(-glm::normalize(ray.direction));
        const Real u_light = stream.next();
        const Vec2 u = stream.next2();
        radiance += throughput * sample_light_mis(scene, at, frame, material, wo, u_light, u);
        const Real u_lobe = stream.next();
        const BsdfSample s = sample_bsdf(material, wo, u_lobe, stream.next2());
        if (s.weight == Color(0)) break;
        throughput *= s.weight;
        full_weight = s.delta;
        bounce_pdf = s.pdf;
        const Vec3 direction = frame.to_world(s.wi);
        ray = spawn_ray(at, glm::dot(direction, at.normal) > 0 ? at.normal : -at.normal, direction);
        if (depth >= 3) {  // the 4th surface on: Russian roulette, unbiased by the division
            const Real q =
                std::min(Real(0.95), Real(std::max({throughput.r, throughput.g, throughput.b})));
            if (stream.next() >= q) break;
            throughput /= float(q);
        }
    }
    return radiance;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#6-the-path-tracer");
    // (void)scene, (void)camera_ray, (void)stream;
    // return Color(0);
    // END SOLUTION
}

}  // namespace rt
