// Affine transforms of surfaces (docs/scene-format.md#transforms-and-instances): composed in
// double, baked into a surface where the shape keeps its kind, applied to rays where it does not
// (instances, Scene::instances).
#pragma once

#include <glm/glm.hpp>

#include "accel/bvh.h"
#include "core/hit.h"
#include "core/ray.h"
#include "scene/scene.h"

namespace rt {

// A rotation by `degrees` about `axis` (right-hand rule; any non-zero length).
glm::dmat4 axis_rotation(glm::dvec3 axis, double degrees);
// Euler angles in degrees: about x first, then y, then z, all about the fixed world axes
// (Rz * Ry * Rx; docs/conventions.md#transforms).
glm::dmat4 euler_rotation(glm::dvec3 degrees);

// The inverse transpose of the linear part: what normals are multiplied by.
glm::dmat3 normal_matrix(const glm::dmat4& m);

// When the linear part of `m` is a rotation times a uniform scale (a similarity: a sphere stays a
// sphere), its scale factor (> 0); else 0.
double similarity_scale(const glm::dmat4& m);
// Whether the linear part of `m` maps each axis onto an axis (a scale, possibly mirrored, and
// quarter turns): an axis-aligned box stays one.
bool keeps_axes(const glm::dmat4& m);

// `m` applied to points, in double, rounded once to Real.
Vec3 transform_point(const glm::dmat4& m, const Vec3& p);
// A unit normal through normal_matrix, normalised; the zero vector stays zero.
Vec3 transform_normal(const glm::dmat3& n, const Vec3& normal);

// An instance of `object` placed by `to_world` (its inverse computed here, in double).
Instance make_instance(const glm::dmat4& to_world, std::size_t object, int material);

// The box around the world image of `box` (an object's bounds) under instance.object_to_world,
// conservative: rounded outwards and widened by a few float steps for the rounding of the ray
// mapped into the object.
Aabb instance_bounds(const Instance& instance, const Aabb& box);

// The ray as the instance's object sees it. The same t names the same point in both spaces.
inline Ray object_ray(const Instance& instance, const Ray& ray) {
    const Mat4& m = instance.world_to_object;
    return Ray{Vec3(m * glm::vec<4, Real>(ray.origin, 1)),
               Vec3(m * glm::vec<4, Real>(ray.direction, 0)), ray.time};
}

// A normal of the object (unit or not) in world space, by the inverse transpose, normalised.
inline Vec3 world_normal(const Instance& instance, const Vec3& n) {
    const Vec3 w = glm::transpose(glm::mat<3, 3, Real>(instance.world_to_object)) * n;
    const Real length = glm::length(w);
    return length > 0 ? w / length : w;
}

// A hit on an instance seen from inside its object: the object, the ray mapped into it, and the
// hit as the object's own (its primitive hit.object_primitive, its normal mapped back, the same
// t, uv and front_face). `object` is null when `hit` is not on an instance.
struct ObjectView {
    const Scene* object = nullptr;
    const Instance* instance = nullptr;
    Ray ray;
    Hit hit;
};
ObjectView object_view(const Scene& scene, const Ray& ray, const Hit& hit);

// A point of the world in the instance's object, and a world normal there (normalised).
Vec3 object_point(const Instance& instance, const Vec3& p);
Vec3 object_normal(const Instance& instance, const Vec3& n);

}  // namespace rt
