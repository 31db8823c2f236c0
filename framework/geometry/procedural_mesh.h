// Triangle meshes made in code, so that tests, scenes and the default benchmarks never depend on
// downloaded data. Every generator is deterministic (same arguments, same mesh, bit for bit, on
// every machine) and gives consistently oriented, counter-clockwise-from-outside triangles.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/real.h"

namespace rt {

struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<Vec3> normals;  // per vertex (same size as vertices), or empty
    std::vector<Vec2> uvs;      // per vertex (same size as vertices), or empty
};

// Generators throw std::invalid_argument for arguments out of range (negative or absurd counts,
// sizes that are not finite and positive).

// Icosahedron subdivided `subdivisions` times (0..kMaxIcosphereSubdivisions), projected onto the
// sphere: 20 * 4^s triangles, 10 * 4^s + 2 shared vertices, normals = position / radius, no uvs
// (a sphere cannot be unwrapped without a seam; use the sphere primitive for that).
TriangleMesh make_icosphere(int subdivisions, Real radius = 1);

// Torus around +y: `rings` segments around the main circle of radius R, `sides` around the tube
// of radius r (0 < r < R), both >= 3: 2 * rings * sides triangles. Normals and uvs
// (u = ring / rings, v = side / sides, both 0..1): the last ring and side repeat the first
// with identical coordinates, so the mesh is closed by position though not by vertex index.
TriangleMesh make_torus(int rings, int sides, Real major_radius = 1,
                        Real minor_radius = Real(0.35));

// A height field over [-1, 1]^2 in x and z, cells_x by cells_z cells (2 triangles each), heights
// from a seeded sum of sines and value noise, in [0, height]. Every triangle faces up (+y);
// normals are the area-weighted face normals around each vertex, uv = ((x + 1) / 2, (z + 1) / 2).
TriangleMesh make_terrain(int cells_x, int cells_z, std::uint64_t seed, Real height = Real(0.3));

// `count` independent random triangles with vertices in [-1, 1]^3, each of edge length around
// `size` (the worst case for a BVH: overlapping boxes of all orientations). Three vertices of
// its own per triangle, no normals or uvs (shading uses the geometric normal).
TriangleMesh make_triangle_soup(std::size_t count, std::uint64_t seed, Real size = Real(0.1));

// The most triangles a generator makes (the scene's own limit, docs/scene-format.md); larger
// requests throw std::invalid_argument instead of exhausting memory.
inline constexpr std::size_t kMaxProceduralTriangles = 20'000'000;
inline constexpr int kMaxIcosphereSubdivisions = 9;  // 5,242,880 triangles

// The names make_procedural_mesh knows, in a fixed order.
const std::vector<std::string>& procedural_shapes();

// The resolution make_procedural_mesh uses for `shape` and `min_triangles` (0 counts as 1):
//   icosphere: a = subdivisions, the smallest with 20 * 4^a >= min_triangles;
//   torus:     b = sides = max(3, ceil(sqrt(min_triangles / 4))), a = rings, the fewest (>= 3)
//              with 2 * a * b >= min_triangles (so about twice as many rings as sides);
//   terrain:   b = cells_z = ceil(sqrt(min_triangles / 2)), a = cells_x, the fewest with
//              2 * a * b >= min_triangles;
//   soup:      a = exactly min_triangles triangles.
// `triangles` is the count that resolution gives. Throws std::invalid_argument for an unknown
// shape or more than kMaxProceduralTriangles triangles asked for.
struct ProceduralResolution {
    int a = 0, b = 0;
    std::size_t triangles = 0;
};
ProceduralResolution procedural_resolution(std::string_view shape, std::size_t min_triangles);

// The generator named `shape` ("icosphere", "torus", "terrain", "soup") with the smallest
// resolution giving at least `min_triangles` triangles. Throws std::invalid_argument naming the
// known shapes for an unknown name.
TriangleMesh make_procedural_mesh(std::string_view shape, std::size_t min_triangles,
                                  std::uint64_t seed = 1);

}  // namespace rt
