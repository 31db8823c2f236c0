// Where secondary rays start (docs/conventions.md#secondary-ray-origins).
//
// One mechanism, used by every shadow, reflected and refracted ray: the hit point is refined
// onto the surface it lies on, with a conservative bound on the rounding error of each
// coordinate (`surface_point`), and the ray origin is moved just past that error box along the
// normal (`offset_ray_origin`). This is pbrt-v4's OffsetRayOrigin (Pharr, Jakob, Humphreys,
// "Physically Based Rendering", 4th ed., section 6.8.6); no fixed epsilon anywhere.
#pragma once

#include "core/hit.h"
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
};

// gamma(n) = n u / (1 - n u), u the unit roundoff of Real: the bound on the relative error of n
// chained floating-point operations (Higham; pbrt 6.8.1).
Real gamma_bound(int n);

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

// The origin for a ray leaving `point` in `direction`: `point` moved along `normal` by the
// error box's extent d = |normal|.error, towards the side `direction` goes to, then rounded one
// more float away from the surface. The exact surface is then strictly behind the origin, so the
// new ray cannot hit it again at a tiny t, whatever the scene's scale. A point that is exact
// (error 0 along the normal, e.g. on an axis-aligned plane through representable coordinates)
// is not moved: the surface is then at exactly t = 0, which the open t-range excludes.
Vec3 offset_ray_origin(const Vec3& point, const Vec3& error, const Vec3& normal,
                       const Vec3& direction);

}  // namespace rt
