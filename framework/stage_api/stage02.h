// Stage 02 (intersections): the functions students write in stages/02-intersections/.
// Handout: stages/02-intersections/README.md. Conventions: docs/conventions.md.
//
// Every function below shares one contract:
//   - accept a hit only when t_range.min < t < t_range.max (open interval);
//   - on a hit, fill hit.t, hit.point (= ray.at(t)), hit.normal and hit.front_face (through
//     hit.set_face_normal with the unit outward normal), hit.uv where stated, and return true;
//   - on a miss, return false and leave `hit` untouched;
//   - the ray direction need not be unit length, and may be zero, NaN or infinite: such a
//     ray hits nothing (return false), it must never crash.
#pragma once

#include "core/hit.h"
#include "scene/scene.h"

namespace rt {

// Ray-sphere by the quadratic formula, in a numerically stable form (no cancellation).
// hit.uv = (0, 0): a sphere's texture coordinates are stage 07's sphere_texcoord, computed only
// at the hit that is shaded, and only when its material has a texture.
bool intersect_sphere(const Ray& ray, const Sphere& sphere, Interval t_range, Hit& hit);

// Ray-plane. A ray parallel to the plane (including one lying in it) misses.
// The outward normal is plane.normal. hit.uv = (0, 0).
bool intersect_plane(const Ray& ray, const Plane& plane, Interval t_range, Hit& hit);

// Ray-triangle by Cramer's rule: solve [a-b, a-c, d] (beta, gamma, t)^T = a - o.
// Hit when beta >= 0, gamma >= 0, beta + gamma <= 1. The outward normal is
// normalize(cross(b - a, c - a)) (counter-clockwise seen from the front). hit.uv = (beta, gamma).
bool intersect_triangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c,
                        Interval t_range, Hit& hit);

// Ray-axis-aligned box by slabs. The outward normal is that of the face hit (the entry face,
// or the exit face when the ray starts inside). hit.uv = (0, 0).
bool intersect_box(const Ray& ray, const Box& box, Interval t_range, Hit& hit);

// The nearest hit among all surfaces of the scene within t_range. Also fills hit.primitive
// (Scene::primitive_id) and hit.material. Spheres are tested as scene.sphere_at(i, ray.time),
// where the ray meets them (stage 10's motion blur moves some; the others are spheres[i]).
bool intersect_nearest(const Ray& ray, const Scene& scene, Interval t_range, Hit& hit);

}  // namespace rt
