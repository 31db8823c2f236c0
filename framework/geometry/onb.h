// An orthonormal basis around a unit vector, for turning directions sampled about +z into
// world space (stage 10: cosine_ray). Duff et al., "Building an Orthonormal Basis, Revisited"
// (JCGT 2017): branch-free but for the sign, continuous everywhere except across n.z = 0.
#pragma once

#include <cmath>

#include "core/real.h"

namespace rt {

struct Onb {
    Vec3 t{1, 0, 0}, b{0, 1, 0}, n{0, 0, 1};  // right-handed: cross(t, b) = n

    // The world direction of `local` (x along t, y along b, z along n).
    Vec3 to_world(const Vec3& local) const { return local.x * t + local.y * b + local.z * n; }
    // The local coordinates of the world direction `world` (stage 11's shading frames).
    Vec3 to_local(const Vec3& world) const {
        return Vec3(glm::dot(world, t), glm::dot(world, b), glm::dot(world, n));
    }
};

inline Onb onb_around(const Vec3& n) {
    const Real sign = std::copysign(Real(1), n.z);
    const Real a = Real(-1) / (sign + n.z);
    const Real b = n.x * n.y * a;
    return Onb{Vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x),
               Vec3(b, sign + n.y * n.y * a, -n.y), n};
}

}  // namespace rt
