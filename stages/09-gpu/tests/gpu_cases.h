// Stage 09's GPU unit tests run the student's intersect_sphere, _plane, _triangle and _box
// (GLSL) on a batch of ray cases in a compute shader (tests/intersect_cases.comp). This is the
// host side both test files share: the case layout the shader reads and one dispatch.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "core/ray.h"
#include "scene/scene.h"

namespace rt::gpu_cases {

// One case, 6 vec4s as intersect_cases.comp reads them: origin and kind (its int bits: 0
// sphere, 1 plane, 2 triangle, 3 box), direction, t range (x min, y max), then the surface:
// a (sphere: centre, radius; plane: point; triangle: first vertex; box: min), b (plane:
// normal; triangle: second vertex; box: max), c (triangle: third vertex).
struct alignas(16) GpuRayCase {
    glm::vec4 origin_kind, direction, range, a, b, c;
};
static_assert(sizeof(GpuRayCase) == 96, "6 vec4s, as intersect_cases.comp reads them");

enum Kind { kSphere = 0, kPlane = 1, kTriangle = 2, kBox = 3 };

glm::vec4 g4(const Vec3& v, float w = 0);

// The case of `ray` against one surface (converted to float: the GPU computes in float).
GpuRayCase sphere_case(const Ray& ray, const Sphere& sphere, Interval range);
GpuRayCase plane_case(const Ray& ray, const Plane& plane, Interval range);
GpuRayCase triangle_case(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c,
                         Interval range);
GpuRayCase box_case(const Ray& ray, const Box& box, Interval range);

// What the shader answered for one case.
struct GpuAnswer {
    bool found = false;
    float t = 0;
    glm::vec3 normal{0};
    bool front_face = false;
};

// Compiles intersect_cases.comp with the student's GLSL (gpu_student_dir()), runs it on every
// case and returns the answers; a stub reached is reported as the renderer reports it (`not
// implemented: NAME (file:line); read ...`), which fails the StageTest. Returns false with
// `error` when no context or program could be made.
bool run_on_gpu(const std::vector<GpuRayCase>& cases, std::vector<GpuAnswer>& answers,
                std::string& error);

}  // namespace rt::gpu_cases
