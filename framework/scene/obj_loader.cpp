#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

namespace rt {

namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxObjBytes = std::uintmax_t(2) << 30;  // 2 GiB

// Everything an ObjError says starts with the file and, where known, the line.
[[noreturn]] void fail(const std::string& name, std::size_t line, const std::string& what,
                       const std::string& fix) {
    std::string message = "mesh \"" + name + "\"";
    if (line > 0) message += " line " + std::to_string(line);
    message += ": " + what + "; " + fix;
    for (char& c : message)  // keep the message on one line whatever the file contained
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
    throw ObjError(message);
}

std::string read_file(const fs::path& file, const std::string& name) {
    std::error_code ec;
    fs::file_status status = fs::status(file, ec);
    if (!fs::exists(status))
        fail(name, 0, "file not found (looked for \"" + file.string() + "\")",
             "check the \"file\" path, which is relative to the scene file's folder");
    if (fs::is_directory(status))
        fail(name, 0, "is a directory, not an OBJ file", "name the .obj file itself");
    std::ifstream in(file, std::ios::binary);
    if (!in)
        fail(name, 0, std::string("cannot be opened (") + std::strerror(errno) + ")",
             "check the file's permissions");
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > kMaxObjBytes)
            fail(name, 0, "is larger than 2 GiB", "use a smaller mesh");
    }
    if (in.bad()) fail(name, 0, "could not be read", "check the file");
    return text;
}

// The lines of an OBJ file the way tinyobjloader sees them: "\n", "\r\n" and "\r" all end a
// line, and leading blanks are ignored.
template <typename Visit>
void for_each_line(const std::string& text, Visit visit) {
    std::size_t line = 1, start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find_first_of("\r\n", start);
        if (end == std::string::npos) end = text.size();
        std::string_view content(text.data() + start, end - start);
        std::size_t first = content.find_first_not_of(" \t");
        visit(line, first == std::string_view::npos ? std::string_view() : content.substr(first));
        if (end == text.size()) break;
        start = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
        ++line;
    }
}

std::vector<std::string_view> words(std::string_view s) {
    std::vector<std::string_view> out;
    std::size_t pos = 0;
    while ((pos = s.find_first_not_of(" \t", pos)) != std::string_view::npos) {
        std::size_t end = s.find_first_of(" \t", pos);
        if (end == std::string_view::npos) end = s.size();
        out.push_back(s.substr(pos, end - pos));
        pos = end;
    }
    return out;
}

bool is_directive(std::string_view line, std::string_view keyword) {
    return line.size() > keyword.size() && line.substr(0, keyword.size()) == keyword &&
           (line[keyword.size()] == ' ' || line[keyword.size()] == '\t');
}

std::string quoted(std::string_view s) {
    std::string out = "\"";  // built step by step: GCC 12 -O3 warns falsely on "\"" + s + "\""
    out.append(s.substr(0, 40));
    out += '"';
    return out;
}

// What the checking pass learns about the file before tinyobjloader reads it.
struct ObjSummary {
    std::vector<std::size_t> vertex_lines;  // line of each "v", in order
    std::vector<std::string> material_names;  // distinct "usemtl" names, first use first
    bool usemtl_before_mtllib = false;       // tinyobjloader only honours usemtl after mtllib
    std::size_t triangle_count = 0;           // after triangulation
};

// tinyobjloader silently turns unparsable coordinates into 0 and keeps out-of-range face
// indices, so check what it would misread, while the line numbers are still known.
ObjSummary check_obj_text(const std::string& text, const std::string& name) {
    ObjSummary summary;
    for_each_line(text, [&](std::size_t line, std::string_view s) {
        if (!is_directive(s, "v")) return;
        std::vector<std::string_view> coords = words(s.substr(1));
        if (coords.size() < 3)
            fail(name, line, "vertex has " + std::to_string(coords.size()) + " coordinates",
                 "write \"v x y z\"");
        for (std::string_view word : coords) {
            std::string_view digits = word.substr(word[0] == '+' ? 1 : 0);
            double value = 0;
            auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
            if (ec == std::errc::result_out_of_range || (ec == std::errc() &&
                                                         end == digits.data() + digits.size() &&
                                                         !std::isfinite(value)))
                fail(name, line, "vertex coordinate " + quoted(word) + " is not finite",
                     "use ordinary numbers");
            if (ec != std::errc() || end != digits.data() + digits.size())
                fail(name, line, "vertex coordinate " + quoted(word) + " is not a number",
                     "write \"v x y z\" with numbers");
        }
        summary.vertex_lines.push_back(line);
    });

    const long long vertex_count = static_cast<long long>(summary.vertex_lines.size());
    long long vertices_so_far = 0;  // negative face indices count back from here
    bool seen_mtllib = false;
    std::set<std::string, std::less<>> names;
    for_each_line(text, [&](std::size_t line, std::string_view s) {
        if (is_directive(s, "v")) ++vertices_so_far;
        if (is_directive(s, "mtllib")) seen_mtllib = true;
        if (s.substr(0, 6) == "usemtl") {
            std::vector<std::string_view> parts = words(s.substr(6));
            if (!parts.empty() && names.insert(std::string(parts[0])).second)
                summary.material_names.emplace_back(parts[0]);
            summary.usemtl_before_mtllib |= !seen_mtllib;
        }
        if (!is_directive(s, "f")) return;
        std::vector<std::string_view> corners = words(s.substr(1));
        if (corners.size() < 3)
            fail(name, line, "face has " + std::to_string(corners.size()) + " vertices",
                 "a face needs at least 3");
        for (std::string_view corner : corners) {
            std::string_view digits = corner.substr(0, corner.find('/'));
            long long index = 0;
            auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
            if (ec != std::errc() || end != digits.data() + digits.size())
                fail(name, line, "face entry " + quoted(corner) + " is not a vertex index",
                     "write \"f i j k\" with vertex numbers");
            if (index == 0)
                fail(name, line, "face index 0 is invalid", "OBJ vertex numbers start at 1");
            long long resolved = index > 0 ? index : vertices_so_far + index + 1;  // 1-based
            if (resolved < 1 || resolved > vertex_count)
                fail(name, line,
                     "face index " + std::to_string(index) + " out of range (the file has " +
                         std::to_string(vertex_count) + " vertices)",
                     "fix the face or the vertex list");
        }
        summary.triangle_count += corners.size() - 2;
    });
    return summary;
}

