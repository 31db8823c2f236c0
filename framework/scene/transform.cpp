// Affine transforms of surfaces (scene/transform.h).
#include "scene/transform.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/prepared_scene.h"

namespace rt {

glm::dmat4 axis_rotation(glm::dvec3 axis, double degrees) {
    return glm::rotate(glm::dmat4(1), glm::radians(degrees), glm::normalize(axis));
}

glm::dmat4 euler_rotation(glm::dvec3 degrees) {
    const glm::dmat4 rx = axis_rotation({1, 0, 0}, degrees.x);
    const glm::dmat4 ry = axis_rotation({0, 1, 0}, degrees.y);
    const glm::dmat4 rz = axis_rotation({0, 0, 1}, degrees.z);
    return rz * ry * rx;
}

glm::dmat3 normal_matrix(const glm::dmat4& m) {
    return glm::transpose(glm::inverse(glm::dmat3(m)));
}

double similarity_scale(const glm::dmat4& m) {
    const glm::dmat3 l(m);
    const glm::dmat3 gram = glm::transpose(l) * l;  // s^2 I for a similarity
    const double s2 = (gram[0][0] + gram[1][1] + gram[2][2]) / 3;
    if (!(s2 > 0)) return 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(gram[i][j] - (i == j ? s2 : 0)) > 1e-9 * s2) return 0;
    return std::sqrt(s2);
}

bool keeps_axes(const glm::dmat4& m) {
    const glm::dmat3 l(m);
    double largest = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) largest = std::max(largest, std::abs(l[i][j]));
    for (int column = 0; column < 3; ++column) {
        int nonzero = 0;
        for (int row = 0; row < 3; ++row)
            if (std::abs(l[column][row]) > 1e-12 * largest) ++nonzero;  // cos 90 deg is 6e-17
        if (nonzero != 1) return false;
    }
    return true;
}

Vec3 transform_point(const glm::dmat4& m, const Vec3& p) {
    return Vec3(glm::dvec3(m * glm::dvec4(glm::dvec3(p), 1)));
}

Vec3 transform_normal(const glm::dmat3& n, const Vec3& normal) {
    const glm::dvec3 w = n * glm::dvec3(normal);
    const double length = glm::length(w);
    if (!(length > 0) || !std::isfinite(length)) return Vec3(0);
    return Vec3(w / length);
}

Instance make_instance(const glm::dmat4& to_world, std::size_t object, int material) {
    Instance instance;
    instance.object_to_world = Mat4(to_world);
    instance.world_to_object = Mat4(glm::inverse(to_world));
    instance.object = object;
    instance.material = material;
    return instance;
}

Aabb instance_bounds(const Instance& instance, const Aabb& box) {
    const glm::dmat4 m(instance.object_to_world);
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                           corner & 4 ? box.max.z : box.min.z);
        const glm::dvec3 w(m * glm::dvec4(p, 1));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
    }
    // The object-space ray is the world ray rounded (to Real) through world_to_object: widen by a
    // margin far above that rounding, relative to the box's size and place.
    const double margin =
        1e-5 * (glm::length(hi - lo) + glm::length(glm::max(glm::abs(lo), glm::abs(hi))));
    const float inf = std::numeric_limits<float>::infinity();
    Aabb out;
    for (int k = 0; k < 3; ++k) {
        out.min[k] = std::nextafter(float(lo[k] - margin), -inf);
        out.max[k] = std::nextafter(float(hi[k] + margin), inf);
    }
    return out;
}

Vec3 object_point(const Instance& instance, const Vec3& p) {
    return Vec3(instance.world_to_object * glm::vec<4, Real>(p, 1));
}

Vec3 object_normal(const Instance& instance, const Vec3& n) {
    const Vec3 o = glm::transpose(glm::mat<3, 3, Real>(instance.object_to_world)) * n;
    const Real length = glm::length(o);
    return length > 0 ? o / length : o;
}

ObjectView object_view(const Scene& scene, const Ray& ray, const Hit& hit) {
    ObjectView view;
    std::size_t i = 0;
    if (!scene.is_primitive(hit.primitive) ||
        scene.primitive_kind(hit.primitive, i) != Scene::Kind::Instance)
        return view;
    view.instance = &scene.instances[i];
    view.object = scene.objects[view.instance->object].get();
    view.ray = object_ray(*view.instance, ray);
    view.hit = hit;
    view.hit.point = view.ray.at(hit.t);
    view.hit.normal = object_normal(*view.instance, hit.normal);
    view.hit.primitive = hit.object_primitive;
    view.hit.object_primitive = -1;
    return view;
}

}  // namespace rt
