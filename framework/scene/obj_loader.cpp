#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "core/diagnostics.h"

namespace rt {

namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxObjBytes = std::uintmax_t(2) << 30;  // 2 GiB
constexpr std::uintmax_t kMaxMtlBytes = std::uintmax_t(64) << 20;  // 64 MiB

// Everything an ObjError says starts with the file and, where known, the line.
[[noreturn]] void fail(const std::string& name, std::size_t line, const std::string& what,
                       const std::string& fix) {
    std::string message = "mesh \"" + name + "\"";
    if (line > 0) message += " line " + std::to_string(line);
    throw ObjError(one_line(message + ": " + what + "; " + fix));
}

std::string shown(std::string_view s) {
    std::string out = "\"";  // built step by step: GCC 12 -O3 warns falsely on "\"" + s + "\""
    out.append(s.substr(0, 40));
    out += '"';
    return out;
}

// Reads a whole file; `complain(what, fix)` reports (and throws) a problem with it.
template <typename Complain>
std::string read_file(const fs::path& file, std::uintmax_t max_bytes, const char* what_it_should_be,
                      Complain complain) {
    std::error_code ec;
    fs::file_status status = fs::status(file, ec);
    if (!fs::exists(status))
        complain("file not found (looked for \"" + file.string() + "\")",
                 "check the path, which is relative to the folder of the file that names it");
    if (fs::is_directory(status))
        complain(std::string("is a directory, not ") + what_it_should_be, "name the file itself");
    std::ifstream in(file, std::ios::binary);
    if (!in)
        complain(std::string("cannot be opened (") + std::strerror(errno) + ")", "check the file's permissions");
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > max_bytes)
            complain("is larger than " + std::to_string(max_bytes >> 20) + " MiB", "use a smaller file");
    }
    if (in.bad()) complain("could not be read", "check the file");
    return text;
}

// The lines of an OBJ or MTL file the way tinyobjloader sees them: "\n", "\r\n" and "\r" all
// end a line, and leading blanks are ignored.
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

// `line` starts with `keyword` followed by a blank (as tinyobjloader tests it).
bool is_directive(std::string_view line, std::string_view keyword) {
    return line.size() > keyword.size() && line.substr(0, keyword.size()) == keyword &&
           (line[keyword.size()] == ' ' || line[keyword.size()] == '\t');
}

enum class Number { Ok, NotANumber, NotFinite };

// A decimal number as OBJ and MTL write it ("1", "-2.5e3", "+0.5").
Number parse_number(std::string_view word, double& value) {
    std::string_view digits = word.substr(!word.empty() && word[0] == '+' ? 1 : 0);
    value = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    bool whole_word = end == digits.data() + digits.size();
    if (ec == std::errc::result_out_of_range && whole_word) {
        // from_chars says this for overflow (1e999) and for underflow (1e-999); only the first
        // is a problem, the second reads as 0.
        std::size_t e = digits.find_first_of("eE");
        if (e != std::string_view::npos && e + 1 < digits.size() && digits[e + 1] == '-') return Number::Ok;
        return Number::NotFinite;
    }
    if (ec != std::errc() || !whole_word) return Number::NotANumber;
    return std::isfinite(value) ? Number::Ok : Number::NotFinite;
}

// A 1-based OBJ index (negative ones count back from the `so_far` elements read before the
// line), resolved to 1..total, or 0 when it is outside.
long long resolve_index(long long index, long long so_far, long long total) {
    long long resolved = index > 0 ? index : so_far + index + 1;
    return resolved >= 1 && resolved <= total ? resolved : 0;
}

// ---- the checking pass ------------------------------------------------------------------------

struct MaterialLibrary {
    std::size_t line;      // of its mtllib line
    std::string file;      // as written
};

// What the checking pass learns about the file before tinyobjloader reads it.
struct ObjSummary {
    std::vector<std::size_t> vertex_lines;  // line of each "v", in order
    long long normal_count = 0, uv_count = 0;
    std::vector<ObjMaterial> materials;     // distinct "usemtl" names, first use first
    std::vector<MaterialLibrary> libraries;
    bool usemtl_before_mtllib = false;      // tinyobjloader only honours usemtl after mtllib
    std::size_t triangle_count = 0;         // after triangulation
    // First face line naming a "vt" / "vn" index in a file that has no such line at all: some
    // exporters write "f 1/1/1 ..." regardless. Those indices are ignored (with a warning).
    std::size_t dangling_uv_line = 0, dangling_normal_line = 0;
};

