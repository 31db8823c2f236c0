// The typed reader over a scene file's JSON (scene/scene_reader.h).
#include "scene/scene_reader.h"

#include <cstdio>

#include <algorithm>
#include <cmath>

#include "core/diagnostics.h"
#include "scene/message_text.h"
#include "scene/scene_loader.h"

namespace rt::scene_internal {

std::string describe(const json& value) {
    switch (value.type()) {
        case json::value_t::null:
            return "null";
        case json::value_t::boolean:
            return value.get<bool>() ? "true" : "false";
        case json::value_t::string:
            return "the string " + quote(value.get<std::string>());
        case json::value_t::array:
            return "an array";
        case json::value_t::object:
            return "an object";
        default:
            return "a number";
    }
}

const json* member(const json& object, const char* key) {
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

[[noreturn]] void SceneReader::fail_at(std::size_t offset, const std::string& what_and_fix) const {
    TextPosition at = position_of_offset(text_, offset == JsonPositions::npos ? 0 : offset);
    throw SceneError(one_line(name_ + ":" + std::to_string(at.line) + ":" +
                              std::to_string(at.column) + ": error: " + what_and_fix));
}

[[noreturn]] void SceneReader::fail_at(std::size_t offset, const std::string& what,
                                       const std::string& fix) const {
    fail_at(offset, what + "; " + fix);
}

[[noreturn]] void SceneReader::fail_value(const std::string& pointer, const std::string& what,
                                          const std::string& fix) const {
    fail_at(positions_ ? positions_->value_offset(pointer) : 0, what, fix);
}

[[noreturn]] void SceneReader::fail_value(const std::string& pointer,
                                          const std::string& what_and_fix) const {
    fail_at(positions_ ? positions_->value_offset(pointer) : 0, what_and_fix);
}

[[noreturn]] void SceneReader::fail_key(const std::string& pointer, const std::string& what,
                                        const std::string& fix) const {
    std::size_t offset = positions_ ? positions_->key_offset(pointer) : 0;
    if (offset == JsonPositions::npos && positions_) offset = positions_->value_offset(pointer);
    fail_at(offset, what, fix);
}

void SceneReader::warn_key(const std::string& pointer, const std::string& what,
                           const std::string& fix) const {
    std::size_t offset = positions_ ? positions_->key_offset(pointer) : 0;
    TextPosition at = position_of_offset(text_, offset == JsonPositions::npos ? 0 : offset);
    std::fprintf(stderr, "%s\n",
                 one_line(name_ + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                          ": warning: " + what + "; " + fix)
                     .c_str());
}

std::string SceneReader::label(const std::string& pointer) {
    std::string indices, token;
    std::size_t end = pointer.size();
    while (end > 0) {
        std::size_t slash = pointer.rfind('/', end - 1);
        token = pointer.substr(slash + 1, end - slash - 1);
        if (token.empty() || token.find_first_not_of("0123456789") != std::string::npos) break;
        indices = "[" + token + "]" + indices;
        end = slash;
        token.clear();
    }
    if (token.empty()) return "the scene" + indices;
    return "\"" + token + "\"" + indices;
}

std::string SceneReader::source_text(const std::string& pointer) const {
    std::size_t start = positions_->value_offset(pointer);
    if (start == JsonPositions::npos) return "?";
    std::size_t end = text_.find_first_of(" \t\r\n,]}", start);
    return text_.substr(start, std::min<std::size_t>(end, text_.size()) - start).substr(0, 40);
}

void SceneReader::check_keys(const json& object, const std::string& pointer,
                             const std::string& what, const std::vector<std::string>& known) const {
    // Report the unknown key that comes first in the file (nlohmann sorts keys).
    std::optional<std::string> first_unknown;
    std::size_t first_offset = JsonPositions::npos;
    for (const auto& item : object.items()) {
        if (std::find(known.begin(), known.end(), item.key()) != known.end()) continue;
        std::size_t offset = positions_->key_offset(JsonPositions::child(pointer, item.key()));
        if (!first_unknown || offset < first_offset) {
            first_unknown = item.key();
            first_offset = offset;
        }
    }
    if (first_unknown)
        fail_key(JsonPositions::child(pointer, *first_unknown),
                 "unknown key " + quote(*first_unknown) + " in " + what,
                 suggestion(*first_unknown, known));
}

void SceneReader::check_keys(const json& object, const std::string& pointer,
                             const SchemaElement& element) const {
    check_keys(object, pointer, element.what, element.key_names());
}

void SceneReader::require_object(const json& value, const std::string& pointer,
                                 const std::string& example) const {
    if (!value.is_object())
        fail_value(pointer, label(pointer) + " must be an object, got " + describe(value),
                   "write it as " + example);
}

void SceneReader::require_array(const json& value, const std::string& pointer,
                                const std::string& example) const {
    if (!value.is_array())
        fail_value(pointer, label(pointer) + " must be an array, got " + describe(value),
                   "write it as " + example);
}

void SceneReader::require_array_of(const json& value, const std::string& pointer, std::size_t size,
                                   const std::string& entries, const std::string& counted,
                                   const std::string& fix) const {
    if (!value.is_array() || value.size() != size) {
        std::string got =
            value.is_array() ? std::to_string(value.size()) + " " + counted : describe(value);
        fail_value(pointer,
                   label(pointer) + " must be an array of " + std::to_string(size) + " " + entries +
                       ", got " + got,
                   fix);
    }
}

const json& SceneReader::required(const json& object, const std::string& pointer, const char* key,
                                  const std::string& what, const std::string& example) const {
    const json* value = member(object, key);
    if (!value)
        fail_value(pointer, what + " needs \"" + key + "\"",
                   std::string("add \"") + key + "\": " + example);
    return *value;
}

double SceneReader::number(const json& value, const std::string& pointer) const {
    if (!value.is_number())
        fail_value(pointer, label(pointer) + " must be a number, got " + describe(value),
                   "write a number such as 1.5 (without quotes)");
    double d = value.get<double>();
    if (!std::isfinite(d))
        fail_value(pointer,
                   label(pointer) + " must be a finite number, got " + source_text(pointer),
                   "use an ordinary number");
    return d;
}

Real SceneReader::real(const json& value, const std::string& pointer) const {
    double d = number(value, pointer);
    if (!std::isfinite(static_cast<Real>(d)))
        fail_value(pointer, label(pointer) + " is too large, got " + source_text(pointer),
                   "use a smaller number");
    return static_cast<Real>(d);
}

double SceneReader::whole_number(const json& value, const std::string& pointer) const {
    double d = number(value, pointer);
    if (d != std::floor(d))
        fail_value(pointer, label(pointer) + " must be a whole number, got " + source_text(pointer),
                   "drop the fraction");
    return d;
}

Real SceneReader::real_in(const json& value, const std::string& pointer, bool ok_if(double),
                          const std::string& rule, const std::string& fix) const {
    Real r = real(value, pointer);
    if (!ok_if(value.get<double>()))
        fail_value(pointer, label(pointer) + " must be " + rule + ", got " + source_text(pointer),
                   fix);
    return r;
}

Vec3 SceneReader::vec3(const json& value, const std::string& pointer) const {
    require_array_of(value, pointer, 3, "numbers", "numbers", "write it as [x, y, z]");
    Vec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = real(value[std::size_t(i)], JsonPositions::child(pointer, std::size_t(i)));
    return v;
}

Color SceneReader::color(const json& value, const std::string& pointer) const {
    Vec3 v = vec3(value, pointer);
    for (std::size_t i = 0; i < 3; ++i) {
        std::string element = JsonPositions::child(pointer, i);
        if (!(value[i].get<double>() >= 0) || !std::isfinite(float(v[int(i)])))
            fail_value(element, label(element) + " must be >= 0, got " + source_text(element),
                       "colours cannot be negative (or too large)");
    }
    return Color(float(v.x), float(v.y), float(v.z));
}

bool SceneReader::boolean(const json& value, const std::string& pointer) const {
    if (!value.is_boolean())
        fail_value(pointer, label(pointer) + " must be true or false, got " + describe(value),
                   "write true or false (without quotes)");
    return value.get<bool>();
}

std::string SceneReader::string(const json& value, const std::string& pointer,
                                const std::string& example) const {
    if (!value.is_string())
        fail_value(pointer, label(pointer) + " must be a string, got " + describe(value),
                   std::string("write it in double quotes, e.g. ") + example);
    return value.get<std::string>();
}

std::size_t SceneReader::choice(const json& value, const std::string& pointer,
                                const std::vector<std::string>& options) const {
    std::string word = string(value, pointer, "\"" + options.front() + "\"");
    auto it = std::find(options.begin(), options.end(), word);
    if (it == options.end())
        fail_value(pointer, "unknown " + label(pointer) + " " + quote(word),
                   closest(word, options)
                       ? suggestion(word, options) + " (allowed: " + list_of(options) + ")"
                       : "use " + list_of(options));
    return std::size_t(it - options.begin());
}

Vec3 SceneReader::unit_direction(const json& value, const std::string& pointer,
                                 const std::string& fix) const {
    vec3(value, pointer);  // checks the shape and that every number is finite
    double x = value[0].get<double>(), y = value[1].get<double>(), z = value[2].get<double>();
    double length = std::sqrt(x * x + y * y + z * z);
    if (!(length > 0) || !std::isfinite(length))
        fail_value(pointer, label(pointer) + " must have a non-zero, finite length", fix);
    return Vec3(Real(x / length), Real(y / length), Real(z / length));
}

}  // namespace rt::scene_internal
