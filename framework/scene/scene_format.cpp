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
#include "scene/scene_schema.h"

namespace rt {

namespace {

using json = nlohmann::json;
using Order = std::vector<std::string>;

// How the keys of an object are ordered: by the element it is, which may depend on the object
// itself (a surface or a light, by its "type"); nullptr when no table orders it.
using ElementOf = const SchemaElement* (*)(const json& object);

// An element's keys in its table's order (scene_schema.h); none: every key alphabetically.
Order order_for(ElementOf element_of, const json& object) {
    const SchemaElement* element = element_of ? element_of(object) : nullptr;
    return element ? element->key_names() : Order{};
}

std::string type_of(const json& object) {
    const json* type = object.contains("type") ? &object.at("type") : nullptr;
    return type && type->is_string() ? type->get<std::string>() : "";
}

const SchemaElement* surface(const json& object) {
    return schema::surface_of_type(type_of(object));
}
const SchemaElement* light(const json& object) {
    return schema::light_of_type(type_of(object));
}

// An element whose table does not depend on the object: a function per table, made once.
template <const SchemaElement& element>
const SchemaElement* always(const json&) {
    return &element;
}

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

// The element of an object nested under `key` (texture slots, procedural textures, the
// environment's sky and "cube" faces, a height field, a transform step's "rotate"), or of the
// objects in an array under `key` (an object's "surfaces", an instance's "transform" steps).
ElementOf element_of_member(const std::string& key) {
    if (key.size() > 4 && key.compare(key.size() - 4, 4, "_map") == 0)
        return always<schema::kTextureSlot>;
    if (key == "surfaces") return surface;
    if (key == "transform") return always<schema::kTransformStep>;
    if (key == "rotate") return always<schema::kRotation>;
    if (key == "checker") return always<schema::kCheckerTexture>;
    if (key == "checker_3d") return always<schema::kChecker3dTexture>;
    if (key == "marble") return always<schema::kMarbleTexture>;
    if (key == "sky") return always<schema::kSky>;
    if (key == "cube") return always<schema::kCubeFaces>;
    if (key == "heightfield") return always<schema::kHeightField>;
    return nullptr;
}

// A value on one line: {"a": 1, "b": [1, 2, 3]}. `element_of` orders the keys of `v` itself, or
// of each object in it when `v` is an array.
void write_inline(const json& v, ElementOf element_of, std::string& out) {
    switch (v.type()) {
        case json::value_t::object: {
            out += '{';
            bool first = true;
            for (const std::string& key : ordered_keys(v, order_for(element_of, v))) {
                if (!first) out += ", ";
                first = false;
                out += string_text(key) + ": ";
                write_inline(v.at(key), element_of_member(key), out);
            }
            out += '}';
            break;
        }
        case json::value_t::array: {
            out += '[';
            for (std::size_t i = 0; i < v.size(); ++i) {
                if (i > 0) out += ", ";
                write_inline(v[i], element_of, out);
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

ElementOf element_of_section(const std::string& key) {
    if (key == "camera") return always<schema::kCamera>;
    if (key == "image") return always<schema::kImage>;
    if (key == "render") return always<schema::kRender>;
    if (key == "environment") return always<schema::kEnvironment>;
    if (key == "fog") return always<schema::kFog>;
    return nullptr;
}

ElementOf element_of_items(const std::string& key) {
    if (key == "textures") return always<schema::kTexture>;
    if (key == "materials") return always<schema::kMaterial>;
    if (key == "objects") return always<schema::kObject>;
    if (key == "surfaces") return surface;
    if (key == "lights") return light;
    return nullptr;
}

std::string write_canonical(const json& root) {
    if (!root.is_object() || root.empty()) {
        std::string out;
        write_inline(root, nullptr, out);
        return out + "\n";
    }
    std::string out = "{\n";
    const std::vector<std::string> keys = ordered_keys(root, schema::kScene.key_names());
    for (std::size_t k = 0; k < keys.size(); ++k) {
        const std::string& key = keys[k];
        const json& value = root.at(key);
        out += "  " + string_text(key) + ": ";
        const ElementOf items = element_of_items(key);
        if (items && value.is_array() && !value.empty()) {
            // A list section: one item per line.
            out += "[\n";
            for (std::size_t i = 0; i < value.size(); ++i) {
                out += "    ";
                write_inline(value[i], items, out);
                out += i + 1 < value.size() ? ",\n" : "\n";
            }
            out += "  ]";
        } else {
            write_inline(value, element_of_section(key), out);
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
