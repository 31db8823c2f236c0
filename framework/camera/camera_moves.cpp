// Moving a camera (camera/camera_moves.h).
#include "camera/camera_moves.h"

#include <algorithm>
#include <cmath>

namespace rt {
namespace {

const Real kDegrees = Real(3.14159265358979323846 / 180.0);

// Rodrigues' rotation of v about the unit axis k.
Vec3 rotate(const Vec3& v, const Vec3& k, Real degrees) {
    const Real a = degrees * kDegrees, c = std::cos(a), s = std::sin(a);
    return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1 - c);
}

}  // namespace

void turn_camera(Camera& camera, double degrees) {
    const Real a = Real(degrees * 3.14159265358979323846 / 180.0);
    const Real c = std::cos(a), s = std::sin(a);
    const Vec3 u = c * camera.u + s * camera.w;
    const Vec3 w = c * camera.w - s * camera.u;
    camera.u = u;
    camera.w = w;
}

void orbit(Camera& camera, Real distance, const Vec3& up, Real yaw_degrees, Real pitch_degrees) {
    const Vec3 pivot = camera.eye - camera.w * distance;
    Vec3 offset = rotate(camera.eye - pivot, up, -yaw_degrees);
    const Vec3 right = glm::normalize(glm::cross(up, offset));
    const Vec3 pitched = rotate(offset, right, pitch_degrees);
    // Keep at least ~3 degrees from the up axis, where the look-at frame is undefined.
    if (std::abs(glm::dot(glm::normalize(pitched), up)) < Real(0.998)) offset = pitched;
    camera = make_look_at_camera(camera.projection, pivot + offset, pivot, up,
                                 camera.vertical_fov_degrees, camera.view_height);
}

void pan(Camera& camera, Real distance, Real right, Real up) {
    const Real height = camera.projection == Projection::Orthographic
                            ? camera.view_height
                            : 2 * distance * std::tan(camera.vertical_fov_degrees * kDegrees / 2);
    camera.eye += (camera.u * right + camera.v * up) * height;
}

void zoom(Camera& camera, Real& distance, Real factor) {
    if (camera.projection == Projection::Orthographic) {
        camera.view_height *= factor;
        return;
    }
    const Vec3 pivot = camera.eye - camera.w * distance;
    distance = std::max(distance * factor, Real(1e-3));
    camera.eye = pivot + camera.w * distance;
}

void set_projection(Camera& camera, Real distance, Projection projection) {
    if (camera.projection == projection) return;
    if (projection == Projection::Orthographic)
        camera.view_height = 2 * distance * std::tan(camera.vertical_fov_degrees * kDegrees / 2);
    else
        camera.vertical_fov_degrees = std::clamp(
            2 * std::atan(camera.view_height / (2 * distance)) / kDegrees, Real(1), Real(170));
    camera.projection = projection;
}

}  // namespace rt
