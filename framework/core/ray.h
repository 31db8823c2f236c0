// Rays and ray parameter ranges (docs/conventions.md#rays-and-t-ranges).
#pragma once

#include "core/real.h"

namespace rt {

// A ray r(t) = origin + t * direction. Camera rays have unit-length directions, so t is a
// distance; other rays need not, and intersection code must not assume it.
struct Ray {
    Vec3 origin{0};
    Vec3 direction{0, 0, -1};
    // When the ray travels: the shutter time of its camera sample (stage 10's motion blur moves
    // spheres with it, Scene::sphere_at), 0 without motion blur. Rays spawned at a surface keep
    // the time of the ray that found it (spawn_ray in scene/surface_point.h).
    Real time = 0;

    Vec3 at(Real t) const { return origin + t * direction; }
};

// The open range of accepted ray parameters: a hit counts when min < t < max.
struct Interval {
    Real min = 0;
    Real max = kInfinity;

    bool contains(Real t) const { return min < t && t < max; }
};

}  // namespace rt
