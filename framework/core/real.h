// The scalar type and vector types used everywhere in the framework and the stages.
//
// `Real` is chosen in exactly one place: float by default, double when the project is configured
// with -DRT_DOUBLE=ON (the `double` preset), so the accuracy lab can compare both precisions.
// Conventions for coordinates, units and colours: docs/conventions.md.
#pragma once

#include <glm/glm.hpp>
#include <limits>

namespace rt {

#ifdef RT_DOUBLE
using Real = double;
#else
using Real = float;
#endif

using Vec2 = glm::vec<2, Real>;
using Vec3 = glm::vec<3, Real>;
using Color = glm::vec3;  // linear RGB, always float: colours do not need double precision

inline constexpr Real kInfinity = std::numeric_limits<Real>::infinity();
inline constexpr Real kPi = Real(3.14159265358979323846);

// True when every component is a finite number (not NaN, not +-Inf).
template <int N, typename T>
bool all_finite(const glm::vec<N, T>& v) {
    for (int i = 0; i < N; ++i)
        if (!(v[i] - v[i] == T(0))) return false;  // NaN and Inf both fail x - x == 0
    return true;
}

}  // namespace rt
