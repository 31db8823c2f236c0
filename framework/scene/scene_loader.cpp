// The scene file reader (docs/scene-format.md). Parsing is nlohmann::json's job; this file turns
// the parsed value into a Scene and checks every field, so that a mistake in a scene file is
// reported as one compiler-style line pointing at the offending value instead of a crash or a
// silently wrong picture.
#include <cstdio>
#include "scene/scene_loader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <vector>

#include "core/diagnostics.h"
#include "geometry/procedural_mesh.h"
#include "scene/json_positions.h"
#include "scene/obj_loader.h"

namespace rt {

namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

// Limits against absurd sizes (documented in docs/scene-format.md).
constexpr double kMaxImageSide = 16384;
constexpr double kMaxPixels = 64.0 * 1024 * 1024;
constexpr double kMaxRecursionDepth = 64;
constexpr std::size_t kMaxTriangles = 20'000'000;
constexpr std::size_t kMaxSceneFileBytes = std::size_t(64) << 20;
constexpr double kMaxCheckerTiles = 1024;  // per side of a "checkerboard"
constexpr int kMaxNesting = 100;  // a scene needs 5 levels; this stops pathological input early

// A string shown in a message: JSON-quoted (so odd characters are visible) and kept short.
std::string quote(const std::string& s) {
    std::string shown = json(s.size() > 60 ? s.substr(0, 57) + "..." : s)
                            .dump(-1, ' ', false, json::error_handler_t::replace);
    return shown;
}

std::string list_of(const std::vector<std::string>& options) {
    std::string out;
    for (std::size_t i = 0; i < options.size(); ++i) {
        if (i > 0) out += i + 1 == options.size() ? " or " : ", ";
        out += "\"" + options[i] + "\"";
    }
    return out;
}

// Case-insensitive Levenshtein distance, for "did you mean ...?".
std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t above = row[j];
            bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// The option closest to `word`, if it is close enough to be a plausible typo.
std::optional<std::string> closest(const std::string& word, const std::vector<std::string>& options) {
    if (word.size() > 64) return std::nullopt;
    auto lower = [](std::string s) {
        for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    if (word.size() >= 3)  // an abbreviation such as "ortho"
        for (const std::string& option : options)
            if (lower(option).rfind(lower(word), 0) == 0) return option;
    std::optional<std::string> best;
    std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const std::string& option : options) {
        std::size_t d = edit_distance(word, option);
        if (d < best_distance) best = option, best_distance = d;
    }
    return best;
}

// "did you mean "x"?" or "use one of ...".
std::string suggestion(const std::string& word, const std::vector<std::string>& options) {
    if (auto near = closest(word, options)) return "did you mean \"" + *near + "\"?";
    return "use " + list_of(options);
}

std::string describe(const json& value) {
    switch (value.type()) {
        case json::value_t::null: return "null";
        case json::value_t::boolean: return value.get<bool>() ? "true" : "false";
        case json::value_t::string: return "the string " + quote(value.get<std::string>());
        case json::value_t::array: return "an array";
        case json::value_t::object: return "an object";
        default: return "a number";
    }
}

const json* member(const json& object, const char* key) {
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

class Loader {
public:
    Loader(const std::string& text, const std::string& name, const fs::path& base_dir)
        : text_(text), name_(name), base_dir_(base_dir) {}

    Scene load() {
        parse();
        const json& root = root_;
        if (!root.is_object())
            fail_value("", "the top level must be a JSON object, got " + describe(root),
                       "wrap the scene in { ... }");
        check_keys(root, "", "the scene",
                   {"camera", "image", "render", "background", "ambient_light", "materials",
                    "surfaces", "lights"});
        scene_.source = name_;
        read_image(root);
        read_render(root);
        if (const json* v = member(root, "background")) scene_.background = color(*v, "/background");
        if (const json* v = member(root, "ambient_light"))
            scene_.ambient_light = color(*v, "/ambient_light");
        read_camera(root);
        read_materials(root);
        read_surfaces(root);
        read_lights(root);
        scene_.update_features();
        return std::move(scene_);
    }

private:
    // ---- errors ---------------------------------------------------------------------------

    [[noreturn]] void fail_at(std::size_t offset, const std::string& what_and_fix) const {
        TextPosition at = position_of_offset(text_, offset == JsonPositions::npos ? 0 : offset);
        throw SceneError(one_line(name_ + ":" + std::to_string(at.line) + ":" +
                                  std::to_string(at.column) + ": error: " + what_and_fix));
    }
    [[noreturn]] void fail_at(std::size_t offset, const std::string& what, const std::string& fix) const {
        fail_at(offset, what + "; " + fix);
    }
    // At the value `pointer` names (the enclosing object for a missing field).
    [[noreturn]] void fail_value(const std::string& pointer, const std::string& what,
                                 const std::string& fix) const {
        fail_at(positions_ ? positions_->value_offset(pointer) : 0, what, fix);
    }
    // At the key of `pointer` (unknown and duplicate keys).
    [[noreturn]] void fail_key(const std::string& pointer, const std::string& what,
                               const std::string& fix) const {
        std::size_t offset = positions_ ? positions_->key_offset(pointer) : 0;
        if (offset == JsonPositions::npos && positions_) offset = positions_->value_offset(pointer);
        fail_at(offset, what, fix);
    }

    // How a value is named in messages: "radius", "center"[1], "surfaces"[3].
    static std::string label(const std::string& pointer) {
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

    // The text of a scalar value as written in the file (to show 1e999 rather than "inf").
    std::string source_text(const std::string& pointer) const {
        std::size_t start = positions_->value_offset(pointer);
        if (start == JsonPositions::npos) return "?";
        std::size_t end = text_.find_first_of(" \t\r\n,]}", start);
        return text_.substr(start, std::min<std::size_t>(end, text_.size()) - start).substr(0, 40);
    }

    // ---- parsing --------------------------------------------------------------------------

    void parse() {
        std::size_t first = text_.find_first_not_of(" \t\r\n");
        if (first == std::string::npos || text_.compare(first, std::string::npos, "\xEF\xBB\xBF") == 0)
            fail_at(0, "the file is empty", "a scene file holds a JSON object such as {\"surfaces\": []}");
        check_nesting();
        try {
            root_ = json::parse(text_);
        } catch (const json::parse_error& e) {
            fail_at(e.byte > 0 ? e.byte - 1 : 0, syntax_message(e));
        } catch (const json::out_of_range&) {
            // nlohmann refuses numbers beyond double (1e999) without saying where: find it.
            positions_.emplace(text_);
            std::size_t offset = first_overflowing_number();
            std::string pointer = positions_->pointer_at(offset);
            fail_at(offset, label(pointer) + " must be a finite number, got " +
                                text_.substr(offset, std::min<std::size_t>(40, text_.find_first_of(
                                                                                 " \t\r\n,]}", offset) - offset)),
                    "use an ordinary number");
        }
        positions_.emplace(text_);
        if (!positions_->duplicate_keys().empty()) {
            const std::string& pointer = positions_->duplicate_keys().front();
            fail_key(pointer, "duplicate key " + label(pointer),
                     "remove one of them (only the last one would count)");
        }
    }

    // nlohmann's parser copes with deep nesting, but nothing in a scene is deeper than a few
    // levels, and refusing early keeps every later step cheap.
    void check_nesting() const {
        int depth = 0;
        for (std::size_t i = 0; i < text_.size(); ++i) {
            char c = text_[i];
            if (c == '"') {
                for (++i; i < text_.size() && text_[i] != '"'; ++i)
                    if (text_[i] == '\\') ++i;
            } else if (c == '[' || c == '{') {
                if (++depth > kMaxNesting)
                    fail_at(i, "brackets nested more than " + std::to_string(kMaxNesting) + " deep",
                            "a scene file needs only a few levels; check the brackets");
            } else if (c == ']' || c == '}') {
                --depth;
            }
        }
    }

    // The offset of the first number (outside strings) too large for a double.
    std::size_t first_overflowing_number() const {
        for (std::size_t i = 0; i < text_.size(); ++i) {
            char c = text_[i];
            if (c == '"') {
                for (++i; i < text_.size() && text_[i] != '"'; ++i)
                    if (text_[i] == '\\') ++i;
            } else if (c == '-' || (c >= '0' && c <= '9')) {
                std::size_t end = text_.find_first_of(" \t\r\n,]}", i);
                if (end == std::string::npos) end = text_.size();
                if (std::isinf(std::strtod(text_.substr(i, end - i).c_str(), nullptr))) return i;
                i = end - 1;
            }
        }
        return 0;
    }

    std::string syntax_message(const json::parse_error& e) const {
        // nlohmann: "[json.exception.parse_error.101] parse error at line 1, column 5: syntax
        // error while parsing value - <detail>"; keep <detail>, we give the position ourselves.
        std::string detail = e.what();
        std::size_t dash = detail.find(" - ");
        if (dash != std::string::npos) detail = detail.substr(dash + 3);
        std::size_t semicolon = detail.find("; expected");  // keep ';' for separating the fix
        if (semicolon != std::string::npos) detail[semicolon] = ',';
        // "; last read: '...'" helps only when it is plain text (not binary or broken UTF-8).
        std::size_t last_read = detail.find("; last read: ");
        if (last_read != std::string::npos) {
            bool plain = std::all_of(detail.begin() + long(last_read), detail.end(),
                                     [](char c) { return c >= 0x20 && c < 0x7f; });
            if (plain) detail[last_read] = ',';
            else detail.erase(last_read);
        }
        if (detail.size() > 160) detail = detail.substr(0, 157) + "...";
        std::size_t at = e.byte > 0 ? e.byte - 1 : 0;
        std::string fix = "check the JSON syntax here (keys need double quotes, items need commas)";
        if (detail.find("UTF-8") != std::string::npos) {
            fix = "save the file as UTF-8 text";
        } else if (at >= text_.size()) {
            fix = "the file ends too early: check for a missing closing bracket, brace or quote";
        } else if (text_[at] == ']' || text_[at] == '}') {
            std::size_t before = text_.find_last_not_of(" \t\r\n", at == 0 ? 0 : at - 1);
            if (at > 0 && before != std::string::npos && text_[before] == ',')
                fix = "remove the trailing comma before it";
        }
        return "invalid JSON: " + detail + "; " + fix;
    }

    // ---- typed fields ---------------------------------------------------------------------

    void check_keys(const json& object, const std::string& pointer, const std::string& what,
                    const std::vector<std::string>& known) const {
        // Report the unknown key that comes first in the file (nlohmann sorts keys).
        std::optional<std::string> first_unknown;
        std::size_t first_offset = JsonPositions::npos;
        for (const auto& item : object.items()) {
            if (std::find(known.begin(), known.end(), item.key()) != known.end()) continue;
            std::size_t offset = positions_->key_offset(JsonPositions::child(pointer, item.key()));
            if (!first_unknown || offset < first_offset) first_unknown = item.key(), first_offset = offset;
        }
        if (first_unknown)
            fail_key(JsonPositions::child(pointer, *first_unknown),
                     "unknown key " + quote(*first_unknown) + " in " + what,
                     suggestion(*first_unknown, known));
    }

    void require_object(const json& value, const std::string& pointer, const std::string& example) const {
        if (!value.is_object())
            fail_value(pointer, label(pointer) + " must be an object, got " + describe(value),
                       "write it as " + example);
    }

    void require_array(const json& value, const std::string& pointer, const std::string& example) const {
        if (!value.is_array())
            fail_value(pointer, label(pointer) + " must be an array, got " + describe(value),
                       "write it as " + example);
    }

    const json& required(const json& object, const std::string& pointer, const char* key,
                         const std::string& what, const std::string& example) const {
        const json* value = member(object, key);
        if (!value)
            fail_value(pointer, what + " needs \"" + key + "\"", std::string("add \"") + key + "\": " + example);
        return *value;
    }

    double number(const json& value, const std::string& pointer) const {
        if (!value.is_number())
            fail_value(pointer, label(pointer) + " must be a number, got " + describe(value),
                       "write a number such as 1.5 (without quotes)");
        double d = value.get<double>();
        if (!std::isfinite(d))
            fail_value(pointer, label(pointer) + " must be a finite number, got " + source_text(pointer),
                       "use an ordinary number");
        return d;
    }

    // A number that must also fit in Real (float by default).
    Real real(const json& value, const std::string& pointer) const {
        double d = number(value, pointer);
        if (!std::isfinite(static_cast<Real>(d)))
            fail_value(pointer, label(pointer) + " is too large, got " + source_text(pointer),
                       "use a smaller number");
        return static_cast<Real>(d);
    }

    double whole_number(const json& value, const std::string& pointer) const {
        double d = number(value, pointer);
        if (d != std::floor(d))
            fail_value(pointer, label(pointer) + " must be a whole number, got " + source_text(pointer),
                       "drop the fraction");
        return d;
    }

    // A number checked against a range; `rule` reads like "> 0" or "between 1 and 16384".
    Real real_in(const json& value, const std::string& pointer, bool ok_if(double),
                 const std::string& rule, const std::string& fix) const {
        Real r = real(value, pointer);
        if (!ok_if(value.get<double>()))
            fail_value(pointer, label(pointer) + " must be " + rule + ", got " + source_text(pointer), fix);
        return r;
    }

    Vec3 vec3(const json& value, const std::string& pointer) const {
        if (!value.is_array() || value.size() != 3) {
            std::string got = value.is_array() ? std::to_string(value.size()) + " numbers"
                                               : describe(value);
            fail_value(pointer, label(pointer) + " must be an array of 3 numbers, got " + got,
                       "write it as [x, y, z]");
        }
        Vec3 v;
        for (int i = 0; i < 3; ++i) v[i] = real(value[std::size_t(i)], JsonPositions::child(pointer, std::size_t(i)));
        return v;
    }

    Color color(const json& value, const std::string& pointer) const {
        Vec3 v = vec3(value, pointer);
        for (std::size_t i = 0; i < 3; ++i) {
            std::string element = JsonPositions::child(pointer, i);
            if (!(value[i].get<double>() >= 0) || !std::isfinite(float(v[int(i)])))
                fail_value(element, label(element) + " must be >= 0, got " + source_text(element),
                           "colours cannot be negative (or too large)");
        }
        return Color(float(v.x), float(v.y), float(v.z));
    }

    bool boolean(const json& value, const std::string& pointer) const {
        if (!value.is_boolean())
            fail_value(pointer, label(pointer) + " must be true or false, got " + describe(value),
                       "write true or false (without quotes)");
        return value.get<bool>();
    }

    std::string string(const json& value, const std::string& pointer, const std::string& example) const {
        if (!value.is_string())
            fail_value(pointer, label(pointer) + " must be a string, got " + describe(value),
                       std::string("write it in double quotes, e.g. ") + example);
        return value.get<std::string>();
    }

    // One of a fixed set of words; returns its position in `options`.
    std::size_t choice(const json& value, const std::string& pointer,
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

    Vec3 unit_direction(const json& value, const std::string& pointer, const std::string& fix) const {
        vec3(value, pointer);  // checks the shape and that every number is finite
        double x = value[0].get<double>(), y = value[1].get<double>(), z = value[2].get<double>();
        double length = std::sqrt(x * x + y * y + z * z);
        if (!(length > 0) || !std::isfinite(length))
            fail_value(pointer, label(pointer) + " must have a non-zero, finite length", fix);
        return Vec3(Real(x / length), Real(y / length), Real(z / length));
    }

    // ---- sections -------------------------------------------------------------------------

    void read_image(const json& root) {
        const json* image = member(root, "image");
        if (!image) return;
        require_object(*image, "/image", "{\"width\": 640, \"height\": 480}");
        check_keys(*image, "/image", "\"image\"", {"width", "height"});
        auto side = [&](const char* key, int& out) {
            const json* v = member(*image, key);
            if (!v) return;
            std::string pointer = JsonPositions::child("/image", key);
            double d = whole_number(*v, pointer);
            if (d < 1 || d > kMaxImageSide)
                fail_value(pointer, label(pointer) + " must be between 1 and 16384, got " + source_text(pointer),
                           "choose a sensible image size");
            out = int(d);
        };
        side("width", scene_.image.width);
        side("height", scene_.image.height);
        if (double(scene_.image.width) * double(scene_.image.height) > kMaxPixels)
            fail_value("/image", "the image has " + std::to_string(scene_.image.width) + "x" +
                                     std::to_string(scene_.image.height) +
                                     " pixels, more than the 67108864 (64 Mi) allowed",
                       "make it smaller");
    }

    void read_render(const json& root) {
        const json* render = member(root, "render");
        if (!render) return;
        require_object(*render, "/render", "{\"mode\": \"shaded\", \"max_depth\": 5}");
        check_keys(*render, "/render", "\"render\"", {"mode", "max_depth", "shadows", "fresnel", "accelerator"});
        if (const json* v = member(*render, "mode")) {
            static const std::vector<std::string> modes{"directions", "normals", "depth", "primitive", "shaded", "bvh_visits"};
            static const RenderMode values[] = {RenderMode::Directions, RenderMode::Normals, RenderMode::Depth,
                                                RenderMode::PrimitiveId, RenderMode::Shaded, RenderMode::BvhVisits};
            scene_.mode = values[choice(*v, "/render/mode", modes)];
        }
        if (const json* v = member(*render, "max_depth")) {
            double d = whole_number(*v, "/render/max_depth");
            if (d < 0 || d > kMaxRecursionDepth)
                fail_value("/render/max_depth",
                           "\"max_depth\" must be between 0 and 64, got " + source_text("/render/max_depth"),
                           "a few bounces are enough");
            scene_.max_depth = int(d);
        }
        if (const json* v = member(*render, "shadows")) scene_.shadows = boolean(*v, "/render/shadows");
        if (const json* v = member(*render, "fresnel")) scene_.fresnel = boolean(*v, "/render/fresnel");
        if (const json* v = member(*render, "accelerator")) {
            static const std::vector<std::string> names{"none", "bvh"};
            scene_.accelerator = choice(*v, "/render/accelerator", names) == 0 ? Accelerator::None : Accelerator::Bvh;
        }
        if (scene_.mode == RenderMode::BvhVisits && scene_.accelerator != Accelerator::Bvh)
            fail_value("/render/mode", "mode \"bvh_visits\" draws the BVH, but the scene has no \"accelerator\": \"bvh\"",
                       "add \"accelerator\": \"bvh\" to \"render\"");
    }

    void read_camera(const json& root) {
        Projection projection = Projection::Perspective;
        Vec3 eye{0, 0, 5}, look_at{0, 0, 0}, up{0, 1, 0};
        Real fov = 45, view_height = 2;
        const json* camera = member(root, "camera");
        const json empty = json::object();
        if (!camera) camera = &empty;
        require_object(*camera, "/camera", "{\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]}");
        check_keys(*camera, "/camera", "\"camera\"",
                   {"projection", "eye", "look_at", "up", "fov", "view_height"});
        if (const json* v = member(*camera, "projection"))
            projection = choice(*v, "/camera/projection", {"perspective", "orthographic"}) == 0
                             ? Projection::Perspective
                             : Projection::Orthographic;
        if (const json* v = member(*camera, "eye")) eye = vec3(*v, "/camera/eye");
        if (const json* v = member(*camera, "look_at")) look_at = vec3(*v, "/camera/look_at");
        if (const json* v = member(*camera, "up")) up = vec3(*v, "/camera/up");
        if (const json* v = member(*camera, "fov"))
            fov = real_in(*v, "/camera/fov", [](double d) { return d > 0 && d < 180; },
                          "between 0 and 180 degrees (exclusive)", "a typical vertical fov is 30 to 60");
        if (const json* v = member(*camera, "view_height"))
            view_height = real_in(*v, "/camera/view_height", [](double d) { return d > 0; }, "> 0",
                                  "give the height of the visible rectangle in world units");

        // The frame is only defined for a real viewing direction and an up that is not along it.
        auto where = [&](const char* key) {
            return member(*camera, key) ? JsonPositions::child("/camera", key) : std::string("/camera");
        };
        glm::dvec3 direction = glm::dvec3(look_at) - glm::dvec3(eye);
        glm::dvec3 upward(up);
        if (glm::length(direction) == 0)
            fail_value(where(member(*camera, "look_at") ? "look_at" : "eye"),
                       "\"look_at\" equals \"eye\", so the camera has no viewing direction",
                       "move the camera or its target");
        double sine = glm::length(glm::cross(upward, direction)) /
                      (glm::length(upward) * glm::length(direction));
        if (!(sine > 1e-4))
            fail_value(where("up"), "\"up\" is zero or parallel to the viewing direction",
                       "choose an up vector that is not along look_at - eye, e.g. [0, 1, 0] or [0, 0, 1]");
        scene_.camera = make_look_at_camera(projection, eye, look_at, up, fov, view_height);
        const Camera& c = scene_.camera;
        if (!all_finite(c.u) || !all_finite(c.v) || !all_finite(c.w))
            fail_value("/camera", "the camera frame cannot be computed (coordinates too large)",
                       "use smaller camera coordinates");
    }

    void read_materials(const json& root) {
        if (const json* list = member(root, "materials")) {
            require_array(*list, "/materials", "[{\"name\": \"red\", \"diffuse\": [0.8, 0.1, 0.1]}]");
            for (std::size_t i = 0; i < list->size(); ++i)
                read_material((*list)[i], JsonPositions::child("/materials", i));
        }
        if (scene_.materials.empty()) {
            Material fallback;
            fallback.name = "default";
            scene_.materials.push_back(fallback);
            material_ids_["default"] = 0;
        }
    }

    void read_material(const json& object, const std::string& pointer) {
        require_object(object, pointer, "{\"name\": \"red\", \"diffuse\": [0.8, 0.1, 0.1]}");
        check_keys(object, pointer, "a material",
                   {"name", "ambient", "diffuse", "specular", "emissive", "shininess", "reflective",
                    "transmissive", "ior"});
        Material m;
        if (const json* v = member(object, "name")) {
            std::string name_pointer = JsonPositions::child(pointer, "name");
            m.name = string(*v, name_pointer, "\"red\"");
            if (m.name.empty())
                fail_value(name_pointer, "a material name must not be empty", "name it or leave \"name\" out");
            auto [it, added] = material_ids_.emplace(m.name, int(scene_.materials.size()));
            if (!added)
                fail_value(name_pointer,
                           "duplicate material name " + quote(m.name) + " (material " +
                               std::to_string(it->second) + " has it too)",
                           "give each material its own name");
        }
        struct ColorField {
            const char* key;
            Color Material::*field;
        };
        for (ColorField f : {ColorField{"ambient", &Material::ambient}, {"diffuse", &Material::diffuse},
                             {"specular", &Material::specular}, {"emissive", &Material::emissive},
                             {"reflective", &Material::reflective},
                             {"transmissive", &Material::transmissive}})
            if (const json* v = member(object, f.key)) m.*f.field = color(*v, JsonPositions::child(pointer, f.key));
        if (const json* v = member(object, "shininess"))
            m.shininess = float(real_in(*v, JsonPositions::child(pointer, "shininess"),
                                        [](double d) { return d >= 0; }, ">= 0",
                                        "typical Phong exponents are 1 to 1000"));
        if (const json* v = member(object, "ior"))
            m.ior = float(real_in(*v, JsonPositions::child(pointer, "ior"), [](double d) { return d > 0; },
                                  "> 0", "glass is about 1.5, water 1.33"));
        scene_.materials.push_back(m);
    }

    // "material": a name or an index; omitted means material 0.
    int material_of(const json& surface, const std::string& pointer) const {
        const json* v = member(surface, "material");
        if (!v) return 0;
        return material_ref(*v, JsonPositions::child(pointer, "material"));
    }

    // A material name (string) or index (whole number) at `at`.
    int material_ref(const json& value, const std::string& at) const {
        const json* v = &value;
        if (v->is_string()) {
            std::string name = v->get<std::string>();
            auto it = material_ids_.find(name);
            if (it == material_ids_.end()) {
                std::vector<std::string> names;
                for (const Material& m : scene_.materials)
                    if (!m.name.empty()) names.push_back(m.name);
                std::string fix = names.empty() ? "define it under \"materials\""
                                  : closest(name, names) ? suggestion(name, names)
                                                         : "define it under \"materials\" or use " +
                                                               list_of(names);
                fail_value(at, "unknown material " + quote(name), fix);
            }
            return it->second;
        }
        if (v->is_number()) {
            double d = whole_number(*v, at);
            if (d < 0 || d >= double(scene_.materials.size()))
                fail_value(at,
                           "material index " + source_text(at) + " out of range (the scene has " +
                               std::to_string(scene_.materials.size()) + " material" +
                               (scene_.materials.size() == 1 ? "" : "s") + ")",
                           "use an index from 0 to " + std::to_string(scene_.materials.size() - 1) +
                               " or a material name");
            return int(d);
        }
        fail_value(at, label(at) + " must be a material name or index, got " + describe(*v),
                   "write e.g. \"material\": \"red\" or \"material\": 0");
    }

    void read_surfaces(const json& root) {
        const json* list = member(root, "surfaces");
        if (!list) return;
        require_array(*list, "/surfaces", "[{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}]");
        for (std::size_t i = 0; i < list->size(); ++i) read_surface((*list)[i], JsonPositions::child("/surfaces", i));
        pad_shading_data();
    }

    void read_surface(const json& s, const std::string& pointer) {
        static const std::vector<std::string> types{"sphere", "plane", "triangle", "box", "mesh",
                                                    "checkerboard"};
        require_object(s, pointer, "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}");
        const json& type_value = required(s, pointer, "type", "a surface", list_of(types));
        std::size_t type = choice(type_value, JsonPositions::child(pointer, "type"), types);
        auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
        switch (type) {
            case 0: {
                check_keys(s, pointer, "a sphere", {"type", "center", "radius", "material"});
                Sphere sphere;
                sphere.center = vec3(required(s, pointer, "center", "a sphere", "[x, y, z]"), at("center"));
                sphere.radius = real_in(required(s, pointer, "radius", "a sphere", "1"), at("radius"),
                                        [](double d) { return d > 0; }, "> 0",
                                        "give the sphere a positive radius");
                sphere.material = material_of(s, pointer);
                scene_.spheres.push_back(sphere);
                break;
            }
            case 1: {
                check_keys(s, pointer, "a plane", {"type", "point", "normal", "material"});
                Plane plane;
                plane.point = vec3(required(s, pointer, "point", "a plane", "[x, y, z]"), at("point"));
                plane.normal = unit_direction(required(s, pointer, "normal", "a plane", "[0, 1, 0]"),
                                              at("normal"), "give the plane a normal such as [0, 1, 0]");
                plane.material = material_of(s, pointer);
                scene_.planes.push_back(plane);
                break;
            }
            case 2: {
                check_keys(s, pointer, "a triangle", {"type", "vertices", "material"});
                const json& corners = required(s, pointer, "vertices", "a triangle", "[[x, y, z], [x, y, z], [x, y, z]]");
                if (!corners.is_array() || corners.size() != 3)
                    fail_value(at("vertices"),
                               "\"vertices\" must be an array of 3 points, got " +
                                   (corners.is_array() ? std::to_string(corners.size()) + " points"
                                                       : describe(corners)),
                               "write [[x, y, z], [x, y, z], [x, y, z]]");
                Triangle triangle;
                for (std::size_t k = 0; k < 3; ++k) {
                    check_vertex_room(1, at("vertices"));
                    triangle.v[k] = std::uint32_t(scene_.vertices.size());
                    scene_.vertices.push_back(vec3(corners[k], JsonPositions::child(at("vertices"), k)));
                }
                triangle.material = material_of(s, pointer);
                check_triangle_room(1, at("vertices"));
                scene_.triangles.push_back(triangle);
                break;
            }
            case 3: {
                check_keys(s, pointer, "a box", {"type", "min", "max", "material"});
                Box box;
                box.min = vec3(required(s, pointer, "min", "a box", "[x, y, z]"), at("min"));
                box.max = vec3(required(s, pointer, "max", "a box", "[x, y, z]"), at("max"));
                for (int k = 0; k < 3; ++k)
                    if (box.min[k] > box.max[k])
                        fail_value(JsonPositions::child(at("max"), std::size_t(k)),
                                   std::string("\"max\" must not be below \"min\", but ") + "xyz"[k] +
                                       " is " + source_text(JsonPositions::child(at("max"), std::size_t(k))) +
                                       " < " + source_text(JsonPositions::child(at("min"), std::size_t(k))),
                                   "swap the values or fix the corner");
                box.material = material_of(s, pointer);
                scene_.boxes.push_back(box);
                break;
            }
            case 4:
                check_keys(s, pointer, "a mesh",
                           {"type", "file", "procedural", "triangles", "seed", "translate", "scale", "material"});
                read_mesh(s, pointer);
                break;
            default:
                check_keys(s, pointer, "a checkerboard", {"type", "min", "max", "tiles", "materials"});
                read_checkerboard(s, pointer);
                break;
        }
    }

    // A "checkerboard": shorthand for a floor of tiles[0] x tiles[1] boxes between "min" and
    // "max" (docs/scene-format.md). Tile (i, j) spans x edges i..i+1 and z edges j..j+1, where
    // edge k = min + (max - min) * k / n in double (edge n is max itself), and all of min.y..max.y;
    // it gets materials[(i + j) % 2]. Boxes are appended with i outer, j inner.
    void read_checkerboard(const json& s, const std::string& pointer) {
        auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
        const json& lo_value = required(s, pointer, "min", "a checkerboard", "[x, y, z]");
        const json& hi_value = required(s, pointer, "max", "a checkerboard", "[x, y, z]");
        const Vec3 lo = vec3(lo_value, at("min")), hi = vec3(hi_value, at("max"));
        for (int k = 0; k < 3; ++k) {
            const bool flat = k != 1;  // the board needs an area in x and z; y may be thin
            const double a = lo_value[std::size_t(k)].get<double>(), b = hi_value[std::size_t(k)].get<double>();
            if (flat ? !(a < b) : !(a <= b)) {
                const std::string element = JsonPositions::child(at("max"), std::size_t(k));
                fail_value(element,
                           std::string("\"max\" must ") + (flat ? "be above" : "not be below") +
                               " \"min\", but " + "xyz"[k] + " is " + source_text(element) +
                               (flat ? " <= " : " < ") +
                               source_text(JsonPositions::child(at("min"), std::size_t(k))),
                           flat ? "give the board an area in x and z" : "swap the values or fix the corner");
            }
        }
        const json& tiles = required(s, pointer, "tiles", "a checkerboard", "[8, 8]");
        if (!tiles.is_array() || tiles.size() != 2)
            fail_value(at("tiles"),
                       "\"tiles\" must be an array of 2 whole numbers (along x, along z), got " +
                           (tiles.is_array() ? std::to_string(tiles.size()) + " numbers" : describe(tiles)),
                       "write it as [8, 8]");
        std::size_t count[2];
        for (std::size_t k = 0; k < 2; ++k) {
            const std::string element = JsonPositions::child(at("tiles"), k);
            const double d = whole_number(tiles[k], element);
            if (d < 1 || d > kMaxCheckerTiles)
                fail_value(element, label(element) + " must be between 1 and " +
                                        std::to_string(int(kMaxCheckerTiles)) + ", got " + source_text(element),
                           "use fewer, larger tiles");
            count[k] = std::size_t(d);
        }
        const json& materials = required(s, pointer, "materials", "a checkerboard", "[\"dark\", \"light\"]");
        if (!materials.is_array() || materials.size() != 2)
            fail_value(at("materials"),
                       "\"materials\" must be an array of 2 materials, got " +
                           (materials.is_array() ? std::to_string(materials.size()) + " entries"
                                                 : describe(materials)),
                       "write it as [\"dark\", \"light\"] (names or indices)");
        const int material[2] = {material_ref(materials[0], JsonPositions::child(at("materials"), std::size_t(0))),
                                 material_ref(materials[1], JsonPositions::child(at("materials"), std::size_t(1)))};
        // The edges in double, from the numbers as written (not from their Real roundings).
        auto edges = [](double a, double b, std::size_t n) {
            std::vector<Real> e(n + 1);
            for (std::size_t k = 0; k < n; ++k) e[k] = Real(std::min(a + (b - a) * double(k) / double(n), b));
            e[n] = Real(b);
            return e;
        };
        const std::vector<Real> ex = edges(lo_value[0].get<double>(), hi_value[0].get<double>(), count[0]);
        const std::vector<Real> ez = edges(lo_value[2].get<double>(), hi_value[2].get<double>(), count[1]);
        scene_.boxes.reserve(scene_.boxes.size() + count[0] * count[1]);
        for (std::size_t i = 0; i < count[0]; ++i)
            for (std::size_t j = 0; j < count[1]; ++j) {
                Box box;
                box.min = Vec3(ex[i], lo.y, ez[j]);
                box.max = Vec3(ex[i + 1], hi.y, ez[j + 1]);
                box.material = material[(i + j) % 2];
                scene_.boxes.push_back(box);
            }
    }

    void check_vertex_room(std::size_t more, const std::string& pointer) const {
        if (scene_.vertices.size() + more > std::size_t(UINT32_MAX))
            fail_value(pointer, "too many vertices in the scene", "use smaller meshes");
    }
    void check_triangle_room(std::size_t more, const std::string& pointer) const {
        if (scene_.triangles.size() + more > kMaxTriangles)
            fail_value(pointer, "the scene has more than 20000000 triangles", "use smaller meshes");
    }

    // A "mesh" surface: exactly one of "file" (an OBJ file) and "procedural" (a generated mesh,
    // framework/geometry/procedural_mesh.h), each placed by "scale", then "translate".
    void read_mesh(const json& s, const std::string& pointer) {
        auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
        const json* file_value = member(s, "file");
        const json* shape_value = member(s, "procedural");
        if (file_value && shape_value)
            fail_key(at("procedural"), "a mesh has \"file\" or \"procedural\", not both",
                     "keep the one you mean");
        if (!file_value && !shape_value)
            fail_value(pointer, "a mesh needs \"file\" or \"procedural\"",
                       "add \"file\": \"model.obj\" or e.g. \"procedural\": \"torus\", \"triangles\": 1000");
        if (file_value)
            for (const char* key : {"triangles", "seed"})
                if (member(s, key))
                    fail_key(at(key), std::string("\"") + key + "\" is only for procedural meshes",
                             "remove it (an OBJ file has its own triangles)");
        Vec3 translate{0}, scale{1};
        if (const json* v = member(s, "translate")) translate = vec3(*v, at("translate"));
        if (const json* v = member(s, "scale")) {
            scale = v->is_number() ? Vec3(real(*v, at("scale"))) : vec3(*v, at("scale"));
            if (scale.x == 0 || scale.y == 0 || scale.z == 0)
                fail_value(at("scale"), "\"scale\" must not be 0", "use 1 to keep the mesh's size");
        }
        int material = material_of(s, pointer);
        if (shape_value) read_procedural_mesh(s, pointer, scale, translate, material);
        else read_obj_mesh(*file_value, at("file"), scale, translate, material);
    }

    void read_procedural_mesh(const json& s, const std::string& pointer, Vec3 scale, Vec3 translate,
                              int material) {
        auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
        const std::vector<std::string>& shapes = procedural_shapes();
        const std::string& shape = shapes[choice(*member(s, "procedural"), at("procedural"), shapes)];
        double count = whole_number(required(s, pointer, "triangles", "a procedural mesh", "1000"), at("triangles"));
        if (count < 1 || count > double(kMaxTriangles))
            fail_value(at("triangles"), "\"triangles\" must be between 1 and 20000000, got " + source_text(at("triangles")),
                       "ask for fewer triangles");
        std::uint64_t seed = 1;
        if (const json* v = member(s, "seed")) {
            double d = whole_number(*v, at("seed"));
            if (d < 0 || d > 9007199254740992.0)  // 2^53: every whole number up to it is exact
                fail_value(at("seed"), "\"seed\" must be between 0 and 9007199254740992, got " + source_text(at("seed")),
                           "any whole number in that range will do");
            seed = std::uint64_t(d);
        }
        const std::size_t room = kMaxTriangles - scene_.triangles.size();
        TriangleMesh mesh;
        try {
            ProceduralResolution resolution = procedural_resolution(shape, std::size_t(count));
            if (resolution.triangles > room)
                fail_value(at("triangles"),
                           "the scene would have more than 20000000 triangles (this " + shape + " has " +
                               std::to_string(resolution.triangles) + ")",
                           "ask for fewer triangles");
            mesh = make_procedural_mesh(shape, std::size_t(count), seed);
        } catch (const std::invalid_argument& e) {
            fail_value(at("triangles"), e.what(), "ask for fewer triangles");
        }
        check_vertex_room(mesh.vertices.size(), at("procedural"));
        for (Vec3& p : mesh.vertices) {
            p = p * scale + translate;
            if (!all_finite(p))
                fail_value(member(s, "scale") ? at("scale") : at("translate"),
                           "the mesh is too large to represent once scaled and translated",
                           "use a smaller \"scale\" or \"translate\"");
        }
        for (Vec3& n : mesh.normals) n = scale_normal(n, scale);
        if (scale.x * scale.y * scale.z < 0)  // mirrored: keep the outward side outward
            for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
        append_mesh(mesh.vertices, mesh.normals, mesh.uvs, mesh.triangles,
                    [&](std::size_t) { return material; });
    }

    void read_obj_mesh(const json& file_value, const std::string& file_pointer, Vec3 scale, Vec3 translate,
                       int material) {
        std::string file = string(file_value, file_pointer, "\"model.obj\"");
        if (file.empty()) fail_value(file_pointer, "\"file\" is empty", "name an .obj file");
        fs::path path = fs::path(file).is_absolute() ? fs::path(file) : base_dir_ / file;
        // A usemtl name picks, in this order: the scene material of that name, the scene material
        // named "<file>:<name>", a new material made from the OBJ's .mtl definition (named
        // "<file>:<name>", shared by later meshes of the same file); without any mtllib in the
        // file, the surface's "material".
        auto in_scene = [&](const std::string& name) -> const int* {
            auto it = material_ids_.find(name);
            if (it == material_ids_.end()) it = material_ids_.find(file + ":" + name);
            return it == material_ids_.end() ? nullptr : &it->second;
        };
        ObjMesh mesh;
        try {
            mesh = load_obj(path, file, scale, translate, kMaxTriangles - scene_.triangles.size(),
                            [&](const std::string& name) { return in_scene(name) != nullptr; });
        } catch (const ObjError& e) {
            fail_at(positions_->value_offset(file_pointer), e.what());
        }
        for (const std::string& warning : mesh.warnings)
            std::fprintf(stderr, "%s: warning: %s\n", scene_.source.c_str(), warning.c_str());
        check_vertex_room(mesh.vertices.size(), file_pointer);
        std::vector<int> by_obj_material;
        for (const ObjMaterial& m : mesh.materials) {
            int id = material;
            if (const int* known = in_scene(m.name)) {
                id = *known;
            } else if (m.defined) {
                Material made = m.material;
                made.name = file + ":" + m.name;
                id = int(scene_.materials.size());
                material_ids_.emplace(made.name, id);
                scene_.materials.push_back(made);
            }
            by_obj_material.push_back(id);
        }
        append_mesh(mesh.vertices, mesh.normals, mesh.uvs, mesh.triangles, [&](std::size_t i) {
            int obj_material = mesh.triangle_material[i];
            return obj_material < 0 ? material : by_obj_material[std::size_t(obj_material)];
        });
    }

    // Appends a mesh to the scene's flat arrays. `normals` and `uvs` are each empty or one per
    // vertex; Scene::normals and Scene::uvs stay empty until some mesh has them, and from then
    // on hold one entry per scene vertex, (0, 0, 0) and (0, 0) for vertices without (see
    // scene.h). pad_shading_data() fills in the vertices added after the last mesh.
    template <typename MaterialOf>
    void append_mesh(const std::vector<Vec3>& vertices, const std::vector<Vec3>& normals,
                     const std::vector<Vec2>& uvs, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                     MaterialOf material_of_triangle) {
        const std::size_t first = scene_.vertices.size();
        scene_.vertices.insert(scene_.vertices.end(), vertices.begin(), vertices.end());
        if (!normals.empty() || !scene_.normals.empty()) {
            scene_.normals.resize(first, Vec3(0));
            if (normals.empty()) scene_.normals.resize(scene_.vertices.size(), Vec3(0));
            else scene_.normals.insert(scene_.normals.end(), normals.begin(), normals.end());
        }
        if (!uvs.empty() || !scene_.uvs.empty()) {
            scene_.uvs.resize(first, Vec2(0));
            if (uvs.empty()) scene_.uvs.resize(scene_.vertices.size(), Vec2(0));
            else scene_.uvs.insert(scene_.uvs.end(), uvs.begin(), uvs.end());
        }
        scene_.triangles.reserve(scene_.triangles.size() + triangles.size());
        for (std::size_t i = 0; i < triangles.size(); ++i) {
            Triangle t;
            for (std::size_t k = 0; k < 3; ++k) t.v[k] = triangles[i][k] + std::uint32_t(first);
            t.material = material_of_triangle(i);
            scene_.triangles.push_back(t);
        }
    }

    void pad_shading_data() {
        if (!scene_.normals.empty()) scene_.normals.resize(scene_.vertices.size(), Vec3(0));
        if (!scene_.uvs.empty()) scene_.uvs.resize(scene_.vertices.size(), Vec2(0));
    }

    void read_lights(const json& root) {
        const json* list = member(root, "lights");
        if (!list) return;
        require_array(*list, "/lights", "[{\"type\": \"point\", \"position\": [0, 5, 0]}]");
        for (std::size_t i = 0; i < list->size(); ++i) read_light((*list)[i], JsonPositions::child("/lights", i));
    }

    void read_light(const json& object, const std::string& pointer) {
        static const std::vector<std::string> types{"point", "directional"};
        require_object(object, pointer, "{\"type\": \"point\", \"position\": [0, 5, 0]}");
        const json& type_value = required(object, pointer, "type", "a light", list_of(types));
        Light light;
        auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
        if (choice(type_value, at("type"), types) == 0) {
            check_keys(object, pointer, "a point light", {"type", "position", "intensity", "attenuation"});
            light.kind = LightKind::Point;
            light.position = vec3(required(object, pointer, "position", "a point light", "[x, y, z]"), at("position"));
            if (const json* v = member(object, "attenuation")) {
                Color a = color(*v, at("attenuation"));
                if (a.x == 0 && a.y == 0 && a.z == 0)
                    fail_value(at("attenuation"), "\"attenuation\" must not be all zero",
                               "use [1, 0, 0] for no fall-off");
                light.attenuation = Vec3(a);
            }
        } else {
            check_keys(object, pointer, "a directional light", {"type", "direction", "intensity"});
            light.kind = LightKind::Directional;
            light.direction = unit_direction(required(object, pointer, "direction", "a directional light", "[0, -1, 0]"),
                                             at("direction"), "give the direction the light travels, e.g. [0, -1, 0]");
        }
        if (const json* v = member(object, "intensity")) light.intensity = color(*v, at("intensity"));
        scene_.lights.push_back(light);
    }

    const std::string& text_;
    std::string name_;
    fs::path base_dir_;
    json root_;
    std::optional<JsonPositions> positions_;
    Scene scene_;
    std::map<std::string, int> material_ids_;
};

}  // namespace

Scene parse_scene(const std::string& text, const std::string& name, const fs::path& base_dir) {
    try {
        return Loader(text, name, base_dir).load();
    } catch (const json::exception& e) {  // a safety net: every check should come first
        throw SceneError(one_line(name + ":1:1: error: unexpected problem reading the scene (" +
                                  std::string(e.what()) + "); please report this file"));
    }
}

std::string read_scene_text(const fs::path& file) {
    const std::string name = file.string();
    auto fail = [&](const std::string& what, const std::string& fix) {
        throw SceneError(one_line(name + ":1:1: error: " + what + "; " + fix));
    };
    std::error_code ec;
    fs::file_status status = fs::status(file, ec);
    if (!fs::exists(status)) fail("no such file", "check the path");
    if (fs::is_directory(status)) fail("is a directory, not a scene file", "give the path of a .json file");
    std::ifstream in(file, std::ios::binary);
    if (!in) fail("cannot open the file", "check its permissions");
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, std::size_t(in.gcount()));
        if (text.size() > kMaxSceneFileBytes)
            fail("the file is larger than 64 MiB", "put large geometry in an OBJ mesh");
    }
    if (in.bad()) fail("the file could not be read", "check the file");
    return text;
}

Scene load_scene(const fs::path& file) {
    return parse_scene(read_scene_text(file), file.string(), file.parent_path());
}

}  // namespace rt
