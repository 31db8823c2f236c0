// What stage 02's exact-arithmetic tests share (cgal_exact_test.cpp: triangles and closed
// meshes; cgal_exact_shapes_test.cpp: spheres, boxes, planes, degenerate rays): the tolerance
// unit, the handout sections a failure points to, and how numbers and rays are printed.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "geometry/watertight.h"
#include "remote/call_each.h"
#include "stage_api/stage02.h"
#include "testing/exact_cases.h"
#include "testing/exact_reference.h"
#include "testing/stage_test.h"

namespace rt::exact_test {

using namespace rt::exact;

constexpr double kEps = std::numeric_limits<Real>::epsilon();
constexpr bool kFloat = std::is_same_v<Real, float>;

// Where a failure sends the student: the handout section on what went wrong.
constexpr const char* kReadSphere = "read stages/02-intersections/README.md#a-stable-quadratic";
constexpr const char* kReadTriangle =
    "read stages/02-intersections/README.md#ray-triangle-cramers-rule";
constexpr const char* kReadBox = "read stages/02-intersections/README.md#ray-box-slabs";
constexpr const char* kReadPlane = "read stages/02-intersections/README.md#ray-plane";
constexpr const char* kReadRanges = "read docs/conventions.md#rays-and-t-ranges";

inline std::string text(const Vec3& v) {
    std::ostringstream out;
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}
// Numbers in messages: a ratio or a size to 3 significant digits, a t to 9.
inline std::string few(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", x);
    return buffer;
}
inline std::string digits(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", x);
    return buffer;
}
inline std::string text(const Ray& ray) {
    return "ray o " + text(ray.origin) + " d " + text(ray.direction);
}
inline const char* hit_or_miss(bool hit) {
    return hit ? "a hit" : "a miss";
}

inline double length(const Vec3& v) {
    return std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
}

using TriangleFn = bool (*)(const Ray&, const Vec3&, const Vec3&, const Vec3&, Interval, Hit&);
struct Method {
    const char* name;
    TriangleFn fn;
};
inline const Method kMethods[2] = {{"Cramer", &intersect_triangle},
                                   {"watertight", &intersect_triangle_watertight}};

}  // namespace rt::exact_test
