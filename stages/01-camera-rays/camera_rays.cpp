// Stage 01: camera rays. Handout: stages/01-camera-rays/README.md
// Conventions (pixel centres, camera frame, units): docs/conventions.md
//
// You edit only this file. Tests: ctest --test-dir build -L stage01 --output-on-failure
// The camera frame is given: camera.u points right, camera.v up, and the camera looks along
// -camera.w. All three are unit length and mutually orthogonal.
#include <cmath>

#include "core/not_implemented.h"
#include "stage_api/stage01.h"

namespace rt {

// Perspective camera. The image plane sits at distance 1 in front of the eye; it spans the
// vertical field of view `camera.vertical_fov_degrees` from its top edge to its bottom edge, and
// its width follows from the aspect ratio size.width / size.height (square pixels).
// `pixel` is in pixel units: (0, 0) is the top-left corner of the image, y grows downwards.
// Return a ray from camera.eye through that point of the image plane, direction of unit length.
Ray perspective_ray(const Camera& camera, Vec2 pixel, ImageSize size) {
    // BEGIN SOLUTION
    const Real half_height = std::tan(glm::radians(camera.vertical_fov_degrees) / 2);
    const Real half_width = half_height * size.aspect();
    // Map the image point to [-1, 1] in both directions, +1 at the right and at the top.
    const Real s = 2 * pixel.x / Real(size.width) - 1;
    const Real t = 1 - 2 * pixel.y / Real(size.height);
    const Vec3 direction = s * half_width * camera.u + t * half_height * camera.v - camera.w;
    return Ray{camera.eye, glm::normalize(direction)};
    // STUB
    // RT_NOT_IMPLEMENTED("stages/01-camera-rays/README.md#perspective-rays");
    // (void)pixel; (void)size;
    // return Ray{camera.eye, Vec3(0)};
    // END SOLUTION
}

// Orthographic camera. The viewed rectangle is centred on camera.eye, lies in the plane spanned
// by camera.u and camera.v, is camera.view_height tall and as wide as the aspect ratio says.
// Return a ray starting on that rectangle at the image point, travelling along -camera.w.
Ray orthographic_ray(const Camera& camera, Vec2 pixel, ImageSize size) {
    // BEGIN SOLUTION
    const Real half_height = camera.view_height / 2;
    const Real half_width = half_height * size.aspect();
    const Real s = 2 * pixel.x / Real(size.width) - 1;
    const Real t = 1 - 2 * pixel.y / Real(size.height);
    const Vec3 origin = camera.eye + s * half_width * camera.u + t * half_height * camera.v;
    return Ray{origin, -camera.w};
    // STUB
    // RT_NOT_IMPLEMENTED("stages/01-camera-rays/README.md#orthographic-rays");
    // (void)pixel; (void)size;
    // return Ray{camera.eye, Vec3(0)};
    // END SOLUTION
}

}  // namespace rt