// Checks the numbers of a "v", "vn" or "vt" line: between `min` and `max` of them, all finite.
void check_numbers(const std::string& name, std::size_t line, std::string_view rest, std::size_t min,
                   std::size_t max, const char* what, const char* form) {
    std::vector<std::string_view> values = words(rest);
    if (values.size() < min || values.size() > max)
        fail(name, line, std::string(what) + " has " + std::to_string(values.size()) + " coordinate" +
                             (values.size() == 1 ? "" : "s"),
             std::string("write \"") + form + "\"");
    for (std::string_view word : values) {
        double value;
        switch (parse_number(word, value)) {
            case Number::Ok: break;
            case Number::NotFinite:
                fail(name, line, std::string(what) + " coordinate " + shown(word) + " is not finite",
                     "use ordinary numbers");
            case Number::NotANumber:
                fail(name, line, std::string(what) + " coordinate " + shown(word) + " is not a number",
                     std::string("write \"") + form + "\" with numbers");
        }
    }
}

// One entry of an "f" line: "v", "v/vt", "v//vn" or "v/vt/vn".
struct Corner {
    long long v = 0, vt = 0, vn = 0;  // 0: absent
};

Corner parse_corner(const std::string& name, std::size_t line, std::string_view entry) {
    std::string_view parts[3];
    std::size_t count = 0, start = 0;
    while (true) {
        std::size_t slash = entry.find('/', start);
        if (count == 3)
            fail(name, line, "face entry " + shown(entry) + " has more than two '/'",
                 "write v, v/vt, v//vn or v/vt/vn");
        parts[count++] = entry.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
        if (slash == std::string_view::npos) break;
        start = slash + 1;
    }
    // `what` names the part in messages: "face index 0" for the vertex (as OBJ readers say),
    // "texture coordinate index 0" and "normal index 0" for the others.
    auto integer = [&](std::string_view digits, const std::string& what) {
        long long value = 0;
        auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (ec == std::errc::result_out_of_range)
            fail(name, line, "face entry " + shown(entry) + " has an index too large to be real", "fix the face");
        if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
            fail(name, line,
                 "face entry " + shown(entry) + (what == "face" ? " is not a vertex index" : " has a " + what +
                                                                       " index that is not a number"),
                 "write \"f i j k\" with vertex numbers (or i/t/n triples)");
        if (value == 0) fail(name, line, what + " index 0 is invalid", "OBJ numbers start at 1");
        return value;
    };
    Corner corner;
    corner.v = integer(parts[0], "face");
    if (count >= 2 && !(count == 3 && parts[1].empty())) corner.vt = integer(parts[1], "texture coordinate");
    if (count == 3) corner.vn = integer(parts[2], "normal");
    return corner;
}

