// Loading an OBJ file into a mesh (scene/obj_loader.h): the checks and material libraries
// first, then tinyobjloader, then one scene vertex per distinct corner and the placement.
#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <map>
#include <sstream>

#include "scene/mesh_placement.h"
#include "scene/mtl_reader.h"
#include "scene/obj_check.h"
#include "scene/obj_text.h"

namespace rt {

namespace {

using namespace obj_internal;
namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxObjBytes = std::uintmax_t(2) << 30;  // 2 GiB

// Gives tinyobjloader a material for every usemtl name without reading any .mtl file: the
// libraries are read by read_libraries, and tinyobjloader's material ids are then simply
// positions in `names`.
class NamesOnlyMaterialReader : public tinyobj::MaterialReader {
  public:
    explicit NamesOnlyMaterialReader(const std::vector<ObjMaterial>& names) : names_(names) {}
    bool operator()(const std::string&, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* ids, std::string*, std::string*) override {
        for (std::size_t i = 0; i < names_.size(); ++i) {
            const std::string token = material_token(i);  // what with_material_tokens wrote
            (*ids)[token] = static_cast<int>(materials->size());
            tinyobj::material_t material{};  // zeroed: tinyobjloader copies every field
            material.name = names_[i].name;
            materials->push_back(material);
        }
        return true;
    }

  private:
    const std::vector<ObjMaterial>& names_;
};

// tinyobjloader's first error line, with "line N" moved back by `line_shift`.
std::string first_error(const std::string& errors, int line_shift) {
    std::string first = errors.substr(0, errors.find('\n'));
    if (line_shift) {
        std::size_t at = first.find("line ");
        if (at != std::string::npos) {
            std::size_t digits_end = first.find_first_not_of("0123456789", at + 5);
            if (digits_end == std::string::npos) digits_end = first.size();
            if (digits_end > at + 5 && digits_end - at - 5 < 18) {
                long long n = std::stoll(first.substr(at + 5, digits_end - at - 5)) - line_shift;
                first.replace(at + 5, digits_end - at - 5, std::to_string(n));
            }
        }
    }
    return first.empty() ? std::string("failed") : first;
}

// Scene vertices for each distinct (position, normal, uv) the corners use: `first_of_[p]` starts
// a chain, through `next_`, of the combinations made so far with position p. Without any normals
// or uvs, scene vertex i is simply OBJ vertex i + 1, used or not.
class Welder {
  public:
    Welder(const tinyobj::attrib_t& attrib, std::vector<tinyobj::shape_t>& shapes,
           const std::string& name)
        : attrib_(attrib),
          name_(name),
          position_count_(attrib.vertices.size() / 3),
          normal_count_(attrib.normals.size() / 3),
          uv_count_(attrib.texcoords.size() / 2),
          first_of_(position_count_, kNone) {
        // A file without any "vt" ("vn") line has no uvs (normals), whatever its faces say.
        for (tinyobj::shape_t& shape : shapes)
            for (tinyobj::index_t& index : shape.mesh.indices) {
                if (uv_count_ == 0) index.texcoord_index = -1;
                if (normal_count_ == 0) index.normal_index = -1;
                has_normals_ |= index.normal_index >= 0;
                has_uvs_ |= index.texcoord_index >= 0;
            }
        if (!has_normals_ && !has_uvs_)
            for (std::size_t p = 0; p < position_count_; ++p)
                combination_.push_back({int(p), -1, -1});
    }

    // The triangles of every shape, their corners as scene vertices, with their materials.
    void add_triangles(const std::vector<tinyobj::shape_t>& shapes, std::size_t triangle_count,
                       ObjMesh& mesh) {
        mesh.triangles.reserve(triangle_count);
        mesh.triangle_material.reserve(triangle_count);
        for (const tinyobj::shape_t& shape : shapes) {
            std::size_t next_index = 0;
            for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
                std::size_t corners = shape.mesh.num_face_vertices[face];
                if (corners != 3 || next_index + 3 > shape.mesh.indices.size())
                    fail(name_, 0, "tinyobjloader returned a face that is not a triangle",
                         "triangulate the mesh before exporting it");
                std::array<std::uint32_t, 3> triangle{};
                for (std::size_t k = 0; k < 3; ++k)
                    triangle[k] = vertex_of(shape.mesh.indices[next_index + k]);
                next_index += 3;
                int material =
                    face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
                if (material < 0 || static_cast<std::size_t>(material) >= mesh.materials.size())
                    material = -1;
                mesh.triangles.push_back(triangle);
                mesh.triangle_material.push_back(material);
            }
        }
        if (mesh.triangles.empty())
            fail(name_, 0, "contains no triangles", "add faces or use another file");
    }

