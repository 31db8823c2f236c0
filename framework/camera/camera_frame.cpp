#include "camera/camera.h"

#include <cmath>

namespace rt {

Camera make_look_at_camera(Projection projection, Vec3 eye, Vec3 target, Vec3 up,
                           Real vertical_fov_degrees, Real view_height) {
    Camera camera;
    camera.projection = projection;
    camera.eye = eye;
    camera.w = glm::normalize(eye - target);
    camera.u = glm::normalize(glm::cross(up, camera.w));
    camera.v = glm::cross(camera.w, camera.u);
    camera.vertical_fov_degrees = vertical_fov_degrees;
    camera.view_height = view_height;
    return camera;
}

}  // namespace rt
