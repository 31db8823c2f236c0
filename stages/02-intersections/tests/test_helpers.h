// Shared helpers of the stage 02 tests.
#pragma once

#include <cmath>
#include <limits>
#include <source_location>
#include <sstream>
#include <string>

#include "stage_api/stage02.h"
#include "testing/expect_near.h"
#include "testing/stage_test.h"

namespace rt::stage02 {

// Tolerance for closed-form checks of a few operations on values of order 1.
inline constexpr Real kTol = Real(1e-5);

using testing::expect_vec_near;
using testing::text;

// A hit record that no correct implementation writes, to detect writes on a miss.
inline Hit sentinel_hit() {
    Hit h;
    h.t = Real(-12345);
    h.point = Vec3(7);
    h.normal = Vec3(7);
    h.uv = Vec2(7);
    return h;
}

inline bool untouched(const Hit& h) {
    return h.t == Real(-12345) && h.point == Vec3(7) && h.normal == Vec3(7) && h.uv == Vec2(7);
}

// Directions no intersection may accept: zero, NaN, infinite.
inline const Vec3 kBadDirections[] = {Vec3(0), Vec3(std::numeric_limits<Real>::quiet_NaN(), 0, -1),
                                      Vec3(0, std::numeric_limits<Real>::infinity(), 0),
                                      Vec3(-std::numeric_limits<Real>::infinity(), 1, 1)};

}  // namespace rt::stage02