    // Numbers the combinations in the order of their positions in the file (and of first use
    // among those sharing a position), so scene vertices follow the OBJ's vertex list.
    void renumber_in_file_order(ObjMesh& mesh) {
        if (!has_normals_ && !has_uvs_) return;
        std::vector<std::uint32_t> order(combination_.size());
        for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
            return combination_[a][0] < combination_[b][0];
        });
        std::vector<std::uint32_t> renumber(order.size());
        std::vector<std::array<int, 3>> sorted(order.size());
        for (std::uint32_t i = 0; i < order.size(); ++i)
            renumber[order[i]] = i, sorted[i] = combination_[order[i]];
        for (auto& triangle : mesh.triangles)
            for (std::uint32_t& v : triangle) v = renumber[v];
        combination_ = std::move(sorted);
    }

    // The scene vertices (with normals and uvs when the file has them); returns each one's OBJ
    // position index.
    std::vector<std::size_t> add_vertices(ObjMesh& mesh) const {
        std::vector<std::size_t> position_of;
        position_of.reserve(combination_.size());
        mesh.vertices.reserve(combination_.size());
        if (has_normals_) mesh.normals.reserve(combination_.size());
        if (has_uvs_) mesh.uvs.reserve(combination_.size());
        const auto& a = attrib_;
        for (const auto& [p, n, t] : combination_) {
            std::size_t i = std::size_t(p);
            position_of.push_back(i);
            mesh.vertices.push_back(Vec3(Real(a.vertices[3 * i]), Real(a.vertices[3 * i + 1]),
                                         Real(a.vertices[3 * i + 2])));
            if (has_normals_) {
                std::size_t k = std::size_t(n);
                mesh.normals.push_back(n < 0 ? Vec3(0)
                                             : Vec3(Real(a.normals[3 * k]),
                                                    Real(a.normals[3 * k + 1]),
                                                    Real(a.normals[3 * k + 2])));
            }
            if (has_uvs_) {
                std::size_t k = std::size_t(t);
                // OBJ's vt counts v upwards from the bottom of the image; ours counts rows from
                // the top (docs/conventions.md#texture-coordinates), so v flips here, once.
                mesh.uvs.push_back(
                    t < 0 ? Vec2(0)
                          : Vec2(Real(a.texcoords[2 * k]), 1 - Real(a.texcoords[2 * k + 1])));
            }
        }
        return position_of;
    }

  private:
    static constexpr std::uint32_t kNone = UINT32_MAX;

    std::uint32_t vertex_of(const tinyobj::index_t& index) {
        int p = index.vertex_index, n = index.normal_index, t = index.texcoord_index;
        if (p < 0 || std::size_t(p) >= position_count_)
            fail(name_, 0,
                 "face index " + std::to_string(p + 1) + " out of range (the file has " +
                     std::to_string(position_count_) + " vertices)",
                 "fix the face or the vertex list");
        if (n >= 0 && std::size_t(n) >= normal_count_)
            fail(name_, 0, "normal index " + std::to_string(n + 1) + " out of range",
                 "fix the face");
        if (t >= 0 && std::size_t(t) >= uv_count_)
            fail(name_, 0, "texture coordinate index " + std::to_string(t + 1) + " out of range",
                 "fix the face");
        if (!has_normals_ && !has_uvs_) return std::uint32_t(p);  // one to one
        if (!has_normals_) n = -1;
        if (!has_uvs_) t = -1;
        for (std::uint32_t v = first_of_[std::size_t(p)]; v != kNone; v = next_[v])
            if (combination_[v][1] == n && combination_[v][2] == t) return v;
        if (combination_.size() >= std::size_t(UINT32_MAX))
            fail(name_, 0, "has too many distinct vertices", "use a smaller mesh");
        auto v = std::uint32_t(combination_.size());
        combination_.push_back({p, n, t});
        next_.push_back(first_of_[std::size_t(p)]);
        first_of_[std::size_t(p)] = v;
        return v;
    }

    const tinyobj::attrib_t& attrib_;
    const std::string& name_;
    const std::size_t position_count_, normal_count_, uv_count_;
    bool has_normals_ = false, has_uvs_ = false;
    std::vector<std::uint32_t> first_of_, next_;
    std::vector<std::array<int, 3>> combination_;  // (position, normal, uv) of each scene vertex
};

