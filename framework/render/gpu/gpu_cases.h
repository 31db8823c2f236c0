// Stage 09's GPU unit tests run the student's intersect_sphere, _plane, _triangle and _box
// (GLSL) on a batch of ray cases in a compute shader (shaders/intersect_cases.comp). This is the
// host side: the case layout the shader reads, the answers it writes, and one dispatch.
//
// The builders are inline so that a grading judge (framework/remote/) can make cases without
// linking the GPU renderer; run_gpu_cases runs the student's GLSL, so in grading it is a call
// the judge sends to the worker (stage_api/calls.h, RT_GPU_CALLS).
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "core/ray.h"
#include "gpu/gpu_scene.h"
#include "scene/scene.h"

namespace rt {
namespace gpu_cases {

// One case, 6 vec4s as intersect_cases.comp reads them: origin and kind (its int bits: 0
// sphere, 1 plane, 2 triangle, 3 box), direction, t range (x min, y max), then the surface:
// a (sphere: centre, radius; plane: point; triangle: first vertex; box: min), b (plane:
// normal; triangle: second vertex; box: max), c (triangle: third vertex).
struct alignas(16) GpuRayCase {
    glm::vec4 origin_kind, direction, range, a, b, c;
};
static_assert(sizeof(GpuRayCase) == 96, "6 vec4s, as intersect_cases.comp reads them");

enum Kind { kSphere = 0, kPlane = 1, kTriangle = 2, kBox = 3 };

// The kind's name, for messages ("sphere case 17").
inline const char* kind_name(int kind) {
    static const char* const names[] = {"sphere", "plane", "triangle", "box"};
    return kind >= 0 && kind < 4 ? names[kind] : "unknown";
}

inline glm::vec4 g4(const Vec3& v, float w = 0) {
    return glm::vec4(float(v.x), float(v.y), float(v.z), w);
}

// The case of `ray` against one surface (converted to float: the GPU computes in float).
inline GpuRayCase ray_case(const Ray& ray, Kind kind, Interval range, glm::vec4 a, glm::vec4 b = {},
                           glm::vec4 c = {}) {
    return {g4(ray.origin, gpu::int_bits(kind)),
            g4(ray.direction),
            glm::vec4(float(range.min), float(range.max), 0, 0),
            a,
            b,
            c};
}
inline GpuRayCase sphere_case(const Ray& ray, const Sphere& sphere, Interval range) {
    return ray_case(ray, kSphere, range, g4(sphere.center, float(sphere.radius)));
}
inline GpuRayCase plane_case(const Ray& ray, const Plane& plane, Interval range) {
    return ray_case(ray, kPlane, range, g4(plane.point), g4(plane.normal));
}
inline GpuRayCase triangle_case(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c,
                                Interval range) {
    return ray_case(ray, kTriangle, range, g4(a), g4(b), g4(c));
}
inline GpuRayCase box_case(const Ray& ray, const Box& box, Interval range) {
    return ray_case(ray, kBox, range, g4(box.min), g4(box.max));
}

// What the shader answered for one case.
struct GpuAnswer {
    bool found = false;
    float t = 0;
    glm::vec3 normal{0};
    bool front_face = false;
    glm::vec2 uv{0};  // as Hit::uv: a triangle's (beta, gamma), (0, 0) on the other kinds
};

}  // namespace gpu_cases

// Compiles intersect_cases.comp with the student's GLSL (gpu_student_dir()), runs it on every
// case and returns the answers; a stub reached is reported as the renderer reports it (`not
// implemented: NAME (file:line); read ...`), which fails the StageTest. Returns false with
// `error` when no context or program could be made.
bool run_gpu_cases(const std::vector<gpu_cases::GpuRayCase>& cases,
                   std::vector<gpu_cases::GpuAnswer>& answers, std::string& error);

}  // namespace rt
