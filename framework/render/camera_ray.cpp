#include "render/camera_ray.h"

#include <cmath>

#include "render/accelerate.h"
#include "render/nearest_hit.h"
#include "stage_api/stage01.h"

namespace rt {

Ray camera_ray(const Camera& camera, Vec2 pixel, ImageSize size) {
    return camera.projection == Projection::Perspective ? perspective_ray(camera, pixel, size)
                                                        : orthographic_ray(camera, pixel, size);
}

Real orbit_pivot_distance(const PreparedScene& scene) {
    const Ray ray = camera_ray(
        scene.camera, Vec2(Real(scene.image.width) / 2, Real(scene.image.height) / 2), scene.image);
    Hit hit;
    if (nearest_hit(scene, ray, Interval{0, kInfinity}, hit) && std::isfinite(hit.t) && hit.t > 0)
        return hit.t;
    const Real from_origin = glm::length(scene.camera.eye);
    return from_origin > Real(1e-3) ? from_origin : Real(5);
}

}  // namespace rt
