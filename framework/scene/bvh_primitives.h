// What a BVH over a scene is built from: one BvhPrimitive per bounded primitive. It lives with the
// scene, which the BVH itself (accel/) knows nothing of.
#pragma once

#include "accel/bvh.h"
#include "scene/scene.h"

namespace rt {

// Spheres, triangles and boxes of `scene` (planes are unbounded and stay out), in primitive id
// order. Boxes are conservative in float whatever Real is: a coordinate that does not convert
// exactly is rounded outwards, and sphere bounds get one extra float step for the rounding of
// centre +- radius.
std::vector<BvhPrimitive> bvh_primitives(const Scene& scene);

}  // namespace rt
