// MTL material libraries (scene/mtl_reader.h).
#include "scene/mtl_reader.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <string_view>

#include "scene/obj_text.h"

namespace rt::obj_internal {

namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxMtlBytes = std::uintmax_t(64) << 20;  // 64 MiB

// What an MTL file says about one material, beyond tinyobjloader's values: which keys it gave
// (absent ones keep the scene's defaults).
struct MtlKeys {
    bool ambient = false, diffuse = false, specular = false, emissive = false;
    bool shininess = false, ior = false, dissolve = false;
};

// The rule a value of the key `word` (taking `count` numbers) breaks, or "" when it keeps it:
// colours and Ns are never negative, d and Tr are fractions, illum is a model number.
std::string broken_value_rule(const std::string& word, std::size_t count, double value) {
    if ((count == 3 || word == "Ns") && !(value >= 0)) return ">= 0";
    if ((word == "d" || word == "Tr") && !(value >= 0 && value <= 1)) return "between 0 and 1";
    if (word == "illum" && !(value >= 0 && value <= 10 && value == std::floor(value)))
        return "a whole number 0..10";
    return "";
}

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
            const std::string material(directive_argument(s, 6));
            if (material.empty())
                complain(line, "\"newmtl\" needs a name", "write \"newmtl name\"");
            auto [it, added] = first_line.emplace(material, line);
            if (!added)
                complain(line,
                         "material " + shown(material) + " is defined again (first on line " +
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
            {"Ka", 3, &MtlKeys::ambient},
            {"Kd", 3, &MtlKeys::diffuse},
            {"Ks", 3, &MtlKeys::specular},
            {"Ke", 3, &MtlKeys::emissive},
            {"Tf", 3, nullptr},
            {"Kt", 3, nullptr},
            {"Ns", 1, &MtlKeys::shininess},
            {"Ni", 1, &MtlKeys::ior},
            {"d", 1, &MtlKeys::dissolve},
            {"Tr", 1, &MtlKeys::dissolve},
            {"illum", 1, nullptr},
        };
        for (const Key& key : kKeys) {
            if (!is_directive(s, key.word)) continue;
            std::string word = key.word;
            if (!current)
                complain(line, shown(word) + " comes before any \"newmtl\"",
                         "start the material with \"newmtl name\"");
            std::vector<std::string_view> values = words(s.substr(word.size()));
            std::string form = word + (key.count == 3 ? " r g b" : " value");
            if (values.size() != key.count)
                complain(line,
                         shown(word) + " has " + std::to_string(values.size()) + " number" +
                             (values.size() == 1 ? "" : "s") + ", not " + std::to_string(key.count),
                         "write \"" + form + "\"");
            for (std::string_view v : values) {
                double value;
                Number n = parse_number(v, value);
                if (n != Number::Ok)
                    complain(line,
                             shown(word) + " value " + shown(v) +
                                 (n == Number::NotFinite ? " is not finite" : " is not a number"),
                             "write \"" + form + "\" with ordinary numbers");
                if (const std::string rule = broken_value_rule(word, key.count, value);
                    !rule.empty())
                    complain(line, shown(word) + " must be " + rule + ", got " + shown(v),
                             "fix the value");
            }
            if (key.given) current->*key.given = true;
            return;
        }
    });
    return keys;
}

// The scene material for an MTL one (docs/scene-format.md, "Materials from MTL files").
Material to_scene_material(const tinyobj::material_t& m, const MtlKeys& keys) {
    auto color = [](const tinyobj::real_t* c) {
        return Color(float(c[0]), float(c[1]), float(c[2]));
    };
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

}  // namespace

void read_libraries(const fs::path& obj_file, const std::string& name, const ObjSummary& summary,
                    std::vector<ObjMaterial>& materials, const std::vector<bool>& wanted) {
    for (const MaterialLibrary& library : summary.libraries) {
        fs::path path = fs::path(library.file);
        if (!path.is_absolute()) path = obj_file.parent_path() / path;
        std::string text = read_mesh_file(
            path, kMaxMtlBytes, "a material library",
            [&](const std::string& what, const std::string&) {
                fail(name, library.line, "material library " + shown(library.file) + " " + what,
                     "put the .mtl file beside the .obj (the mtllib path is relative to it), or "
                     "define the "
                     "materials in the scene");
            });
        std::map<std::string, MtlKeys> keys = check_mtl_text(text, name, library.file);
        std::map<std::string, int> tinyobj_ids;
        std::vector<tinyobj::material_t> definitions;
        std::string warnings, errors;
        std::istringstream stream(text);
        tinyobj::LoadMtl(&tinyobj_ids, &definitions, &stream, &warnings, &errors);
        // tinyobjloader keeps a newmtl name's blanks as written; names here are trimmed.
        std::map<std::string, int> ids;
        for (std::size_t d = 0; d < definitions.size(); ++d)
            ids.emplace(std::string(directive_argument(definitions[d].name, 0)), int(d));
        for (std::size_t i = 0; i < materials.size(); ++i) {
            ObjMaterial& m = materials[i];
            if (!wanted[i] || m.defined) continue;  // the first library defining a name wins
            auto id = ids.find(m.name);
            auto given = keys.find(m.name);
            if (id == ids.end() || given == keys.end() || id->second < 0 ||
                std::size_t(id->second) >= definitions.size())
                continue;
            const tinyobj::material_t& d = definitions[std::size_t(id->second)];
            m.material = to_scene_material(d, given->second);
            // map_Bump usually holds a normal map in the files this framework meets (and is the
            // only bump key many exporters write); norm wins when both are given.
            const bool norm = !d.normal_texname.empty();
            const std::pair<const std::string*, const tinyobj::texture_option_t*> maps[4] = {
                {&d.diffuse_texname, &d.diffuse_texopt},
                {&d.specular_texname, &d.specular_texopt},
                {&d.emissive_texname, &d.emissive_texopt},
                {norm ? &d.normal_texname : &d.bump_texname,
                 norm ? &d.normal_texopt : &d.bump_texopt}};
            for (int k = 0; k < 4; ++k) {
                if (maps[k].first->empty()) continue;
                ObjTextureMap& out = m.maps[k];
                out.file = fs::path(*maps[k].first);
                if (!out.file.is_absolute()) out.file = path.parent_path() / out.file;
                out.scale[0] = float(maps[k].second->scale[0]);
                out.scale[1] = float(maps[k].second->scale[1]);
                out.offset[0] = float(maps[k].second->origin_offset[0]);
                out.offset[1] = float(maps[k].second->origin_offset[1]);
                out.clamp = maps[k].second->clamp;
            }
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
             "add \"newmtl " + materials[i].name.substr(0, 40) +
                 "\" to the library or a scene material of that name");
    }
}

}  // namespace rt::obj_internal