// Gives tinyobjloader a material for every usemtl name without reading any .mtl file: the
// scene only uses the names, to pick scene materials.
class NamesOnlyMaterialReader : public tinyobj::MaterialReader {
public:
    explicit NamesOnlyMaterialReader(const std::vector<std::string>& names) : names_(names) {}
    bool operator()(const std::string&, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* ids, std::string*, std::string*) override {
        for (const std::string& name : names_) {
            if (ids->count(name)) continue;
            (*ids)[name] = static_cast<int>(materials->size());
            tinyobj::material_t material{};  // zeroed: tinyobjloader copies every field
            material.name = name;
            materials->push_back(material);
        }
        return true;
    }

private:
    const std::vector<std::string>& names_;
};

}  // namespace

ObjMesh load_obj(const fs::path& file, const std::string& name, Vec3 scale, Vec3 translate,
                 std::size_t max_triangles) {
    std::string text = read_file(file, name);
    ObjSummary summary = check_obj_text(text, name);
    if (summary.triangle_count == 0)
        fail(name, 0, "contains no triangles (no \"f\" lines)", "add faces or use another file");
    if (summary.triangle_count > max_triangles)
        fail(name, 0,
             "has " + std::to_string(summary.triangle_count) + " triangles, more than the " +
                 std::to_string(max_triangles) + " allowed",
             "use a simpler mesh");

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
    NamesOnlyMaterialReader reader(summary.material_names);
    std::istringstream stream(std::move(text));
    bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warnings, &errors, &stream, &reader,
                               /*triangulate=*/true, /*default_vcols_fallback=*/false);
    if (!ok || !errors.empty()) {
        std::string first = errors.substr(0, errors.find('\n'));
        if (line_shift) {  // "line 8" -> "line 7"
            std::size_t at = first.find("line ");
            if (at != std::string::npos) {
                std::size_t digits_end = first.find_first_not_of("0123456789", at + 5);
                if (digits_end == std::string::npos) digits_end = first.size();
                if (digits_end > at + 5) {
                    long n = std::strtol(first.c_str() + at + 5, nullptr, 10) - line_shift;
                    first.replace(at + 5, digits_end - at - 5, std::to_string(n));
                }
            }
        }
        fail(name, 0, "tinyobjloader: " + (first.empty() ? std::string("failed") : first),
             "fix the OBJ file");
    }
    // Warnings that mean geometry was dropped (the checks above should have caught them first).
    for (const char* lost : {"Degenerated face", "invalid vertex index", "Vertex indices out"})
        if (warnings.find(lost) != std::string::npos)
            fail(name, 0, "tinyobjloader: " + warnings.substr(0, warnings.find('\n')),
                 "fix the OBJ file");

    ObjMesh mesh;
    mesh.material_names = summary.material_names;
    const std::size_t vertex_count = attrib.vertices.size() / 3;
    mesh.vertices.reserve(vertex_count);
    for (std::size_t i = 0; i < vertex_count; ++i) {
        Vec3 p(Real(attrib.vertices[3 * i]), Real(attrib.vertices[3 * i + 1]),
               Real(attrib.vertices[3 * i + 2]));
        Vec3 placed = p * scale + translate;
        if (!all_finite(placed))
            fail(name, i < summary.vertex_lines.size() ? summary.vertex_lines[i] : 0,
                 "vertex is too large to represent once scaled and translated",
                 "use smaller coordinates or a smaller \"scale\"");
        mesh.vertices.push_back(placed);
    }

    mesh.triangles.reserve(summary.triangle_count);
    mesh.triangle_material.reserve(summary.triangle_count);
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t next = 0;
        for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
            std::size_t corners = shape.mesh.num_face_vertices[face];
            if (corners != 3 || next + 3 > shape.mesh.indices.size())
                fail(name, 0, "tinyobjloader returned a face that is not a triangle",
                     "triangulate the mesh before exporting it");
            std::array<std::uint32_t, 3> triangle{};
            for (std::size_t k = 0; k < 3; ++k) {
                int index = shape.mesh.indices[next + k].vertex_index;
                if (index < 0 || static_cast<std::size_t>(index) >= vertex_count)
                    fail(name, 0,
                         "face index " + std::to_string(index + 1) +
                             " out of range (the file has " + std::to_string(vertex_count) +
                             " vertices)",
                         "fix the face or the vertex list");
                triangle[k] = static_cast<std::uint32_t>(index);
            }
            next += 3;
            int material = face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
            if (material < 0 || static_cast<std::size_t>(material) >= mesh.material_names.size())
                material = -1;
            mesh.triangles.push_back(triangle);
            mesh.triangle_material.push_back(material);
        }
    }
    if (mesh.triangles.empty())
        fail(name, 0, "contains no triangles", "add faces or use another file");
    return mesh;
}

}  // namespace rt
