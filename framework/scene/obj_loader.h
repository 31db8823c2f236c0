// Reading triangle meshes from Wavefront OBJ files for "mesh" surfaces (docs/scene-format.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/real.h"

namespace rt {

// A mistake in an OBJ file. what() is one line, `<what is wrong>; <how to fix it>`, starting
// with `mesh "<name>"` and, where known, the OBJ line. The scene loader prefixes it with the
// scene file position of the mesh's "file" value.
class ObjError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ObjMesh {
    std::vector<Vec3> vertices;  // already scaled, then translated
    std::vector<std::array<std::uint32_t, 3>> triangles;
    // Per triangle: index into material_names of the OBJ `usemtl` in effect, or -1 for none.
    std::vector<int> triangle_material;
    std::vector<std::string> material_names;
};

// Loads `file` with tinyobjloader (polygons triangulated), then maps every vertex p to
// p * scale + translate. `display_name` is how messages name the file (as the scene wrote it).
// Throws ObjError for a missing or unreadable file, data tinyobjloader would drop or misread
// (face indices out of range, faces with fewer than 3 vertices, coordinates that are not finite
// numbers), no triangles at all, or more than `max_triangles` triangles.
ObjMesh load_obj(const std::filesystem::path& file, const std::string& display_name, Vec3 scale,
                 Vec3 translate, std::size_t max_triangles);

}  // namespace rt
