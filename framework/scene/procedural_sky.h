// The procedural sky (`"environment": {"sky": {...}}`, docs/scene-format.md#environment): a
// gradient from the horizon to the zenith, a ground colour below, and a sun disc, baked once on
// loading into a lat-long image of the texture table. So a scene needs no downloaded image, and
// the sky is looked up exactly like any lat-long file: by the student's stage 08 code on the CPU
// and by the GPU stage's, through the same buffers.
#pragma once

#include "image/image.h"
#include "scene/environment.h"
#include "scene/scene.h"

namespace rt {

struct SkyParameters {
    Color zenith{0.12f, 0.3f, 0.8f};         // straight up
    Color horizon{0.75f, 0.85f, 0.95f};      // at the horizon, from above
    Color ground{0.25f, 0.22f, 0.18f};       // everywhere below the horizon
    Vec3 sun_direction{0.5f, 0.6f, -0.62f};  // unit, towards the sun
    float sun_radius_degrees = 2;            // angular radius of the disc; 0: no sun
    Color sun{40.0f, 36.0f, 30.0f};          // radiance inside the disc
    int height = 256;                        // the baked image is 2 height x height texels
};

// The direction a lat-long (u, v) looks along: the inverse of stage 08's latlong_uv
// (docs/conventions.md#environment-maps), phi = 2 pi (u - 1/2), theta = pi v.
Vec3 latlong_direction(Real u, Real v);

// The radiance of the sky along the unit direction d (no filtering).
Color sky_radiance(const SkyParameters& sky, const Vec3& d);

// The sky baked at texel centres: the lat-long image 2 height x height.
Image bake_sky(const SkyParameters& sky);

// The mean radiance over all directions (each texel weighted by its solid angle) of the
// scene's environment images, times its intensity: the constant an "ambient" factor scales.
// Black without an environment.
Color mean_environment_radiance(const Scene& scene);

}  // namespace rt
