// The canonical form of scene files (docs/scene-format.md#canonical-form). The scene is validated
// by the loader first, so only scenes it accepts are ever rewritten, and the output is re-read
// and compared value by value (every number bit for bit as a double) with the input before it is
// returned: formatting can change the layout of a file, never what it says.
#include "scene/scene_format.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <system_error>
#include <vector>

#include "scene/scene_loader.h"

namespace rt {

namespace {

using json = nlohmann::json;
using Order = std::vector<std::string>;

// Key orders, as the tables of docs/scene-format.md list them. Each surface and light type uses
// a subset of one shared list, so "type" comes first and "material" last in every one of them.
const Order kTopLevel{"camera",      "image",   "render",        "background",
                      "environment", "fog",     "ambient_light", "textures",
                      "materials",   "objects", "surfaces",      "lights"};
const Order kCamera{"projection",  "eye",      "look_at",        "up",     "fov",
                    "view_height", "aperture", "focus_distance", "shutter"};
const Order kImage{"width", "height"};
const Order kRender{"mode",        "max_depth",          "shadows",   "fresnel",
                    "accelerator", "samples_per_pixel",  "seed",      "filter",
                    "indirect",    "occlusion_distance", "integrator"};
const Order kMaterial{"name",      "ambient",     "diffuse",      "specular",     "emissive",
                      "shininess", "reflective",  "transmissive", "ior",          "fuzz",
                      "roughness", "diffuse_map", "specular_map", "emissive_map", "normal_map"};
const Order kTexture{"name",   "image", "checker",     "checker_3d",  "marble",
                     "filter", "wrap",  "color_space", "colour_space"};
const Order kTextureSlot{"texture", "scale", "offset"};
const Order kProcedural{"a", "b", "scale"};
const Order kSurface{"type",        "center",    "radius",   "velocity", "point",     "normal",
                     "vertices",    "min",       "max",      "tiles",    "file",      "procedural",
                     "heightfield", "triangles", "seed",     "scale",    "translate", "object",
                     "transform",   "material",  "materials"};
const Order kObject{"name", "surfaces"};
const Order kRotation{"axis", "degrees"};
const Order kEnvironment{"latlong", "cube", "intensity", "rotate_y"};
const Order kFog{"density", "albedo", "min", "max"};
const Order kCubeFaces{"px", "nx", "py", "ny", "pz", "nz"};
const Order kLight{"type",   "position", "direction", "intensity", "attenuation", "corner",
                   "edge_u", "edge_v",   "center",    "radius",    "radiance"};
const Order kNone{};

// The keys of `object` in canonical order: those of `order` first, as listed, then any others
// alphabetically (the loader refuses unknown keys, so there are none in a valid scene).
std::vector<std::string> ordered_keys(const json& object, const Order& order) {
    std::vector<std::string> keys;
    for (const std::string& key : order)
        if (object.contains(key)) keys.push_back(key);
    for (const auto& item : object.items())  // nlohmann keeps keys sorted
        if (std::find(order.begin(), order.end(), item.key()) == order.end())
            keys.push_back(item.key());
    return keys;
}

std::string string_text(const std::string& s) {
    return json(s).dump();
}

std::string number_text(const json& v) {
    if (v.is_number_unsigned()) return std::to_string(v.get<std::uint64_t>());
    if (v.is_number_integer()) return std::to_string(v.get<std::int64_t>());
    return canonical_number(v.get<double>());
}

// The key order of an object nested under `key` (texture slots, procedural textures, the
// environment's "cube" faces, a transform step's "rotate"), or of the objects in an array under
// `key` (an object's "surfaces"). A transform step has one key, so needs no order.
const Order& order_of_member(const std::string& key) {
    if (key.size() > 4 && key.compare(key.size() - 4, 4, "_map") == 0) return kTextureSlot;
    if (key == "surfaces") return kSurface;
    if (key == "rotate") return kRotation;
    if (key == "checker" || key == "checker_3d" || key == "marble") return kProcedural;
    if (key == "cube") return kCubeFaces;
    return kNone;
}

// A value on one line: {"a": 1, "b": [1, 2, 3]}. `order` orders the keys of `v` itself, or of
// each object in it when `v` is an array.
void write_inline(const json& v, const Order& order, std::string& out) {
    switch (v.type()) {
        case json::value_t::object: {
            out += '{';
            bool first = true;
            for (const std::string& key : ordered_keys(v, order)) {
                if (!first) out += ", ";
                first = false;
                out += string_text(key) + ": ";
                write_inline(v.at(key), order_of_member(key), out);
            }
            out += '}';
            break;
        }
        case json::value_t::array: {
            out += '[';
            for (std::size_t i = 0; i < v.size(); ++i) {
                if (i > 0) out += ", ";
                write_inline(v[i], order, out);
            }
            out += ']';
            break;
        }
        case json::value_t::string:
            out += string_text(v.get<std::string>());
            break;
        case json::value_t::boolean:
            out += v.get<bool>() ? "true" : "false";
            break;
        case json::value_t::null:
            out += "null";
            break;
        default:
            out += number_text(v);
            break;
    }
}

const Order& order_of_section(const std::string& key) {
    if (key == "camera") return kCamera;
    if (key == "image") return kImage;
    if (key == "render") return kRender;
    if (key == "environment") return kEnvironment;
    if (key == "fog") return kFog;
    return kNone;
}

const Order& order_of_items(const std::string& key) {
    if (key == "textures") return kTexture;
    if (key == "materials") return kMaterial;
    if (key == "objects") return kObject;
    if (key == "surfaces") return kSurface;
    if (key == "lights") return kLight;
    return kNone;
}

std::string write_canonical(const json& root) {
    if (!root.is_object() || root.empty()) {
        std::string out;
        write_inline(root, kNone, out);
        return out + "\n";
    }
    std::string out = "{\n";
    const std::vector<std::string> keys = ordered_keys(root, kTopLevel);
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::string& key = keys[k];
        const json& value = root.at(key);
        out += "  " + string_text(key) + ": ";
        const Order& items = order_of_items(key);
        if (&items != &kNone && value.is_array() && !value.empty()) {
            // A list section: one item per line.
            out += "[\n";
            for (std::size_t i = 0; i < value.size(); ++i) {
                out += "    ";
                write_inline(value[i], items, out);
                out += i + 1 < value.size() ? ",\n" : "\n";
            }
            out += "  ]";
        } else {
            write_inline(value, order_of_section(key), out);
        }
        out += k + 1 < keys.size() ? ",\n" : "\n";
    }
    return out + "}\n";
}

// Whether `a` and `b` say the same: the same structure, strings and booleans, and numbers that
// the loader reads as the same double (bit for bit, so -0 differs from 0).
bool same_values(const json& a, const json& b) {
    if (a.is_number() && b.is_number()) {
        if (a.is_number_integer() && b.is_number_integer() &&
            a.is_number_unsigned() == b.is_number_unsigned())
            return a == b;
        const double x = a.get<double>(), y = b.get<double>();
        return std::memcmp(&x, &y, sizeof x) == 0;
    }
    if (a.type() != b.type()) return false;
    if (a.is_object()) {
        if (a.size() != b.size()) return false;
        for (const auto& item : a.items())
            if (!b.contains(item.key()) || !same_values(item.value(), b.at(item.key())))
                return false;
        return true;
    }
    if (a.is_array()) {
        if (a.size() != b.size()) return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (!same_values(a[i], b[i])) return false;
        return true;
    }
    return a == b;
}

}  // namespace

std::string canonical_number(double value) {
    if (value == 0 && std::signbit(value)) return "-0.0";
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (r.ec != std::errc()) return json(value).dump();  // cannot happen for a finite double
    return std::string(buffer, r.ptr);
}

std::string canonical_scene_text(const std::string& text, const std::string& name,
                                 const std::filesystem::path& base_dir) {
    parse_scene(text, name, base_dir);  // the loader's checks and messages, mesh files included
    const json root = json::parse(text);
    std::string canonical = write_canonical(root);
    bool same = false;
    try {
        same = same_values(root, json::parse(canonical));
    } catch (const json::exception&) {
    }
    if (!same)
        throw SceneError(name +
                         ":1:1: error: the canonical form would change a value of this scene; "
                         "please report this file (it was left as it is)");
    return canonical;
}

}  // namespace rt
