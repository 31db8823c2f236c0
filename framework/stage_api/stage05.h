// Stage 05 (recursion): the functions students write in stages/05-recursion/recursion.cpp.
// Handout: stages/05-recursion/README.md.
// The framework's shading driver (framework/render/shade.cpp) calls secondary_rays at each hit
// and adds weight * (colour seen along the ray), up to the scene's max_depth.
#pragma once

#include "scene/surface_point.h"

namespace rt {

// The mirror direction of d about the unit normal n: d - 2 (d.n) n. Any length of d; the result
// has the length of d.
Vec3 reflect(const Vec3& d, const Vec3& n);

// Snell's law. d: unit incoming direction; n: unit normal on the incoming side (d.n <= 0);
// eta = n_incoming / n_outgoing. Writes the unit refracted direction and returns true, or
// returns false (leaving `refracted` alone) on total internal reflection.
bool refract(const Vec3& d, const Vec3& n, Real eta, Vec3& refracted);

// Schlick's approximation of the Fresnel reflectance for light going from index n1 into index
// n2, with cos_incident = cos of the angle between the incoming ray and the normal (>= 0).
// When n1 > n2 the cosine of the transmitted angle is used, and past the critical angle the
// result is 1 (total internal reflection). Always in [0, 1].
Real schlick_reflectance(Real cos_incident, Real n1, Real n2);

struct SecondaryRay {
    Ray ray;
    Color weight{0};  // what the colour seen along `ray` is multiplied by
    bool valid = false;
};

struct SecondaryRays {
    SecondaryRay reflected, refracted;
    bool total_internal_reflection = false;
};

// The reflected and refracted rays at `at` for the ray `incoming` that hit it.
//   weights: reflected k_r, refracted k_t. Entering (at.front_face) goes from index 1 into
//   material.ior, leaving goes from material.ior into 1 (nothing is nested: docs/conventions.md).
//   On total internal reflection there is no refracted ray and k_t is added to the reflected
//   weight. With `fresnel`, F = schlick_reflectance(...) moves F k_t from refraction to
//   reflection. So the two weights always sum to k_r + k_t: no energy is created.
//   A ray with zero weight is not valid. Make each ray with spawn_ray(at, n, direction)
//   (scene/surface_point.h): its origin is offset_ray_origin on the side it leaves to, its time
//   the incoming ray's.
SecondaryRays secondary_rays(const Ray& incoming, const SurfacePoint& at, const Material& material,
                             bool fresnel);

}  // namespace rt
