// The primary ray through an image point: stage 01's functions, chosen by the projection.
// In render/ because it calls student code (framework/README.md, "Trust boundary").
#pragma once

#include "camera/camera.h"

namespace rt {

// The primary ray through image point `pixel` (stage 01): dispatches on camera.projection.
Ray camera_ray(const Camera& camera, Vec2 pixel, ImageSize size);

}  // namespace rt
