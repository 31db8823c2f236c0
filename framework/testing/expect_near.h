// Component-wise checks for the stage tests that say which case failed: `what` names the case
// (which corner, face, light), the values are printed in full, and a trace names the line of
// the call (failures inside a helper otherwise all point at the helper).
#pragma once

#include <gtest/gtest.h>

#include <source_location>
#include <string>

#include "core/ray.h"
#include "scene/scene.h"

namespace rt::testing {

std::string text(const Vec3& v);  // Color is the same type: "(r, g, b)"

void expect_vec_near(const Vec3& actual, const Vec3& expected, const std::string& what,
                     Real tol = Real(1e-5),
                     std::source_location where = std::source_location::current());

// Relative: the tolerance scales with the expected value's magnitude (when above 1).
enum class Scale { Absolute, Relative };
void expect_color_near(const Color& actual, const Color& expected, const std::string& what,
                       float tol = 1e-5f, Scale scale = Scale::Absolute,
                       std::source_location where = std::source_location::current());

}  // namespace rt::testing

// How GoogleTest prints the framework's vectors (Vec2, Vec3, Color, glm's float vectors) in any
// failure message: "(x, y, z)" as text() writes it, not "12-byte object <00-00 ...>". Found by
// argument-dependent lookup, so every test that includes this header (stage_test.h does) uses it.
namespace glm {
template <length_t L, class T, qualifier Q>
void PrintTo(const vec<L, T, Q>& v, std::ostream* out) {
    *out << "(";
    for (length_t i = 0; i < L; ++i) *out << (i ? ", " : "") << v[i];
    *out << ")";
}
}  // namespace glm
