#include "render/camera_ray.h"

#include "stage_api/stage01.h"

namespace rt {

Ray camera_ray(const Camera& camera, Vec2 pixel, ImageSize size) {
    return camera.projection == Projection::Perspective ? perspective_ray(camera, pixel, size)
                                                        : orthographic_ray(camera, pixel, size);
}

}  // namespace rt
