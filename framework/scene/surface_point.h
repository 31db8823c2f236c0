// The hit point refined onto its surface, with a bound on its rounding error: where every
// secondary ray starts (docs/conventions.md#secondary-ray-origins, geometry/offset.h).
#pragma once

#include "core/hit.h"
#include "geometry/offset.h"
#include "scene/scene.h"

namespace rt {

// A hit made ready for shading and for spawning rays.
struct SurfacePoint {
    Vec3 point{0};   // on the surface, refined (see surface_point)
    Vec3 error{0};   // |computed - exact| <= error, per coordinate
    Vec3 normal{0};  // unit, facing the incoming ray (as Hit::normal)
    bool front_face = true;
    int primitive = -1;
    int material = -1;
    // Texture coordinates: filled with stage 07's mappings by the texturing step
    // (render/texturing.h) when the scene has textures, (0, 0) otherwise. Distinct from Hit::uv,
    // which holds the barycentrics for triangles.
    Vec2 texcoord{0};
    Real time = 0;  // of the ray that found it (Ray::time); rays spawned here keep it
};

// Refines hit.point onto the primitive hit.primitive and bounds its error. Per primitive:
//   sphere   p' = c + r (p - c) / |p - c|          error gamma(8) (|c| + |p' - c|)
//   plane    p' = p - n (n.(p - p0))               error |n| gamma(5) |n|.(|p| + |p0|) + gamma(2)
//   |p'| triangle p' = b0 a + b1 b + b2 c (barycentrics from hit.uv)
//                                                  error gamma(7) (|b0 a| + |b1 b| + |b2 c|)
//   box      the face coordinate is snapped to the face's min/max (exact, error 0 on that
//            axis); the others are clamped into the box, error gamma(3) |p'|
// (|v| is the component-wise absolute value.) The bounds are conservative for the operations
// written here; they do not depend on how accurately stage 02 computed hit.point, because the
// refinement puts the point back on the surface.
SurfacePoint surface_point(const Scene& scene, const Ray& ray, const Hit& hit);

// The ray leaving `at` in `direction`: from offset_ray_origin(at.point, at.error, normal,
// direction), at the time of the ray that found `at`, so a moving sphere (stage 10) is where
// that ray saw it. `normal` is the one the offset follows: at.normal, or the face a refracted
// ray crosses. Every shadow, reflected, refracted and sampled ray starts here.
inline Ray spawn_ray(const SurfacePoint& at, const Vec3& normal, const Vec3& direction) {
    return Ray{offset_ray_origin(at.point, at.error, normal, direction), direction, at.time};
}

}  // namespace rt
