// Where secondary rays start (docs/conventions.md#secondary-ray-origins).
//
// One mechanism, used by every shadow, reflected and refracted ray: the hit point is refined
// onto the surface it lies on, with a conservative bound on the rounding error of each
// coordinate (`surface_point`, scene/surface_point.h), and the ray origin is moved just past that error box along the
// normal (`offset_ray_origin`). This is pbrt-v4's OffsetRayOrigin (Pharr, Jakob, Humphreys,
// "Physically Based Rendering", 4th ed., section 6.8.6); no fixed epsilon anywhere.
#pragma once

#include "core/real.h"

namespace rt {

// gamma(n) = n u / (1 - n u), u the unit roundoff of Real: the bound on the relative error of n
// chained floating-point operations (Higham; pbrt 6.8.1).
Real gamma_bound(int n);

// The origin for a ray leaving `point` in `direction`: `point` moved along `normal` by the
// error box's extent d = |normal|.error, towards the side `direction` goes to, then rounded one
// more float away from the surface. The exact surface is then strictly behind the origin, so the
// new ray cannot hit it again at a tiny t, whatever the scene's scale. A point that is exact
// (error 0 along the normal, e.g. on an axis-aligned plane through representable coordinates)
// is not moved: the surface is then at exactly t = 0, which the open t-range excludes.
Vec3 offset_ray_origin(const Vec3& point, const Vec3& error, const Vec3& normal,
                       const Vec3& direction);

}  // namespace rt
