// Stage 01 (camera rays): the functions students write in stages/01-camera-rays/camera_rays.cpp.
// Handout: stages/01-camera-rays/README.md. Conventions: docs/conventions.md.
#pragma once

#include "camera/camera.h"

namespace rt {

// The primary ray of a perspective camera through image point `pixel`.
//   pixel: in pixel units; (0, 0) is the top-left corner of the image, x grows to the right,
//          y grows downwards, and the centre of pixel (i, j) is (i + 0.5, j + 0.5).
//   Returns: origin = camera.eye, direction of unit length.
Ray perspective_ray(const Camera& camera, Vec2 pixel, ImageSize size);

// The primary ray of an orthographic camera through image point `pixel` (same units as above).
//   Returns: origin on the plane through camera.eye spanned by u and v, direction = -camera.w.
Ray orthographic_ray(const Camera& camera, Vec2 pixel, ImageSize size);

}  // namespace rt
