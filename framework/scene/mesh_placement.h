// Placing a triangle mesh in the scene (OBJ files and procedural meshes alike): scale, then
// translate, with normals and winding to match.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/real.h"

namespace rt {

// The normal `n` of a surface scaled by `scale` (per axis): normalize(n / scale), computed in
// double; the zero vector stays zero (it marks "no vertex normal", see Scene::normals).
Vec3 scale_normal(Vec3 n, Vec3 scale);

// Maps every vertex p to p * scale + translate and every normal n to scale_normal(n, scale); a
// scale that mirrors (an odd number of negative factors) also reverses each triangle's winding,
// so outward stays outward. The first vertex that is no longer finite is passed to `too_large`,
// which must throw.
void place_mesh(std::vector<Vec3>& vertices, std::vector<Vec3>& normals,
                std::vector<std::array<std::uint32_t, 3>>& triangles, Vec3 scale, Vec3 translate,
                const std::function<void(std::size_t vertex)>& too_large);

}  // namespace rt
