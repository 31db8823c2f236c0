#include "geometry/height_grid.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/glm.hpp>

namespace rt {

TriangleMesh make_height_grid(std::size_t columns, std::size_t rows,
                              const std::vector<double>& heights) {
    using D3 = glm::dvec3;
    std::vector<D3> points;
    points.reserve(columns * rows);
    for (std::size_t k = 0; k < rows; ++k)
        for (std::size_t i = 0; i < columns; ++i)
            points.emplace_back(-1 + 2 * double(i) / double(columns - 1), heights[k * columns + i],
                                -1 + 2 * double(k) / double(rows - 1));
    auto index = [&](std::size_t i, std::size_t k) { return std::uint32_t(k * columns + i); };

    TriangleMesh mesh;
    mesh.triangles.reserve(2 * (columns - 1) * (rows - 1));
    // Seen from above (+y), x to the right and z towards the viewer, (x0, z0) -> (x0, z1) ->
    // (x1, z0) is counter-clockwise, so every triangle faces up.
    for (std::size_t k = 0; k + 1 < rows; ++k)
        for (std::size_t i = 0; i + 1 < columns; ++i) {
            const std::uint32_t a = index(i, k), b = index(i, k + 1), c = index(i + 1, k),
                                d = index(i + 1, k + 1);
            mesh.triangles.push_back({a, b, c});
            mesh.triangles.push_back({c, b, d});
        }
    // Vertex normals: the area-weighted average of the faces around each vertex.
    std::vector<D3> sums(points.size(), D3(0));
    for (const auto& [a, b, c] : mesh.triangles) {
        const D3 n = glm::cross(points[b] - points[a], points[c] - points[a]);
        sums[a] += n;
        sums[b] += n;
        sums[c] += n;
    }
    mesh.vertices.reserve(points.size());
    mesh.normals.reserve(points.size());
    mesh.uvs.reserve(points.size());
    for (std::size_t k = 0; k < rows; ++k)
        for (std::size_t i = 0; i < columns; ++i) {
            const std::size_t v = index(i, k);
            const D3& p = points[v];
            const double length = glm::length(sums[v]);
            const D3 n = length > 0 ? sums[v] / length : D3(0, 1, 0);
            mesh.vertices.push_back(Vec3(Real(p.x), Real(p.y), Real(p.z)));
            mesh.normals.push_back(Vec3(Real(n.x), Real(n.y), Real(n.z)));
            mesh.uvs.push_back(
                Vec2(Real(double(i) / double(columns - 1)), Real(double(k) / double(rows - 1))));
        }
    return mesh;
}

TriangleMesh make_heightfield(int width, int height, const std::vector<float>& values,
                              double height_scale) {
    if (width < 2 || height < 2)
        throw std::invalid_argument("a height map needs at least 2 x 2 pixels, got " +
                                    std::to_string(width) + " x " + std::to_string(height));
    if (!std::isfinite(height_scale) || height_scale < 0)
        throw std::invalid_argument("the height must be a finite number >= 0");
    std::vector<double> heights(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) heights[i] = double(values[i]) * height_scale;
    return make_height_grid(std::size_t(width), std::size_t(height), heights);
}

}  // namespace rt
