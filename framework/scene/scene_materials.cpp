// The scene's materials: the "materials" list and references to it by name or index.
#include "scene/scene_sections.h"

#include "scene/message_text.h"

namespace rt::schema {
const SchemaElement kMaterial{"a material",
                              "",
                              {"Materials", "Sampling"},
                              {{"name"},
                               {"ambient"},
                               {"diffuse"},
                               {"specular"},
                               {"emissive"},
                               {"shininess"},
                               {"reflective"},
                               {"transmissive"},
                               {"ior"},
                               {"fuzz"},
                               {"roughness"},
                               {"diffuse_map"},
                               {"specular_map"},
                               {"emissive_map"},
                               {"normal_map"}}};
}  // namespace rt::schema

namespace rt::scene_internal {

void SceneSections::read_materials(const json& root) {
    if (const json* list = member(root, "materials")) {
        require_array(*list, "/materials", "[{\"name\": \"red\", \"diffuse\": [0.8, 0.1, 0.1]}]");
        for (std::size_t i = 0; i < list->size(); ++i)
            read_material((*list)[i], JsonPositions::child("/materials", i));
    }
    if (scene_.materials.empty()) {
        material_ids_["default"] = scene_.add_material(Material{}, "default");
    }
}

void SceneSections::read_material(const json& object, const std::string& pointer) {
    require_object(object, pointer, "{\"name\": \"red\", \"diffuse\": [0.8, 0.1, 0.1]}");
    check_keys(object, pointer, schema::kMaterial);
    Material m;
    std::string name;
    if (const json* v = member(object, "name")) {
        std::string name_pointer = JsonPositions::child(pointer, "name");
        name = string(*v, name_pointer, "\"red\"");
        if (name.empty())
            fail_value(name_pointer, "a material name must not be empty",
                       "name it or leave \"name\" out");
        auto [it, added] = material_ids_.emplace(name, int(scene_.materials.size()));
        if (!added)
            fail_value(name_pointer,
                       "duplicate material name " + quote(name) + " (material " +
                           std::to_string(it->second) + " has it too)",
                       "give each material its own name");
    }
    struct ColorField {
        const char* key;
        Color Material::*field;
    };
    for (ColorField f : {ColorField{"ambient", &Material::ambient},
                         {"diffuse", &Material::diffuse},
                         {"specular", &Material::specular},
                         {"emissive", &Material::emissive},
                         {"reflective", &Material::reflective},
                         {"transmissive", &Material::transmissive}})
        if (const json* v = member(object, f.key))
            m.*f.field = color(*v, JsonPositions::child(pointer, f.key));
    if (const json* v = member(object, "shininess"))
        m.shininess = float(real_in(
            *v, JsonPositions::child(pointer, "shininess"), [](double d) { return d >= 0; }, ">= 0",
            "typical Phong exponents are 1 to 1000"));
    if (const json* v = member(object, "ior"))
        m.ior = float(real_in(
            *v, JsonPositions::child(pointer, "ior"), [](double d) { return d > 0; }, "> 0",
            "glass is about 1.5, water 1.33"));
    if (const json* v = member(object, "fuzz"))
        m.fuzz = float(real_in(
            *v, JsonPositions::child(pointer, "fuzz"), [](double d) { return d >= 0 && d <= 1; },
            "between 0 and 1", "0 is a mirror, 0.3 brushed metal"));
    if (const json* v = member(object, "roughness"))
        m.roughness = float(real_in(
            *v, JsonPositions::child(pointer, "roughness"),
            [](double d) { return d >= 0 && d <= 1; }, "between 0 and 1",
            "0 is a mirror, 0.2 polished, 0.6 rough (path tracing, stage 11)"));
    struct SlotField {
        const char* key;
        TextureSlot Material::*slot;
    };
    for (SlotField f : {SlotField{"diffuse_map", &Material::diffuse_map},
                        {"specular_map", &Material::specular_map},
                        {"emissive_map", &Material::emissive_map},
                        {"normal_map", &Material::normal_map}})
        if (const json* v = member(object, f.key))
            m.*f.slot = texture_slot(*v, JsonPositions::child(pointer, f.key));
    scene_.add_material(m, name);
}

int SceneSections::material_of(const json& surface, const std::string& pointer) const {
    const json* v = member(surface, "material");
    if (!v) return 0;
    return material_ref(*v, JsonPositions::child(pointer, "material"));
}

int SceneSections::material_ref(const json& value, const std::string& at) const {
    const json* v = &value;
    if (v->is_string()) {
        std::string name = v->get<std::string>();
        auto it = material_ids_.find(name);
        if (it == material_ids_.end()) {
            std::vector<std::string> names;
            for (const std::string& known : scene_.material_names)
                if (!known.empty()) names.push_back(known);
            std::string fix = names.empty() ? "define it under \"materials\""
                              : closest(name, names)
                                  ? suggestion(name, names)
                                  : "define it under \"materials\" or use " + list_of(names);
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

}  // namespace rt::scene_internal
