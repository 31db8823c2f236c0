// The primary ray through an image point: stage 01's functions, chosen by the projection.
// In render/ because it calls student code (framework/README.md, "Trust boundary").
#pragma once

#include "camera/camera.h"
#include "scene/prepared_scene.h"

namespace rt {

// The primary ray through image point `pixel` (stage 01): dispatches on camera.projection.
Ray camera_ray(const Camera& camera, Vec2 pixel, ImageSize size);

// The pivot `rt view` and `rt export-web`'s page orbit about (camera/camera_moves.h): the distance
// to the surface under the image centre, else as far as the eye is from the origin.
Real orbit_pivot_distance(const PreparedScene& scene);

}  // namespace rt
