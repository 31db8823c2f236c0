// Stage 02: ray-surface intersections. Handout: stages/02-intersections/README.md
// Conventions (t-ranges, normal orientation, triangle winding): docs/conventions.md
//
// You edit only this file. Tests: ctest --test-dir build -L stage02 --output-on-failure
// The contract shared by every function here is written at the top of
// framework/stage_api/stage02.h: open t-range, set_face_normal, leave `hit` alone on a miss, and
// never crash on a zero, NaN or infinite direction (report a miss).
#include <algorithm>
#include <cmath>

#include "core/not_implemented.h"
#include "stage_api/stage02.h"

namespace rt {

// Ray-sphere with centre p and radius r. Solve |o + t d - p|^2 = r^2, a quadratic
// a t^2 + 2 b t + c = 0 with  a = d.d,  b = d.(o - p),  c = (o - p).(o - p) - r^2.
// Compute the roots without cancellation (handout section "A stable quadratic"), take the
// smallest root inside t_range, and fill hit (uv as described in stage02.h).
bool intersect_sphere(const Ray& ray, const Sphere& sphere, Interval t_range, Hit& hit) {
    // BEGIN SOLUTION
    const Vec3 oc = ray.origin - sphere.center;
    const Vec3& d = ray.direction;
    const Real a = glm::dot(d, d);
    if (!(a > 0) || !std::isfinite(a)) return false;  // zero, NaN or infinite direction
    const Real half_b = glm::dot(oc, d);
    const Real c = glm::dot(oc, oc) - sphere.radius * sphere.radius;
    // b^2 - a c written as a (r^2 - |l|^2), with l the vector from the centre to the point of
    // the ray closest to it: no cancellation when the sphere is small and far away.
    const Vec3 l = oc - (half_b / a) * d;
    const Real discriminant = a * (sphere.radius * sphere.radius - glm::dot(l, l));
    if (discriminant < 0) return false;
    // q has the sign of -half_b, so half_b + sign * sqrt never cancels.
    const Real q = -(half_b + std::copysign(std::sqrt(discriminant), half_b));
    Real t0 = q / a;
    Real t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    Real t = t0;
    if (!t_range.contains(t)) {
        t = t1;
        if (!t_range.contains(t)) return false;
    }
    hit.t = t;
    hit.point = ray.at(t);
    const Vec3 outward = (hit.point - sphere.center) / sphere.radius;
    hit.set_face_normal(ray, outward);
    hit.uv = Vec2(0);  // a texture's (u, v) are stage 07's, at the one hit that is shaded
    return true;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/02-intersections/README.md#ray-sphere");
    // (void)ray; (void)sphere; (void)t_range; (void)hit;
    // return false;
    // END SOLUTION
}

// Ray-plane: the plane holds plane.point and has the unit normal plane.normal.
bool intersect_plane(const Ray& ray, const Plane& plane, Interval t_range, Hit& hit) {
    // BEGIN SOLUTION
    const Real denominator = glm::dot(plane.normal, ray.direction);
    // Parallel rays (denominator 0) miss, and so do NaN or infinite directions.
    if (denominator == 0 || !std::isfinite(denominator)) return false;
    const Real t = glm::dot(plane.normal, plane.point - ray.origin) / denominator;
    if (!t_range.contains(t)) return false;
    hit.t = t;
    hit.point = ray.at(t);
    hit.set_face_normal(ray, plane.normal);
    hit.uv = Vec2(0);
    return true;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/02-intersections/README.md#ray-plane");
    // (void)ray; (void)plane; (void)t_range; (void)hit;
    // return false;
    // END SOLUTION
}

// Ray-triangle by Cramer's rule. With o the origin and d the direction, the hit point
// a + beta (b - a) + gamma (c - a) = o + t d is the linear system
//   [a-b  a-c  d] (beta, gamma, t)^T = a - o,
// solved by Cramer's rule: each unknown is a ratio of 3x3 determinants (handout section
// "Cramer's rule"). A determinant of three column vectors x, y, z is dot(x, cross(y, z)).
bool intersect_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c,
                        Interval t_range, Hit& hit) {
    // BEGIN SOLUTION
    const Vec3 col1 = a - b;
    const Vec3 col2 = a - c;
    const Vec3& col3 = ray.direction;
    const Vec3 rhs = a - ray.origin;
    const Real det_m = glm::dot(col1, glm::cross(col2, col3));
    // det_m == 0: the ray is parallel to the triangle's plane (or the triangle is degenerate).
    if (det_m == 0 || !std::isfinite(det_m)) return false;
    const Real t = glm::dot(col1, glm::cross(col2, rhs)) / det_m;
    if (!t_range.contains(t)) return false;
    const Real gamma = glm::dot(col1, glm::cross(rhs, col3)) / det_m;
    if (gamma < 0 || gamma > 1) return false;
    const Real beta = glm::dot(rhs, glm::cross(col2, col3)) / det_m;
    if (beta < 0 || beta > 1 - gamma) return false;
    hit.t = t;
    hit.point = ray.at(t);
    hit.set_face_normal(ray, glm::normalize(glm::cross(b - a, c - a)));
    hit.uv = Vec2(beta, gamma);
    return true;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/02-intersections/README.md#ray-triangle-cramers-rule");
    // (void)ray; (void)a; (void)b; (void)c; (void)t_range; (void)hit;
    // return false;
    // END SOLUTION
}

