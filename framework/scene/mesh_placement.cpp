// Placing a triangle mesh in the scene (scene/mesh_placement.h).
#include "scene/mesh_placement.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace rt {

Vec3 scale_normal(Vec3 n, Vec3 scale) {
    glm::dvec3 scaled = glm::dvec3(n) / glm::dvec3(scale);
    double length = glm::length(scaled);
    if (!(length > 0) || !std::isfinite(length)) return Vec3(0);
    scaled /= length;
    return Vec3(Real(scaled.x), Real(scaled.y), Real(scaled.z));
}

void place_mesh(std::vector<Vec3>& vertices, std::vector<Vec3>& normals,
                std::vector<std::array<std::uint32_t, 3>>& triangles, Vec3 scale, Vec3 translate,
                const std::function<void(std::size_t vertex)>& too_large) {
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        Vec3& p = vertices[i];
        p = p * scale + translate;
        if (!all_finite(p)) {
            too_large(i);
            throw std::logic_error("place_mesh: too_large returned");  // it is meant to throw
        }
    }
    for (Vec3& n : normals) n = scale_normal(n, scale);
    if (scale.x * scale.y * scale.z < 0)  // mirrored: keep the outward side outward
        for (auto& t : triangles) std::swap(t[1], t[2]);
}

}  // namespace rt