// tinyobjloader silently turns unparsable coordinates into 0 and keeps out-of-range face
// indices, so check what it would misread, while the line numbers are still known.
ObjSummary check_obj_text(const std::string& text, const std::string& name) {
    ObjSummary summary;
    for_each_line(text, [&](std::size_t line, std::string_view s) {
        if (is_directive(s, "v")) {
            check_numbers(name, line, s.substr(1), 3, std::size_t(-1), "vertex", "v x y z");
            summary.vertex_lines.push_back(line);
        } else if (is_directive(s, "vn")) {
            check_numbers(name, line, s.substr(2), 3, 3, "normal", "vn x y z");
            ++summary.normal_count;
        } else if (is_directive(s, "vt")) {
            check_numbers(name, line, s.substr(2), 1, 3, "texture coordinate", "vt u v");
            ++summary.uv_count;
        }
    });

    const long long vertex_count = static_cast<long long>(summary.vertex_lines.size());
    long long vertices_so_far = 0, normals_so_far = 0, uvs_so_far = 0;  // for negative indices
    std::map<std::string, std::size_t, std::less<>> material_index;
    for_each_line(text, [&](std::size_t line, std::string_view s) {
        if (is_directive(s, "v")) ++vertices_so_far;
        if (is_directive(s, "vn")) ++normals_so_far;
        if (is_directive(s, "vt")) ++uvs_so_far;
        if (is_directive(s, "mtllib")) {
            std::vector<std::string_view> files = words(s.substr(6));
            for (std::string_view file : files) summary.libraries.push_back({line, std::string(file)});
        }
        if (s.substr(0, 6) == "usemtl") {
            std::vector<std::string_view> parts = words(s.substr(6));
            if (!parts.empty() && material_index.emplace(std::string(parts[0]), summary.materials.size()).second) {
                ObjMaterial m;
                m.name = std::string(parts[0]);
                m.line = line;
                summary.materials.push_back(m);
            }
            summary.usemtl_before_mtllib |= summary.libraries.empty();
        }
        if (!is_directive(s, "f")) return;
        std::vector<std::string_view> entries = words(s.substr(1));
        if (entries.size() < 3)
            fail(name, line, "face has " + std::to_string(entries.size()) + " vertices", "a face needs at least 3");
        for (std::string_view entry : entries) {
            Corner c = parse_corner(name, line, entry);
            if (!resolve_index(c.v, vertices_so_far, vertex_count))
                fail(name, line,
                     "face index " + std::to_string(c.v) + " out of range (the file has " +
                         std::to_string(vertex_count) + " vertices)",
                     "fix the face or the vertex list");
            if (c.vt && summary.uv_count == 0 && summary.dangling_uv_line == 0) summary.dangling_uv_line = line;
            if (c.vn && summary.normal_count == 0 && summary.dangling_normal_line == 0)
                summary.dangling_normal_line = line;
            if (c.vt && summary.uv_count > 0 && !resolve_index(c.vt, uvs_so_far, summary.uv_count))
                fail(name, line,
                     "texture coordinate index " + std::to_string(c.vt) + " out of range (the file has " +
                         std::to_string(summary.uv_count) + " \"vt\" line" + (summary.uv_count == 1 ? ")" : "s)"),
                     "fix the face or the \"vt\" list");
            if (c.vn && summary.normal_count > 0 && !resolve_index(c.vn, normals_so_far, summary.normal_count))
                fail(name, line,
                     "normal index " + std::to_string(c.vn) + " out of range (the file has " +
                         std::to_string(summary.normal_count) + " \"vn\" line" + (summary.normal_count == 1 ? ")" : "s)"),
                     "fix the face or the \"vn\" list");
        }
        summary.triangle_count += entries.size() - 2;
    });
    return summary;
}

// Turns the lines a triangle mesh does not need into comments, keeping the line count:
// tinyobjloader's extensions ("t" tags, "vw" skin weights) size arrays from unchecked numbers in
// the file, and "l" (polylines) and "p" (points) are not surfaces.
void comment_out_unused_lines(std::string& text) {
    std::vector<std::size_t> starts;
    for_each_line(text, [&](std::size_t, std::string_view s) {
        if (is_directive(s, "t") || is_directive(s, "vw") || is_directive(s, "l") || is_directive(s, "p"))
            starts.push_back(std::size_t(s.data() - text.data()));
    });
    for (std::size_t at : starts) text[at] = '#';
}

// ---- material libraries -----------------------------------------------------------------------

// What an MTL file says about one material, beyond tinyobjloader's values: which keys it gave
// (absent ones keep the scene's defaults).
struct MtlKeys {
    bool ambient = false, diffuse = false, specular = false, emissive = false;
    bool shininess = false, ior = false, dissolve = false;
};

