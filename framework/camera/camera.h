// Cameras (docs/conventions.md#camera). The framework builds the orthonormal frame from the
// look-at description; stage 01 turns an image point into a primary ray.
#pragma once

#include "core/ray.h"

namespace rt {

enum class Projection { Perspective, Orthographic };

struct ImageSize {
    int width = 0;
    int height = 0;
    Real aspect() const { return Real(width) / Real(height); }
};

struct Camera {
    Projection projection = Projection::Perspective;
    Vec3 eye{0, 0, 0};
    // Right-handed orthonormal frame: u points right, v up, w backwards (the camera looks
    // along -w), exactly as in Shirley & Marschner, "Fundamentals of Computer Graphics".
    Vec3 u{1, 0, 0}, v{0, 1, 0}, w{0, 0, 1};
    Real vertical_fov_degrees = 45;  // perspective: full vertical opening angle
    Real view_height = 2;            // orthographic: height of the viewed rectangle, world units
};

// Builds a camera at `eye` looking at `target`, with `up` giving the upward direction.
// Precondition: eye != target and up not parallel to (target - eye); the scene loader checks it.
Camera make_look_at_camera(Projection projection, Vec3 eye, Vec3 target, Vec3 up,
                           Real vertical_fov_degrees, Real view_height);

// Moving a camera (turn, orbit, pan, zoom, projection): camera/camera_moves.h.

// The primary ray through a pixel calls stage 01's code: render/camera_ray.h.

}  // namespace rt
