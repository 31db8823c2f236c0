#include "scene/surface_point.h"

#include <algorithm>
#include <cmath>

#include "scene/prepared_scene.h"
#include "scene/transform.h"

namespace rt {
namespace {

Vec3 abs3(const Vec3& v) {
    return glm::abs(v);
}

// A point of an instance: refined on its object's primitive, mapped to the world. The mapping
// p = M q + m adds to q's error |M| e_q (1 + gamma(3)) and its own rounding gamma(3) (|M| |q| +
// |m|) (pbrt-v4's Transform of a point with error).
SurfacePoint instance_point(const Scene& scene, const Ray& ray, const Hit& hit) {
    const ObjectView view = object_view(scene, ray, hit);
    const SurfacePoint local = surface_point(*view.object, view.ray, view.hit);
    const Mat4& m = view.instance->object_to_world;
    glm::mat<3, 3, Real> absolute(m);
    for (int c = 0; c < 3; ++c) absolute[c] = abs3(absolute[c]);
    SurfacePoint sp{.point = Vec3(m * glm::vec<4, Real>(local.point, 1)),
                    .normal = hit.normal,
                    .front_face = hit.front_face,
                    .primitive = hit.primitive,
                    .material = hit.material,
                    .time = ray.time};
    sp.error = (1 + gamma_bound(3)) * (absolute * local.error) +
               gamma_bound(3) * (absolute * abs3(local.point) + abs3(Vec3(m[3])));
    return sp;
}

}  // namespace

SurfacePoint surface_point(const Scene& scene, const Ray& ray, const Hit& hit) {
    SurfacePoint sp{.point = hit.point,
                    .normal = hit.normal,
                    .front_face = hit.front_face,
                    .primitive = hit.primitive,
                    .material = hit.material,
                    .time = ray.time};
    if (!scene.is_primitive(hit.primitive)) {
        // Unknown primitive: the point as computed, with the error of o + t d.
        sp.error = gamma_bound(4) * (abs3(ray.origin) + abs3(hit.t * ray.direction));
        return sp;
    }
    std::size_t i = 0;
    switch (scene.primitive_kind(hit.primitive, i)) {
        case Scene::Kind::Sphere: {
            const Sphere s = scene.sphere_at(i, ray.time);
            const Vec3 from_center = hit.point - s.center;
            const Real length = glm::length(from_center);
            if (length > 0) sp.point = s.center + from_center * (s.radius / length);
            sp.error = gamma_bound(8) * (abs3(s.center) + abs3(sp.point - s.center));
            break;
        }
        case Scene::Kind::Plane: {
            const Plane& p = scene.planes[i];
            sp.point = hit.point - p.normal * glm::dot(p.normal, hit.point - p.point);
            // The signed distance d = n.(p - p0) is off by at most gamma(5) n.(|p| + |p0|); the
            // correction moves each coordinate by n_i d, and the subtraction rounds once more.
            const Real distance_error =
                gamma_bound(5) * glm::dot(abs3(p.normal), abs3(hit.point) + abs3(p.point));
            sp.error = abs3(p.normal) * distance_error + gamma_bound(2) * abs3(sp.point);
            break;
        }
        case Scene::Kind::Triangle: {
            Vec3 a, b, c;
            scene.triangle_vertices(i, a, b, c);
            const Real b1 = hit.uv.x, b2 = hit.uv.y, b0 = 1 - b1 - b2;
            sp.point = b0 * a + b1 * b + b2 * c;
            sp.error = gamma_bound(7) * (abs3(b0 * a) + abs3(b1 * b) + abs3(b2 * c));
            break;
        }
        case Scene::Kind::Box: {
            const Box& box = scene.boxes[i];
            const Vec3 outward = hit.front_face ? hit.normal : -hit.normal;
            int axis = 0;
            for (int k = 1; k < 3; ++k)
                if (std::abs(outward[k]) > std::abs(outward[axis])) axis = k;
            sp.point = glm::clamp(hit.point, box.min, box.max);
            sp.point[axis] = outward[axis] > 0 ? box.max[axis] : box.min[axis];
            sp.error = gamma_bound(3) * abs3(sp.point);
            sp.error[axis] = 0;
            break;
        }
        case Scene::Kind::Instance:
            return instance_point(scene, ray, hit);
    }
    return sp;
}

}  // namespace rt
