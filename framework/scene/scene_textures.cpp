// The scene's texture table (stage 07): the "textures" list, the texture slots of materials
// ("diffuse_map": "bricks" or {"texture": "bricks", "scale": [4, 4], "offset": [0, 0]}) and the
// images they read. Syntax: docs/scene-format.md#textures.
#include <algorithm>
#include <cctype>

#include "image/image.h"
#include "scene/message_text.h"
#include "scene/scene_sections.h"

namespace rt::schema {
const SchemaElement kTexture{"a texture",
                             "",
                             {"Textures"},
                             {{"name", kRequired},
                              {"image"},
                              {"checker"},
                              {"checker_3d"},
                              {"marble"},
                              {"filter"},
                              {"wrap"},
                              {"color_space"},
                              {"colour_space"}}};
const SchemaElement kTextureSlot{
    "a texture slot", "", {"Materials"}, {{"texture", kRequired}, {"scale"}, {"offset"}}};
const SchemaElement kCheckerTexture{"a checker texture", "", {"Textures"}, {{"a"}, {"b"}}};
const SchemaElement kChecker3dTexture{
    "a checker_3d texture", "", {"Textures"}, {{"a"}, {"b"}, {"scale"}}};
const SchemaElement kMarbleTexture{"a marble texture", "", {"Textures"}, {{"a"}, {"b"}, {"scale"}}};
}  // namespace rt::schema

