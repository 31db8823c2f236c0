// Stage 04: shadows. Handout: stages/04-shadows/README.md
// Where secondary rays start: framework/geometry/offset.h and
// docs/conventions.md#secondary-ray-origins. Never add an epsilon of your own.
//
// You edit only this file. Tests: ctest --test-dir build -L stage04 --output-on-failure
// The contracts are in framework/stage_api/stage04.h.
#include "core/not_implemented.h"
#include "render/nearest_hit.h"
#include "stage_api/stage02.h"
#include "stage_api/stage04.h"
#include "stage_api/stage06.h"

namespace rt {

// The ray from `at` towards the light: start at the robust offset origin, stop before the light.
ShadowRay shadow_ray(const SurfacePoint& at, const LightSample& sample) {
    // BEGIN SOLUTION
    ShadowRay shadow;
    shadow.ray = spawn_ray(at, at.normal, sample.direction);
    shadow.t_range = Interval{0, kInfinity};
    if (sample.distance < kInfinity) {
        // The light's distance from the offset origin, not from the surface point.
        const Vec3 light_position = at.point + sample.distance * sample.direction;
        shadow.t_range.max = glm::dot(light_position - shadow.ray.origin, sample.direction);
    }
    return shadow;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/04-shadows/README.md#shadow-rays");
    // (void)at; (void)sample;
    // return {};
    // END SOLUTION
}

// The fraction of the light that gets through: walk along the shadow ray, multiplying by the
// transmissive colour of every surface crossed, until the light is reached or nothing is left.
Color light_transmittance(const PreparedScene& scene, const SurfacePoint& at,
                          const LightSample& sample) {
    // BEGIN SOLUTION
    ShadowRay shadow = shadow_ray(at, sample);
    Color transmittance(1);
    for (int crossed = 0; crossed < kMaxShadowSurfaces; ++crossed) {
        Hit hit;
        if (!nearest_hit(scene, shadow.ray, shadow.t_range, hit)) return transmittance;
        transmittance *= scene.materials[std::size_t(hit.material)].transmissive;
        if (transmittance == Color(0)) return transmittance;
        // Continue past this surface, from the robust origin on its far side.
        const SurfacePoint through = surface_point(scene, shadow.ray, hit);
        const Vec3 origin =
            offset_ray_origin(through.point, through.error, through.normal, shadow.ray.direction);
        shadow.t_range.max -= glm::dot(origin - shadow.ray.origin, shadow.ray.direction);
        shadow.ray.origin = origin;
    }
    return Color(0);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/04-shadows/README.md#coloured-shadows-through-glass");
    // (void)scene; (void)at; (void)sample;
    // return Color(1);
    // END SOLUTION
}

}  // namespace rt
