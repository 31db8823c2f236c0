// Stage 04 (shadows): the functions students write in stages/04-shadows/shadows.cpp.
// Handout: stages/04-shadows/README.md.
// Where rays start: framework/geometry/offset.h (docs/conventions.md#secondary-ray-origins).
#pragma once

#include "scene/prepared_scene.h"
#include "scene/surface_point.h"
#include "stage_api/stage03.h"

namespace rt {

// At most this many transparent surfaces are crossed by one shadow ray; beyond, it is blocked.
inline constexpr int kMaxShadowSurfaces = 64;

// A ray with the range of t in which a hit blocks it.
struct ShadowRay {
    Ray ray;
    Interval t_range;
};

// The shadow ray from the surface point `at` towards the light of `sample`:
//   ray       = spawn_ray(at, at.normal, sample.direction): its origin is
//               offset_ray_origin(at.point, at.error, at.normal, sample.direction), its
//               direction sample.direction (unit), its time at.time
//   t_range   = (0, distance from the origin to the light): the open interval already excludes
//               the light itself; (0, kInfinity) for a directional light.
ShadowRay shadow_ray(const SurfacePoint& at, const LightSample& sample);

// How much light of `sample` reaches `at`: (1, 1, 1) when nothing is in the way. Each surface the
// shadow ray crosses multiplies it by that surface's transmissive colour k_t ("thin shell": a
// glass sphere is crossed twice); an opaque surface (k_t = 0) gives (0, 0, 0). After a
// transparent surface move the ray's origin to offset_ray_origin from it (surface_point gives
// its error bound; the ray keeps its direction and time), at most kMaxShadowSurfaces surfaces. Find each surface with nearest_hit
// (render/nearest_hit.h): stage 02's intersect_nearest until a scene has a BVH, then the tree.
Color light_transmittance(const PreparedScene& scene, const SurfacePoint& at,
                          const LightSample& sample);

}  // namespace rt