// Fills mesh.vertices, normals, uvs, triangles and triangle_material from what tinyobjloader
// read, one scene vertex per distinct (position, normal, uv) the corners use, not yet placed.
// Returns the OBJ position (0-based) of each scene vertex.
std::vector<std::size_t> weld(const tinyobj::attrib_t& attrib,
                              std::vector<tinyobj::shape_t>& shapes, const std::string& name,
                              std::size_t triangle_count, ObjMesh& mesh) {
    Welder welder(attrib, shapes, name);
    welder.add_triangles(shapes, triangle_count, mesh);
    welder.renumber_in_file_order(mesh);
    return welder.add_vertices(mesh);
}

}  // namespace

ObjMesh load_obj(const fs::path& file, const std::string& name, Vec3 scale, Vec3 translate,
                 std::size_t max_triangles, const SceneMaterialLookup& scene_has) {
    std::string text = read_mesh_file(
        file, kMaxObjBytes, "an OBJ file", [&](const std::string& what, const std::string& fix) {
            fail(name, 0, what,
                 what.rfind("file not found", 0) == 0
                     ? "check the \"file\" path, which is relative to the scene file's folder"
                     : fix);
        });
    ObjSummary summary = check_obj_text(text, name);
    if (summary.triangle_count == 0)
        fail(name, 0, "contains no triangles (no \"f\" lines)", "add faces or use another file");
    if (summary.triangle_count > max_triangles)
        fail(name, 0,
             "has " + std::to_string(summary.triangle_count) + " triangles, more than the " +
                 std::to_string(max_triangles) + " allowed",
             "use a simpler mesh");

    // Material definitions are read only for usemtl names the scene does not supply, and only
    // when the file names a library at all.
    ObjMesh mesh;
    auto warn = [&](std::size_t line, const std::string& what) {
        mesh.warnings.push_back("mesh \"" + name + "\" line " + std::to_string(line) + ": " + what);
    };
    if (summary.dangling_uv_line)
        warn(summary.dangling_uv_line,
             "faces name texture coordinates but the file has no \"vt\" line; "
             "the mesh is loaded without uvs");
    if (summary.dangling_normal_line)
        warn(summary.dangling_normal_line,
             "faces name normals but the file has no \"vn\" line; "
             "the mesh is loaded without vertex normals");
    mesh.materials = summary.materials;
    mesh.has_mtllib = !summary.libraries.empty();
    std::vector<bool> wanted(mesh.materials.size());
    bool any_wanted = false;
    for (std::size_t i = 0; i < wanted.size(); ++i)
        any_wanted |= wanted[i] =
            mesh.has_mtllib && !(scene_has && scene_has(mesh.materials[i].name));
    if (any_wanted) read_libraries(file, name, summary, mesh.materials, wanted);

    comment_out_unused_lines(text);
    text = with_material_tokens(text, summary.materials);

    // usemtl only counts after an mtllib line; add one at the front if the file lacks it (the
    // reader above ignores the .mtl name). Line numbers in tinyobjloader's messages then run one
    // ahead, which `line_shift` undoes.
    int line_shift = 0;
    if (summary.usemtl_before_mtllib) {
        text.insert(0, "mtllib rt-scene-materials.mtl\n");
        line_shift = 1;
    }

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warnings, errors;
    NamesOnlyMaterialReader reader(summary.materials);
    std::istringstream stream(std::move(text));
    bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &stream, &reader,
                               /*triangulate=*/true, /*default_vcols_fallback=*/false);
    if (!ok || !errors.empty())
        fail(name, 0, "tinyobjloader: " + first_error(errors, line_shift), "fix the OBJ file");
    // Warnings that mean geometry was dropped (the checks above should have caught them first).
    for (const char* lost : {"Degenerated face", "invalid vertex index", "Vertex indices out"})
        if (warnings.find(lost) != std::string::npos)
            fail(name, 0, "tinyobjloader: " + first_error(warnings, line_shift),
                 "fix the OBJ file");

    // Scene vertex i came from OBJ vertex position_of[i]: its line names a vertex too large.
    std::vector<std::size_t> position_of = weld(attrib, shapes, name, summary.triangle_count, mesh);
    place_mesh(mesh.vertices, mesh.normals, mesh.triangles, scale, translate, [&](std::size_t i) {
        std::size_t p = position_of[i];
        fail(name, p < summary.vertex_lines.size() ? summary.vertex_lines[p] : 0,
             "vertex is too large to represent once scaled and translated",
             "use smaller coordinates or a smaller \"scale\"");
    });
    return mesh;
}

}  // namespace rt
