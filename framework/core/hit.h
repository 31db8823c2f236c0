// What an intersection reports (docs/conventions.md#normals).
#pragma once

#include "core/ray.h"

namespace rt {

struct Hit {
    Real t = kInfinity;      // ray parameter of the hit
    Vec3 point{0};           // ray.at(t)
    Vec3 normal{0};          // unit length, always facing the side the ray came from
    bool front_face = true;  // the ray arrived on the side the outward normal points to
    Vec2 uv{0};              // surface coordinates; triangles: barycentrics (beta, gamma)
    int primitive = -1;      // global primitive id (Scene::primitive_id), -1 if none
    int material = -1;       // index into Scene::materials
    // When `primitive` is an instance (Scene::Kind::Instance): the primitive of its object that
    // was hit, an id of the object's own arrays. -1 otherwise.
    int object_primitive = -1;

    // Stores `outward_normal` (unit length, pointing out of the surface) turned to face the ray,
    // and records in front_face whether the ray hit the outside.
    void set_face_normal(const Ray& ray, const Vec3& outward_normal) {
        front_face = glm::dot(ray.direction, outward_normal) < 0;
        normal = front_face ? outward_normal : -outward_normal;
    }
};

}  // namespace rt