// Ray-box by slabs: intersect the ray's t-interval with the three slabs
// box.min[i] <= o[i] + t d[i] <= box.max[i]. The result [t_near, t_far] is where the ray is
// inside the box; the hit is t_near if it lies in t_range, else t_far.
bool intersect_box(const Ray& ray, const Box& box, Interval t_range, Hit& hit) {
    // BEGIN SOLUTION
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    if (!all_finite(d) || d == Vec3(0)) return false;
    Real t_near = -kInfinity, t_far = kInfinity;
    int near_axis = -1, far_axis = -1;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0) {
            // Parallel to this slab: inside it for every t, or never.
            if (o[i] < box.min[i] || o[i] > box.max[i]) return false;
            continue;
        }
        Real t0 = (box.min[i] - o[i]) / d[i];
        Real t1 = (box.max[i] - o[i]) / d[i];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > t_near) {
            t_near = t0;
            near_axis = i;
        }
        if (t1 < t_far) {
            t_far = t1;
            far_axis = i;
        }
    }
    if (t_near > t_far) return false;
    Real t;
    int axis;
    Real sign;  // the outward normal is sign * e_axis
    if (t_range.contains(t_near)) {
        // entered through this face
        t = t_near;
        axis = near_axis;
        sign = d[axis] > 0 ? -1 : 1;
    } else if (t_range.contains(t_far)) {
        // leaving through this face
        t = t_far;
        axis = far_axis;
        sign = d[axis] > 0 ? 1 : -1;
    } else {
        return false;
    }
    Vec3 outward(0);
    outward[axis] = sign;
    hit.t = t;
    hit.point = ray.at(t);
    hit.set_face_normal(ray, outward);
    hit.uv = Vec2(0);
    return true;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/02-intersections/README.md#ray-box-slabs");
    // (void)ray; (void)box; (void)t_range; (void)hit;
    // return false;
    // END SOLUTION
}

// The nearest hit over every surface of the scene: spheres, planes, triangles, boxes.
// Shrink the range as you find hits, so each later test only accepts something nearer.
// On a hit also set hit.primitive = scene.primitive_id(kind, index) and hit.material.
// Take sphere i as scene.sphere_at(i, ray.time): in stage 10 some spheres move with time.
bool intersect_nearest(const Ray& ray, const Scene& scene, Interval t_range, Hit& hit) {
    // BEGIN SOLUTION
    bool found = false;
    auto record = [&](Scene::Kind kind, std::size_t index, int material) {
        found = true;
        t_range.max = hit.t;
        hit.primitive = scene.primitive_id(kind, index);
        hit.material = material;
    };
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere sphere = scene.sphere_at(i, ray.time);
        if (intersect_sphere(ray, sphere, t_range, hit))
            record(Scene::Kind::Sphere, i, sphere.material);
    }
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
        if (intersect_plane(ray, scene.planes[i], t_range, hit))
            record(Scene::Kind::Plane, i, scene.planes[i].material);
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        Vec3 a, b, c;
        scene.triangle_vertices(i, a, b, c);
        if (intersect_triangle(ray, a, b, c, t_range, hit))
            record(Scene::Kind::Triangle, i, scene.triangles[i].material);
    }
    for (std::size_t i = 0; i < scene.boxes.size(); ++i)
        if (intersect_box(ray, scene.boxes[i], t_range, hit))
            record(Scene::Kind::Box, i, scene.boxes[i].material);
    return found;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/02-intersections/README.md#nearest-hit");
    // (void)ray; (void)scene; (void)t_range; (void)hit;
    // return false;
    // END SOLUTION
}

}  // namespace rt
