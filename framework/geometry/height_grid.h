// Height fields as triangle meshes: a grid of heights over [-1, 1] in x and z, y up. Used by the
// procedural terrain (procedural_mesh.h) and by height maps read from a grey-scale image (the
// scene file's "heightfield" meshes, docs/scene-format.md#meshes).
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/procedural_mesh.h"

namespace rt {

// A columns x rows grid (both >= 2) of heights, row-major, row 0 at z = -1 (the far edge seen
// from +z), column 0 at x = -1: two triangles per cell, all facing up (+y), area-weighted vertex
// normals, uv = (column / (columns - 1), row / (rows - 1)), so an image draped on it with the
// same rows lies as the height map does.
TriangleMesh make_height_grid(std::size_t columns, std::size_t rows,
                              const std::vector<double>& heights);

// A height map: one vertex per pixel of a grey-scale image of `width` x `height` pixels
// (`values` row-major from the top, each in [0, 1], as stored: height maps are data), y = value *
// `height_scale`. Throws std::invalid_argument for an image smaller than 2 x 2 or a scale that
// is not finite and >= 0.
TriangleMesh make_heightfield(int width, int height, const std::vector<float>& values,
                              double height_scale);

}  // namespace rt
