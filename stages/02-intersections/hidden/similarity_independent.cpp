// Not a test: a second, independent solution of this stage (geometric ray-sphere,
// Moller-Trumbore, other slab and nearest-hit code; it passes stage02_tests), the cohort member
// that grader/tests/similarity.sh must NOT flag against the reference. It lives in hidden/,
// which `rt-grade release` leaves out, so no starter tree ships a working solution.
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

// Ray-sphere. Solve |o + t d - c|^2 = r^2, a quadratic a t^2 + 2 b t + c = 0 with
//   a = d.d,  b = d.(o - c),  c = (o - c).(o - c) - r^2.
// Compute the roots without cancellation (handout section "A stable quadratic"), take the
// smallest root inside t_range, and fill hit (uv as described in stage02.h).
bool intersect_sphere(const Ray& ray, const Sphere& sphere, Interval t_range, Hit& hit) {
    // Geometric test: project the centre onto the ray, then step back along it by the half
    // chord. Works with the unnormalised direction by dividing by its length once.
    const Real len = glm::length(ray.direction);
    if (!std::isfinite(len) || len == 0) return false;
    const Vec3 unit = ray.direction / len;
    const Vec3 to_centre = sphere.center - ray.origin;
    const Real along = glm::dot(to_centre, unit);
    const Vec3 closest = to_centre - along * unit;  // perpendicular from the centre to the ray
    const Real r2 = sphere.radius * sphere.radius;
    const Real miss2 = glm::dot(closest, closest);
    if (miss2 > r2) return false;
    const Real half_chord = std::sqrt(r2 - miss2);
    for (const Real distance : {along - half_chord, along + half_chord}) {
        const Real param = distance / len;
        if (t_range.min < param && param < t_range.max) {
            hit.t = param;
            hit.point = ray.at(param);
            hit.set_face_normal(ray, (hit.point - sphere.center) / sphere.radius);
            hit.uv = Vec2(0);
            return true;
        }
    }
    return false;
}

// Ray-plane: the plane holds plane.point and has the unit normal plane.normal.
bool intersect_plane(const Ray& ray, const Plane& plane, Interval t_range, Hit& hit) {
    const Real facing = glm::dot(ray.direction, plane.normal);
    if (!(std::abs(facing) > 0) || std::isinf(facing)) return false;
    const Real param = glm::dot(plane.point - ray.origin, plane.normal) / facing;
    if (param <= t_range.min || param >= t_range.max) return false;
    hit.t = param;
    hit.point = ray.at(param);
    hit.set_face_normal(ray, plane.normal);
    hit.uv = Vec2(0);
    return true;
}

// Ray-triangle by Cramer's rule. With o the origin and d the direction, the hit point
// a + beta (b - a) + gamma (c - a) = o + t d is the linear system
//   [a-b  a-c  d] (beta, gamma, t)^T = a - o,
// solved by Cramer's rule: each unknown is a ratio of 3x3 determinants (handout section
// "Cramer's rule"). A determinant of three column vectors x, y, z is dot(x, cross(y, z)).
bool intersect_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c,
                        Interval t_range, Hit& hit) {
    // Moller-Trumbore: barycentrics from the triple products of the edges and the ray.
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 p = glm::cross(ray.direction, e2);
    const Real det = glm::dot(e1, p);
    if (!std::isfinite(det) || det == 0) return false;
    const Real inv = 1 / det;
    const Vec3 s = ray.origin - a;
    const Real u = inv * glm::dot(s, p);
    if (u < 0 || u > 1) return false;
    const Vec3 q = glm::cross(s, e1);
    const Real v = inv * glm::dot(ray.direction, q);
    if (v < 0 || u + v > 1) return false;
    const Real param = inv * glm::dot(e2, q);
    if (!t_range.contains(param)) return false;
    hit.t = param;
    hit.point = ray.at(param);
    hit.set_face_normal(ray, glm::normalize(glm::cross(e1, e2)));
    hit.uv = Vec2(u, v);
    return true;
}