namespace rt::scene_internal {
namespace {

namespace fs = std::filesystem;

constexpr const char* kTextureExample =
    R"({"name": "bricks", "image": "bricks.png"} or {"name": "checks", "checker": {"a": [1, 1, 1], "b": [0, 0, 0]}})";

}  // namespace

void SceneSections::read_textures(const json& root) {
    const json* list = member(root, "textures");
    if (!list) return;
    require_array(*list, "/textures", std::string("[") + kTextureExample + "]");
    for (std::size_t i = 0; i < list->size(); ++i)
        read_texture((*list)[i], JsonPositions::child("/textures", i));
}

// "color_space", or its old spelling "colour_space" (accepted with a warning); not both.
const char* SceneSections::color_space_key(const json& object, const std::string& pointer) const {
    if (!member(object, "colour_space")) return "color_space";
    const std::string old_key = JsonPositions::child(pointer, "colour_space");
    if (member(object, "color_space"))
        fail_key(old_key, "a texture has \"color_space\" and its old spelling \"colour_space\"",
                 "remove \"colour_space\"");
    warn_key(old_key, "\"colour_space\" is the old spelling of \"color_space\"",
             "rename the key to \"color_space\"");
    return "colour_space";
}

void SceneSections::read_texture(const json& object, const std::string& pointer) {
    require_object(object, pointer, kTextureExample);
    check_keys(object, pointer, schema::kTexture);
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    const std::string name_pointer = at("name");
    const std::string name =
        string(required(object, pointer, "name", "a texture name", "\"bricks\""), name_pointer,
               "\"bricks\"");
    if (name.empty())
        fail_value(name_pointer, "a texture name must not be empty", "name it, e.g. \"bricks\"");
    const int index = int(scene_.textures.size());
    if (auto [it, added] = texture_ids_.emplace(name, index); !added)
        fail_value(name_pointer,
                   "duplicate texture name " + quote(name) + " (texture " +
                       std::to_string(it->second) + " has it too)",
                   "give each texture its own name");

    // Exactly one source: an image file or one procedural kind.
    const char* sources[] = {"image", "checker", "checker_3d", "marble"};
    std::vector<std::string> given;
    for (const char* s : sources)
        if (member(object, s)) given.push_back(s);
    if (given.size() != 1)
        fail_value(pointer,
                   given.empty() ? "a texture needs a source"
                                 : "a texture has one source, got \"" + given[0] + "\" and \"" +
                                       given[1] + "\"",
                   "give one of \"image\", \"checker\", \"checker_3d\", \"marble\"");

    Texture t;
    int color_space = -1;  // -1: by file and use (finish_textures), 0 linear, 1 sRGB
    if (const json* v = member(object, "image")) {
        const std::string file = string(*v, at("image"), "\"bricks.png\"");
        if (file.empty()) fail_value(at("image"), "\"image\" is empty", "name an image file");
        const fs::path path = fs::path(file).is_absolute() ? fs::path(file) : base_dir_ / file;
        t.kind = TextureKind::Image;
        t.image = texture_image(path, at("image"));
        texture_float_file_.push_back(image_info_.at(t.image).floating);
    } else {
        const char* kind = given[0].c_str();
        const json& p = object[kind];
        const std::string pp = at(kind);
        if (given[0] == "checker") t.kind = TextureKind::Checker2D;
        if (given[0] == "checker_3d") t.kind = TextureKind::Checker3D;
        if (given[0] == "marble") t.kind = TextureKind::Marble;
        require_object(p, pp, R"({"a": [1, 1, 1], "b": [0, 0, 0]})");
        check_keys(p, pp,
                   t.kind == TextureKind::Checker2D   ? schema::kCheckerTexture
                   : t.kind == TextureKind::Checker3D ? schema::kChecker3dTexture
                                                      : schema::kMarbleTexture);
        if (const json* a = member(p, "a")) t.a = color(*a, JsonPositions::child(pp, "a"));
        if (const json* b = member(p, "b")) t.b = color(*b, JsonPositions::child(pp, "b"));
        if (const json* s = member(p, "scale"))
            t.scale = float(real_in(
                *s, JsonPositions::child(pp, "scale"), [](double d) { return d > 0; }, "> 0",
                "the size of a cube or vein in world units, e.g. 0.5"));
        texture_float_file_.push_back(false);
        texture_pointer_.push_back(pointer);
        for (const char* key : {"filter", "wrap", "color_space", "colour_space"})
            if (member(object, key))
                fail_key(at(key), std::string("\"") + key + "\" applies to image textures only",
                         "remove it");
    }
    if (const json* v = member(object, "filter"))
        t.filter = TextureFilter(choice(*v, at("filter"), {"nearest", "bilinear"}));
    if (const json* v = member(object, "wrap"))
        t.wrap = TextureWrap(choice(*v, at("wrap"), {"repeat", "clamp", "mirror"}));
    const char* space_key = color_space_key(object, pointer);
    if (const json* v = member(object, space_key))
        color_space = int(choice(*v, at(space_key), {"linear", "srgb"}));
    if (t.kind == TextureKind::Image) texture_pointer_.push_back(at("image"));
    texture_color_space_.push_back(color_space);
    scene_.textures.push_back(t);
    scene_.texture_names.push_back(name);
}

int SceneSections::texture_image(const fs::path& path, const std::string& pointer) {
    const std::string key = path.lexically_normal().string();
    if (auto cached = image_ids_.find(key); cached != image_ids_.end()) return cached->second;
    Image image;
    ImageInfo info;
    try {
        // As stored: decoding sRGB is the lookup's job (stage 07), per texel.
        image = ::rt::read_image(path, Encoding::Data, &info);
    } catch (const ImageError& e) {
        fail_value(pointer,
                   "texture image " + quote(path.filename().string()) + ": " + e.problem());
    }
    const int index = scene_.add_texture_image(image.width, image.height, image.pixels);
    image_ids_.emplace(key, index);
    image_info_[index] = info;
    return index;
}

TextureSlot SceneSections::mtl_texture_slot(const ObjTextureMap& map, bool data,
                                            const std::string& name, const std::string& pointer) {
    // One texture per (file, wrap, use); named after the file as the OBJ's materials are.
    const std::string texture_name = name + (data ? " (data)" : "") + (map.clamp ? " (clamp)" : "");
    int index = -1;
    if (auto it = texture_ids_.find(texture_name); it != texture_ids_.end()) {
        index = it->second;
    } else {
        Texture t;
        t.kind = TextureKind::Image;
        t.image = texture_image(map.file, pointer);
        t.wrap = map.clamp ? TextureWrap::Clamp : TextureWrap::Repeat;
        if (data && image_info_.at(t.image).channels < 3)
            fail_value(pointer, map.file.string() + " is a normal map (norm or map_Bump) but has " +
                                    std::to_string(image_info_.at(t.image).channels) +
                                    " channel(s); a normal map needs RGB");
        t.srgb = !data && !image_info_.at(t.image).floating;
        index = int(scene_.textures.size());
        scene_.textures.push_back(t);
        scene_.texture_names.push_back(texture_name);
        texture_color_space_.push_back(t.srgb ? 1 : 0);
        texture_pointer_.push_back(pointer);
        texture_float_file_.push_back(image_info_.at(t.image).floating);
        texture_ids_.emplace(texture_name, index);
    }
    TextureSlot slot;
    slot.texture = index;
    slot.scale[0] = map.scale[0];
    slot.scale[1] = map.scale[1];
    slot.offset[0] = map.offset[0];
    slot.offset[1] = map.offset[1];
    return slot;
}

TextureSlot SceneSections::texture_slot(const json& value, const std::string& pointer) {
    TextureSlot slot;
    const json* name = &value;
    const std::string example = R"("bricks" or {"texture": "bricks", "scale": [4, 4]})";
    std::string name_pointer = pointer;
    if (value.is_object()) {
        check_keys(value, pointer, schema::kTextureSlot);
        name_pointer = JsonPositions::child(pointer, "texture");
        name = &required(value, pointer, "texture", "the texture's name", "\"bricks\"");
        auto pair = [&](const char* key, float out[2]) {
            const json* v = member(value, key);
            if (!v) return;
            const std::string at = JsonPositions::child(pointer, key);
            require_array_of(*v, at, 2, "numbers",
                             "got " + std::to_string(v->is_array() ? v->size() : 0),
                             std::string("write e.g. \"") + key + "\": [2, 2]");
            for (std::size_t i = 0; i < 2; ++i)
                out[i] = float(real((*v)[i], JsonPositions::child(at, i)));
        };
        pair("scale", slot.scale);
        pair("offset", slot.offset);
    }
    const std::string texture = string(*name, name_pointer, example);
    auto it = texture_ids_.find(texture);
    if (it == texture_ids_.end()) {
        const std::vector<std::string>& names = scene_.texture_names;
        fail_value(name_pointer, "unknown texture " + quote(texture),
                   names.empty() ? std::string("define it under \"textures\"")
                   : closest(texture, names)
                       ? suggestion(texture, names)
                       : "define it under \"textures\" or use " + list_of(names));
    }
    slot.texture = it->second;
    return slot;
}

void SceneSections::finish_textures() {
    // A texture is sRGB-decoded when it says so, or when it reads an integer file and no
    // material uses it as a normal map (normal maps hold data: docs/conventions.md#textures).
    std::vector<bool> normal_map(scene_.textures.size(), false);
    for (const Material& m : scene_.materials)
        if (m.normal_map.used()) normal_map[std::size_t(m.normal_map.texture)] = true;
    for (std::size_t i = 0; i < scene_.textures.size(); ++i) {
        Texture& t = scene_.textures[i];
        if (t.kind != TextureKind::Image) continue;
        const int channels = image_info_.at(t.image).channels;
        if (normal_map[i] && channels < 3)
            fail_value(texture_pointer_[i],
                       "texture " + quote(scene_.texture_names[i]) +
                           " is a normal map but its image has " + std::to_string(channels) +
                           (channels == 1 ? " channel (grey)" : " channels (grey and alpha)"),
                       "a normal map needs RGB (x, y, z in red, green, blue)");
        const int said = texture_color_space_[i];
        t.srgb = said >= 0 ? said == 1 : !texture_float_file_[i] && !normal_map[i];
    }
}

}  // namespace rt::scene_internal
