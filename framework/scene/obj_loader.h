// Reading triangle meshes from Wavefront OBJ files (and their MTL material libraries) for "mesh"
// surfaces (docs/scene-format.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/real.h"
#include "geometry/procedural_mesh.h"
#include "scene/mesh_placement.h"  // scale_normal, used with meshes
#include "scene/scene.h"

namespace rt {

// A mistake in an OBJ or MTL file. what() is one line, `<what is wrong>; <how to fix it>`,
// starting with `mesh "<name>"` and, where known, the OBJ line (`mesh "m.obj" line 7: ...`) or
// the MTL file and line (`mesh "m.obj": "m.mtl" line 3: ...`). The scene loader prefixes it with
// the scene file position of the mesh's "file" value.
class ObjError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// One `usemtl` name of an OBJ file.
// An image map of an MTL material (map_Kd, map_Ks, map_Ke, norm or map_Bump) and its options.
struct ObjTextureMap {
    std::filesystem::path file;  // resolved against the .mtl file's folder; empty: no map
    float scale[2] = {1, 1};     // -s u v
    float offset[2] = {0, 0};    // -o u v
    bool clamp = false;          // -clamp on
};

struct ObjMaterial {
    std::string name;      // as written after usemtl
    std::size_t line = 0;  // the OBJ line of its first usemtl
    bool defined = false;  // found in one of the file's mtllib libraries (and then read)
    Material material;     // its MTL definition when `defined` (`material.name` left empty)
    // Its maps, in the order of Material's slots: diffuse, specular, emissive, normal. The scene
    // loader turns them into textures (docs/scene-format.md#materials-from-mtl-files).
    ObjTextureMap maps[4];
};

// The mesh (geometry/procedural_mesh.h's TriangleMesh) and what OBJ adds to it. In the mesh: one
// vertex per distinct (position, normal, uv) combination the faces use, in order of first use (OBJ
// indexes the three separately, a renderer wants one index per corner); positions already scaled,
// then translated; normals and uvs parallel to the vertices, or empty when no face has a `vn` or
// a `vt` (unit normals, (0, 0, 0) or uv (0, 0) for a corner without one); triangles
// counter-clockwise from outside.
struct ObjMesh : TriangleMesh {
    // Per triangle: index into `materials` of the usemtl in effect, or -1 for none.
    std::vector<int> triangle_material;
    std::vector<ObjMaterial> materials;  // distinct usemtl names, first use first
    bool has_mtllib = false;             // the file names at least one material library
    // Harmless oddities that were worked around, one line each (`mesh "<name>" line N: ...`),
    // e.g. faces naming texture coordinates in a file with no "vt" line at all.
    std::vector<std::string> warnings;
};

// Decides whether the scene itself supplies the material for a usemtl name (then the .mtl
// definition is neither needed nor read).
using SceneMaterialLookup = std::function<bool(const std::string& usemtl_name)>;

// Loads `file` with tinyobjloader (polygons triangulated), then places it with place_mesh: every
// vertex p becomes p * scale + translate and every normal n normalize(n / scale); a scale that
// mirrors (an odd number of negative factors) also reverses each triangle's winding.
// `display_name` is how messages name the file (as the scene wrote it).
//
// Materials: for every usemtl name that `scene_has` does not claim, the file's mtllib libraries
// (relative to the OBJ's folder) are read and must define it; names in a file without any mtllib
// line are left undefined (the scene then uses the surface's material).
//
// Throws ObjError for a missing or unreadable file, data tinyobjloader would drop or misread
// (indices 0 or out of range for v, vt or vn, faces with fewer than 3 vertices, coordinates that
// are not finite numbers, malformed face entries), a missing or malformed material library that
// is needed, a usemtl name it does not define, no triangles at all, or more than `max_triangles`
// triangles.
ObjMesh load_obj(const std::filesystem::path& file, const std::string& display_name, Vec3 scale,
                 Vec3 translate, std::size_t max_triangles,
                 const SceneMaterialLookup& scene_has = {});

}  // namespace rt
