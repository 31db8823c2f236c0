// The checking pass over an OBJ file (scene/obj_check.h).
#include "scene/obj_check.h"

#include <charconv>
#include <map>
#include <string_view>

#include "scene/obj_text.h"

namespace rt::obj_internal {

namespace {

// A 1-based OBJ index (negative ones count back from the `so_far` elements read before the
// line), resolved to 1..total, or 0 when it is outside.
long long resolve_index(long long index, long long so_far, long long total) {
    long long resolved = index > 0 ? index : so_far + index + 1;
    return resolved >= 1 && resolved <= total ? resolved : 0;
}

// Checks the numbers of a "v", "vn" or "vt" line: between `min` and `max` of them, all finite.
void check_numbers(const std::string& name, std::size_t line, std::string_view rest,
                   std::size_t min, std::size_t max, const char* what, const char* form) {
    std::vector<std::string_view> values = words(rest);
    if (values.size() < min || values.size() > max)
        fail(name, line,
             std::string(what) + " has " + std::to_string(values.size()) + " coordinate" +
                 (values.size() == 1 ? "" : "s"),
             std::string("write \"") + form + "\"");
    for (std::string_view word : values) {
        double value;
        switch (parse_number(word, value)) {
            case Number::Ok:
                break;
            case Number::NotFinite:
                fail(name, line,
                     std::string(what) + " coordinate " + shown(word) + " is not finite",
                     "use ordinary numbers");
            case Number::NotANumber:
                fail(name, line,
                     std::string(what) + " coordinate " + shown(word) + " is not a number",
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
        parts[count++] = entry.substr(
            start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
        if (slash == std::string_view::npos) break;
        start = slash + 1;
    }
    // `what` names the part in messages: "face index 0" for the vertex (as OBJ readers say),
    // "texture coordinate index 0" and "normal index 0" for the others.
    auto integer = [&](std::string_view digits, const std::string& what) {
        long long value = 0;
        auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
        if (ec == std::errc::result_out_of_range)
            fail(name, line, "face entry " + shown(entry) + " has an index too large to be real",
                 "fix the face");
        if (ec != std::errc() || end != digits.data() + digits.size() || digits.empty())
            fail(name, line,
                 "face entry " + shown(entry) +
                     (what == "face" ? " is not a vertex index"
                                     : " has a " + what + " index that is not a number"),
                 "write \"f i j k\" with vertex numbers (or i/t/n triples)");
        if (value == 0) fail(name, line, what + " index 0 is invalid", "OBJ numbers start at 1");
        return value;
    };
    Corner corner;
    corner.v = integer(parts[0], "face");
    if (count >= 2 && !(count == 3 && parts[1].empty()))
        corner.vt = integer(parts[1], "texture coordinate");
    if (count == 3) corner.vn = integer(parts[2], "normal");
    return corner;
}

}  // namespace

ObjSummary check_obj_text(const std::string& text, const std::string& name) {
    ObjSummary summary;
    if (is_wide_text(text))
        fail(name, 0, "is UTF-16 (or UTF-32) text, which OBJ readers cannot read",
             "save it as UTF-8 or ASCII text");
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
            for (std::string_view file : files)
                summary.libraries.push_back({line, std::string(file)});
        }
        if (s.substr(0, 6) == "usemtl") {
            const std::string_view material = directive_argument(s, 6);
            if (!material.empty() &&
                material_index.emplace(std::string(material), summary.materials.size()).second) {
                ObjMaterial m;
                m.name = std::string(material);
                m.line = line;
                summary.materials.push_back(m);
            }
            summary.usemtl_before_mtllib |= summary.libraries.empty();
        }
        if (!is_directive(s, "f") && s != "f") return;  // a bare "f" is a face of 0 vertices
        std::vector<std::string_view> entries = words(s.substr(1));
        if (entries.size() < 3)
            fail(name, line, "face has " + std::to_string(entries.size()) + " vertices",
                 "a face needs at least 3");
        for (std::string_view entry : entries) {
            Corner c = parse_corner(name, line, entry);
            if (!resolve_index(c.v, vertices_so_far, vertex_count))
                fail(name, line,
                     "face index " + std::to_string(c.v) + " out of range (the file has " +
                         std::to_string(vertex_count) + " vertices)",
                     "fix the face or the vertex list");
            if (c.vt && summary.uv_count == 0 && summary.dangling_uv_line == 0)
                summary.dangling_uv_line = line;
            if (c.vn && summary.normal_count == 0 && summary.dangling_normal_line == 0)
                summary.dangling_normal_line = line;
            if (c.vt && summary.uv_count > 0 && !resolve_index(c.vt, uvs_so_far, summary.uv_count))
                fail(name, line,
                     "texture coordinate index " + std::to_string(c.vt) +
                         " out of range (the file has " + std::to_string(summary.uv_count) +
                         " \"vt\" line" + (summary.uv_count == 1 ? ")" : "s)"),
                     "fix the face or the \"vt\" list");
            if (c.vn && summary.normal_count > 0 &&
                !resolve_index(c.vn, normals_so_far, summary.normal_count))
                fail(name, line,
                     "normal index " + std::to_string(c.vn) + " out of range (the file has " +
                         std::to_string(summary.normal_count) + " \"vn\" line" +
                         (summary.normal_count == 1 ? ")" : "s)"),
                     "fix the face or the \"vn\" list");
        }
        summary.triangle_count += entries.size() - 2;
    });
    return summary;
}

// the file, and "l" (polylines) and "p" (points) are not surfaces.
std::string with_material_tokens(const std::string& text,
                                 const std::vector<ObjMaterial>& materials) {
    std::map<std::string_view, std::size_t> index;
    for (std::size_t i = 0; i < materials.size(); ++i) index.emplace(materials[i].name, i);
    std::string out;
    out.reserve(text.size());
    std::size_t copied = 0;
    for_each_line(text, [&](std::size_t, std::string_view s) {
        if (s.substr(0, 6) != "usemtl") return;
        const auto it = index.find(directive_argument(s, 6));
        if (it == index.end()) return;
        const std::size_t at = std::size_t(s.data() - text.data());
        out.append(text, copied, at - copied);
        out += "usemtl " + material_token(it->second);
        copied = at + s.size();
    });
    out.append(text, copied, std::string::npos);
    return out;
}

std::string material_token(std::size_t index) {
    return "rt-material-" + std::to_string(index);
}

void comment_out_unused_lines(std::string& text) {
    std::vector<std::size_t> starts;
    for_each_line(text, [&](std::size_t, std::string_view s) {
        if (is_directive(s, "t") || is_directive(s, "vw") || is_directive(s, "l") ||
            is_directive(s, "p"))
            starts.push_back(std::size_t(s.data() - text.data()));
    });
    for (std::size_t at : starts) text[at] = '#';
}

}  // namespace rt::obj_internal