// Checks an MTL file line by line (tinyobjloader reads malformed numbers as 0 without a word)
// and returns the keys each material gives.
std::map<std::string, MtlKeys> check_mtl_text(const std::string& text, const std::string& obj_name,
                                              const std::string& mtl_name) {
    auto complain = [&](std::size_t line, const std::string& what, const std::string& fix) {
        fail(obj_name, 0, shown(mtl_name) + " line " + std::to_string(line) + ": " + what, fix);
    };
    std::map<std::string, MtlKeys> keys;
    std::map<std::string, std::size_t> first_line;
    MtlKeys* current = nullptr;
    for_each_line(text, [&](std::size_t line, std::string_view s) {
        if (is_directive(s, "newmtl")) {
            std::vector<std::string_view> parts = words(s.substr(6));
            if (parts.size() != 1)
                complain(line, "\"newmtl\" needs one name without spaces", "write \"newmtl name\"");
            std::string material(parts[0]);
            auto [it, added] = first_line.emplace(material, line);
            if (!added)
                complain(line, "material " + shown(material) + " is defined again (first on line " +
                                   std::to_string(it->second) + ")",
                         "give each material its own name");
            current = &keys[material];
            return;
        }
        struct Key {
            const char* word;
            std::size_t count;  // numbers it takes
            bool MtlKeys::*given;
        };
        static const Key kKeys[] = {
            {"Ka", 3, &MtlKeys::ambient},   {"Kd", 3, &MtlKeys::diffuse},  {"Ks", 3, &MtlKeys::specular},
            {"Ke", 3, &MtlKeys::emissive},  {"Tf", 3, nullptr},            {"Kt", 3, nullptr},
            {"Ns", 1, &MtlKeys::shininess}, {"Ni", 1, &MtlKeys::ior},      {"d", 1, &MtlKeys::dissolve},
            {"Tr", 1, &MtlKeys::dissolve},  {"illum", 1, nullptr},
        };
        for (const Key& key : kKeys) {
            if (!is_directive(s, key.word)) continue;
            std::string word = key.word;
            if (!current)
                complain(line, shown(word) + " comes before any \"newmtl\"", "start the material with \"newmtl name\"");
            std::vector<std::string_view> values = words(s.substr(word.size()));
            std::string form = word + (key.count == 3 ? " r g b" : " value");
            if (values.size() != key.count)
                complain(line, shown(word) + " has " + std::to_string(values.size()) + " number" +
                                   (values.size() == 1 ? "" : "s") + ", not " + std::to_string(key.count),
                         "write \"" + form + "\"");
            for (std::string_view v : values) {
                double value;
                Number n = parse_number(v, value);
                if (n != Number::Ok)
                    complain(line, shown(word) + " value " + shown(v) +
                                       (n == Number::NotFinite ? " is not finite" : " is not a number"),
                             "write \"" + form + "\" with ordinary numbers");
                bool ok = true;
                std::string rule;
                if (key.count == 3 || word == "Ns") ok = value >= 0, rule = ">= 0";
                if (word == "d" || word == "Tr") ok = value >= 0 && value <= 1, rule = "between 0 and 1";
                if (word == "illum") ok = value >= 0 && value <= 10 && value == std::floor(value), rule = "a whole number 0..10";
                if (!ok) complain(line, shown(word) + " must be " + rule + ", got " + shown(v), "fix the value");
            }
            if (key.given) current->*key.given = true;
            return;
        }
    });
    return keys;
}

// The scene material for an MTL one (docs/scene-format.md, "Materials from MTL files").
Material to_scene_material(const tinyobj::material_t& m, const MtlKeys& keys) {
    auto color = [](const tinyobj::real_t* c) { return Color(float(c[0]), float(c[1]), float(c[2])); };
    Material out;
    if (keys.ambient) out.ambient = color(m.ambient);
    if (keys.diffuse) out.diffuse = color(m.diffuse);
    if (keys.specular) out.specular = color(m.specular);
    if (keys.emissive) out.emissive = color(m.emission);
    if (keys.shininess) out.shininess = float(m.shininess);
    if (keys.ior && m.ior > 0) out.ior = float(m.ior);  // "Ni 0" (some exporters) keeps 1.5
    if (keys.dissolve) out.transmissive = Color(1 - float(m.dissolve));
    if (m.illum >= 3 && m.illum <= 7) out.reflective = out.specular;  // the "ray trace on" models
    return out;
}

// Reads the libraries the file names and fills in the definitions of `wanted` materials.
void read_libraries(const fs::path& obj_file, const std::string& name, const ObjSummary& summary,
                    std::vector<ObjMaterial>& materials, const std::vector<bool>& wanted) {
    std::set<std::string> found;
    for (const MaterialLibrary& library : summary.libraries) {
        fs::path path = fs::path(library.file);
        if (!path.is_absolute()) path = obj_file.parent_path() / path;
        std::string text = read_file(path, kMaxMtlBytes, "a material library", [&](const std::string& what, const std::string&) {
            fail(name, library.line, "material library " + shown(library.file) + " " + what,
                 "put the .mtl file beside the .obj (the mtllib path is relative to it), or define the "
                 "materials in the scene");
        });
        std::map<std::string, MtlKeys> keys = check_mtl_text(text, name, library.file);
        std::map<std::string, int> ids;
        std::vector<tinyobj::material_t> definitions;
        std::string warnings, errors;
        std::istringstream stream(text);
        tinyobj::LoadMtl(&ids, &definitions, &stream, &warnings, &errors);
        for (std::size_t i = 0; i < materials.size(); ++i) {
            ObjMaterial& m = materials[i];
            if (!wanted[i] || m.defined) continue;  // the first library defining a name wins
            auto id = ids.find(m.name);
            auto given = keys.find(m.name);
            if (id == ids.end() || given == keys.end() || id->second < 0 ||
                std::size_t(id->second) >= definitions.size())
                continue;
            m.material = to_scene_material(definitions[std::size_t(id->second)], given->second);
            m.defined = true;
        }
    }
    for (std::size_t i = 0; i < materials.size(); ++i) {
        if (!wanted[i] || materials[i].defined) continue;
        std::string libraries;
        for (const MaterialLibrary& library : summary.libraries)
            libraries += (libraries.empty() ? "" : ", ") + shown(library.file);
        fail(name, materials[i].line,
             "usemtl " + shown(materials[i].name) + " is not defined in " + libraries +
                 " nor in the scene's materials",
             "add \"newmtl " + materials[i].name.substr(0, 40) + "\" to the library or a scene material of that name");
    }
}

