#include "geometry/offset.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

Real gamma_bound(int n) {
    constexpr Real u = std::numeric_limits<Real>::epsilon() / 2;
    return Real(n) * u / (1 - Real(n) * u);
}

namespace {

Vec3 abs3(const Vec3& v) {
    return glm::abs(v);
}

}  // namespace

Vec3 offset_ray_origin(const Vec3& point, const Vec3& error, const Vec3& normal,
                       const Vec3& direction) {
    const Real d = glm::dot(abs3(normal), error);
    Vec3 offset = d * normal;
    if (glm::dot(direction, normal) < 0) offset = -offset;
    Vec3 origin = point + offset;
    // The addition rounds: one more step away from the surface keeps the origin outside.
    for (int k = 0; k < 3; ++k) {
        if (offset[k] > 0)
            origin[k] = std::nextafter(origin[k], kInfinity);
        else if (offset[k] < 0)
            origin[k] = std::nextafter(origin[k], -kInfinity);
    }
    return origin;
}

}  // namespace rt