// Ray-box by slabs: intersect the ray's t-interval with the three slabs
// box.min[i] <= o[i] + t d[i] <= box.max[i]. The result [t_near, t_far] is where the ray is
// inside the box; the hit is t_near if it lies in t_range, else t_far.
bool intersect_box(const Ray& ray, const Box& box, Interval t_range, Hit& hit) {
    if (!all_finite(ray.direction) || glm::dot(ray.direction, ray.direction) == 0) return false;
    const Vec3 inv = Vec3(1) / ray.direction;  // +-inf on an axis the ray is parallel to
    Vec3 lo = (box.min - ray.origin) * inv;
    Vec3 hi = (box.max - ray.origin) * inv;
    for (int k = 0; k < 3; ++k) {
        if (ray.direction[k] == 0) {  // 0 * inf is NaN: decide this axis by the origin alone
            if (ray.origin[k] < box.min[k] || ray.origin[k] > box.max[k]) return false;
            lo[k] = -kInfinity;
            hi[k] = kInfinity;
        }
    }
    const Vec3 enter = glm::min(lo, hi), leave = glm::max(lo, hi);
    const int in_axis =
        enter.x > enter.y ? (enter.x > enter.z ? 0 : 2) : (enter.y > enter.z ? 1 : 2);
    const int out_axis =
        leave.x < leave.y ? (leave.x < leave.z ? 0 : 2) : (leave.y < leave.z ? 1 : 2);
    const Real first = enter[in_axis], last = leave[out_axis];
    if (first > last) return false;
    const bool entering = t_range.contains(first);
    if (!entering && !t_range.contains(last)) return false;
    const int k = entering ? in_axis : out_axis;
    Vec3 face(0);
    face[k] = (ray.direction[k] > 0) == entering ? -1 : 1;
    hit.t = entering ? first : last;
    hit.point = ray.at(hit.t);
    hit.set_face_normal(ray, face);
    hit.uv = Vec2(0);
    return true;
}

// The nearest hit over every surface of the scene: spheres, planes, triangles, boxes.
// Shrink the range as you find hits, so each later test only accepts something nearer.
// On a hit also set hit.primitive = scene.primitive_id(kind, index) and hit.material.
// Take sphere i as scene.sphere_at(i, ray.time): in stage 10 some spheres move with time.
bool intersect_nearest(const Ray& ray, const Scene& scene, Interval t_range, Hit& hit) {
    Hit best;
    int best_kind = -1;
    std::size_t best_index = 0;
    int best_material = 0;
    Interval range = t_range;
    const auto keep = [&](const Hit& h, Scene::Kind kind, std::size_t i, int material) {
        best = h;
        range.max = h.t;
        best_kind = static_cast<int>(kind);
        best_index = i;
        best_material = material;
    };
    Hit h;
    for (std::size_t i = 0; i < scene.boxes.size(); ++i)
        if (intersect_box(ray, scene.boxes[i], range, h))
            keep(h, Scene::Kind::Box, i, scene.boxes[i].material);
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        Vec3 v0, v1, v2;
        scene.triangle_vertices(i, v0, v1, v2);
        if (intersect_triangle(ray, v0, v1, v2, range, h))
            keep(h, Scene::Kind::Triangle, i, scene.triangles[i].material);
    }
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
        if (intersect_plane(ray, scene.planes[i], range, h))
            keep(h, Scene::Kind::Plane, i, scene.planes[i].material);
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere moved = scene.sphere_at(i, ray.time);
        if (intersect_sphere(ray, moved, range, h)) keep(h, Scene::Kind::Sphere, i, moved.material);
    }
    if (best_kind < 0) return false;
    hit = best;
    hit.primitive = scene.primitive_id(static_cast<Scene::Kind>(best_kind), best_index);
    hit.material = best_material;
    return true;
}

}  // namespace rt
