// Stage 11: the area lights a path sees. In stages 10's renderer area lights are not surfaces
// (no ray meets them); the path tracer's BSDF-sampled rays must find them, or the light they
// carry would only ever arrive by light sampling (docs/conventions.md#path-tracing). Framework
// code: given to stages/11-path-tracing/path.cpp.
#pragma once

#include "core/ray.h"
#include "scene/scene.h"

namespace rt {

// The nearest area light `ray` meets with t in `t_range` (pass (0, the nearest surface's t) so
// that a surface in front hides it): its index in scene.area_lights, the ray parameter, and the
// radiance it sends back along the ray (its `radiance`, or 0 from the unlit back of a
// rectangle). light == -1 when the ray meets none. A light is an opaque emitter to such a ray:
// the path ends there (lights reflect nothing).
struct AreaLightHit {
    int light = -1;
    Real t = kInfinity;
    Color radiance{0};
};
AreaLightHit nearest_area_light(const Scene& scene, const Ray& ray, Interval t_range);

}  // namespace rt
