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

void turn_camera(Camera& camera, double degrees) {
    const Real a = Real(degrees * 3.14159265358979323846 / 180.0);
    const Real c = std::cos(a), s = std::sin(a);
    const Vec3 u = c * camera.u + s * camera.w;
    const Vec3 w = c * camera.w - s * camera.u;
    camera.u = u;
    camera.w = w;
}

}  // namespace rt