// Gives tinyobjloader a material for every usemtl name without reading any .mtl file: the
// libraries are read by read_libraries, and tinyobjloader's material ids are then simply
// positions in `names`.
class NamesOnlyMaterialReader : public tinyobj::MaterialReader {
public:
    explicit NamesOnlyMaterialReader(const std::vector<ObjMaterial>& names) : names_(names) {}
    bool operator()(const std::string&, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* ids, std::string*, std::string*) override {
        for (const ObjMaterial& m : names_) {
            if (ids->count(m.name)) continue;
            (*ids)[m.name] = static_cast<int>(materials->size());
            tinyobj::material_t material{};  // zeroed: tinyobjloader copies every field
            material.name = m.name;
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

}  // namespace

Vec3 scale_normal(Vec3 n, Vec3 scale) {
    glm::dvec3 scaled = glm::dvec3(n) / glm::dvec3(scale);
    double length = glm::length(scaled);
    if (!(length > 0) || !std::isfinite(length)) return Vec3(0);
    scaled /= length;
    return Vec3(Real(scaled.x), Real(scaled.y), Real(scaled.z));
}

ObjMesh load_obj(const fs::path& file, const std::string& name, Vec3 scale, Vec3 translate,
                 std::size_t max_triangles, const SceneMaterialLookup& scene_has) {
    std::string text = read_file(file, kMaxObjBytes, "an OBJ file", [&](const std::string& what, const std::string& fix) {
        fail(name, 0, what, what.rfind("file not found", 0) == 0
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
        warn(summary.dangling_uv_line, "faces name texture coordinates but the file has no \"vt\" line; "
                                       "the mesh is loaded without uvs");
    if (summary.dangling_normal_line)
        warn(summary.dangling_normal_line, "faces name normals but the file has no \"vn\" line; "
                                           "the mesh is loaded without vertex normals");
    mesh.materials = summary.materials;
    mesh.has_mtllib = !summary.libraries.empty();
    std::vector<bool> wanted(mesh.materials.size());
    bool any_wanted = false;
    for (std::size_t i = 0; i < wanted.size(); ++i)
        any_wanted |= wanted[i] = mesh.has_mtllib && !(scene_has && scene_has(mesh.materials[i].name));
    if (any_wanted) read_libraries(file, name, summary, mesh.materials, wanted);

    comment_out_unused_lines(text);

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
            fail(name, 0, "tinyobjloader: " + first_error(warnings, line_shift), "fix the OBJ file");

    const std::size_t position_count = attrib.vertices.size() / 3;
    const std::size_t normal_count = attrib.normals.size() / 3;
    const std::size_t uv_count = attrib.texcoords.size() / 2;
    bool has_normals = false, has_uvs = false;
    // A file without any "vt" ("vn") line has no uvs (normals), whatever its faces say.
    for (tinyobj::shape_t& shape : shapes)
        for (tinyobj::index_t& index : shape.mesh.indices) {
            if (uv_count == 0) index.texcoord_index = -1;
            if (normal_count == 0) index.normal_index = -1;
            has_normals |= index.normal_index >= 0;
            has_uvs |= index.texcoord_index >= 0;
        }

    // Scene vertices for each distinct (position, normal, uv) the corners use: `first_of[p]`
    // starts a chain, through `next`, of the combinations made so far with position p. Without
    // any normals or uvs, scene vertex i is simply OBJ vertex i + 1, used or not.
    constexpr std::uint32_t kNone = UINT32_MAX;
    std::vector<std::uint32_t> first_of(position_count, kNone), next;
    std::vector<std::array<int, 3>> combination;  // (position, normal, uv) of each scene vertex
    if (!has_normals && !has_uvs)
        for (std::size_t p = 0; p < position_count; ++p) combination.push_back({int(p), -1, -1});
    const bool mirrored = scale.x * scale.y * scale.z < 0;
    auto vertex_of = [&](const tinyobj::index_t& index) -> std::uint32_t {
        int p = index.vertex_index, n = index.normal_index, t = index.texcoord_index;
        if (p < 0 || std::size_t(p) >= position_count)
            fail(name, 0, "face index " + std::to_string(p + 1) + " out of range (the file has " +
                              std::to_string(position_count) + " vertices)",
                 "fix the face or the vertex list");
        if (n >= 0 && std::size_t(n) >= normal_count)
            fail(name, 0, "normal index " + std::to_string(n + 1) + " out of range", "fix the face");
        if (t >= 0 && std::size_t(t) >= uv_count)
            fail(name, 0, "texture coordinate index " + std::to_string(t + 1) + " out of range", "fix the face");
        if (!has_normals && !has_uvs) return std::uint32_t(p);  // one to one, see below
        if (!has_normals) n = -1;
        if (!has_uvs) t = -1;
        for (std::uint32_t v = first_of[std::size_t(p)]; v != kNone; v = next[v])
            if (combination[v][1] == n && combination[v][2] == t) return v;
        if (combination.size() >= std::size_t(UINT32_MAX))
            fail(name, 0, "has too many distinct vertices", "use a smaller mesh");
        auto v = std::uint32_t(combination.size());
        combination.push_back({p, n, t});
        next.push_back(first_of[std::size_t(p)]);
        first_of[std::size_t(p)] = v;
        return v;
    };

    mesh.triangles.reserve(summary.triangle_count);
    mesh.triangle_material.reserve(summary.triangle_count);
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t next_index = 0;
        for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
            std::size_t corners = shape.mesh.num_face_vertices[face];
            if (corners != 3 || next_index + 3 > shape.mesh.indices.size())
                fail(name, 0, "tinyobjloader returned a face that is not a triangle",
                     "triangulate the mesh before exporting it");
            std::array<std::uint32_t, 3> triangle{};
            for (std::size_t k = 0; k < 3; ++k) triangle[k] = vertex_of(shape.mesh.indices[next_index + k]);
            if (mirrored) std::swap(triangle[1], triangle[2]);
            next_index += 3;
            int material = face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
            if (material < 0 || static_cast<std::size_t>(material) >= mesh.materials.size()) material = -1;
            mesh.triangles.push_back(triangle);
            mesh.triangle_material.push_back(material);
        }
    }
    if (mesh.triangles.empty()) fail(name, 0, "contains no triangles", "add faces or use another file");

    // Number the combinations in the order of their positions in the file (and of first use
    // among those sharing a position), so scene vertices follow the OBJ's vertex list.
    if (has_normals || has_uvs) {
        std::vector<std::uint32_t> order(combination.size());
        for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
            return combination[a][0] < combination[b][0];
        });
        std::vector<std::uint32_t> renumber(order.size());
        std::vector<std::array<int, 3>> sorted(order.size());
        for (std::uint32_t i = 0; i < order.size(); ++i) renumber[order[i]] = i, sorted[i] = combination[order[i]];
        for (auto& triangle : mesh.triangles)
            for (std::uint32_t& v : triangle) v = renumber[v];
        combination = std::move(sorted);
    }

    mesh.vertices.reserve(combination.size());
    if (has_normals) mesh.normals.reserve(combination.size());
    if (has_uvs) mesh.uvs.reserve(combination.size());
    for (const auto& [p, n, t] : combination) {
        std::size_t i = std::size_t(p);
        Vec3 position(Real(attrib.vertices[3 * i]), Real(attrib.vertices[3 * i + 1]), Real(attrib.vertices[3 * i + 2]));
        Vec3 placed = position * scale + translate;
        if (!all_finite(placed))
            fail(name, i < summary.vertex_lines.size() ? summary.vertex_lines[i] : 0,
                 "vertex is too large to represent once scaled and translated",
                 "use smaller coordinates or a smaller \"scale\"");
        mesh.vertices.push_back(placed);
        if (has_normals) {
            std::size_t k = std::size_t(n);
            mesh.normals.push_back(n < 0 ? Vec3(0)
                                         : scale_normal(Vec3(Real(attrib.normals[3 * k]), Real(attrib.normals[3 * k + 1]),
                                                             Real(attrib.normals[3 * k + 2])),
                                                        scale));
        }
        if (has_uvs) {
            std::size_t k = std::size_t(t);
            mesh.uvs.push_back(t < 0 ? Vec2(0) : Vec2(Real(attrib.texcoords[2 * k]), Real(attrib.texcoords[2 * k + 1])));
        }
    }
    return mesh;
}

}  // namespace rt
