// The scene's "mesh" surfaces: OBJ files and procedural meshes, appended to the scene's flat
// vertex and triangle arrays.
#include "scene/scene_sections.h"

#include <cstdio>
#include <stdexcept>

#include "geometry/height_grid.h"
#include "geometry/procedural_mesh.h"
#include "image/image.h"
#include "scene/mesh_placement.h"
#include "scene/obj_loader.h"

namespace rt::schema {
const SchemaElement kHeightField{
    "a height field", "", {"Height fields"}, {{"image", kRequired}, {"height"}}};
}  // namespace rt::schema

namespace rt::scene_internal {

namespace fs = std::filesystem;

namespace {

// Scene::normals and Scene::uvs stay empty until some mesh has them, then hold one entry per
// scene vertex: zeros before `first` and for a mesh without, else the mesh's own.
template <typename T>
void append_per_vertex(std::vector<T>& all, std::size_t first, std::size_t vertex_count,
                       const std::vector<T>& mesh) {
    if (mesh.empty() && all.empty()) return;
    all.resize(first, T(0));
    if (mesh.empty())
        all.resize(vertex_count, T(0));
    else
        all.insert(all.end(), mesh.begin(), mesh.end());
}

}  // namespace

// Appends a mesh to the scene's flat arrays. `normals` and `uvs` are each empty or one per
// vertex; pad_shading_data() fills in the vertices added after the last mesh.
template <typename MaterialOf>
void SceneSections::append_mesh(const std::vector<Vec3>& vertices, const std::vector<Vec3>& normals,
                                const std::vector<Vec2>& uvs,
                                const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                MaterialOf material_of_triangle) {
    const std::size_t first = scene_.vertices.size();
    scene_.vertices.insert(scene_.vertices.end(), vertices.begin(), vertices.end());
    append_per_vertex(scene_.normals, first, scene_.vertices.size(), normals);
    append_per_vertex(scene_.uvs, first, scene_.vertices.size(), uvs);
    scene_.triangles.reserve(scene_.triangles.size() + triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        Triangle t;
        for (std::size_t k = 0; k < 3; ++k) t.v[k] = triangles[i][k] + std::uint32_t(first);
        t.material = material_of_triangle(i);
        scene_.triangles.push_back(t);
    }
}

void SceneSections::pad_shading_data() {
    if (!scene_.normals.empty()) scene_.normals.resize(scene_.vertices.size(), Vec3(0));
    if (!scene_.uvs.empty()) scene_.uvs.resize(scene_.vertices.size(), Vec2(0));
}

// A "mesh" surface: exactly one of "file" (an OBJ file) and "procedural" (a generated mesh,
// framework/geometry/procedural_mesh.h), each placed by "scale", then "translate".
void SceneSections::read_mesh(const json& s, const std::string& pointer) {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    const json* file_value = member(s, "file");
    const json* shape_value = member(s, "procedural");
    const json* height_value = member(s, "heightfield");
    if (int(file_value != nullptr) + int(shape_value != nullptr) + int(height_value != nullptr) > 1)
        fail_key(at(height_value ? "heightfield" : "procedural"),
                 "a mesh has one of \"file\", \"procedural\" and \"heightfield\"",
                 "keep the one you mean");
    if (!file_value && !shape_value && !height_value)
        fail_value(pointer, "a mesh needs \"file\", \"procedural\" or \"heightfield\"",
                   "add \"file\": \"model.obj\", e.g. \"procedural\": \"torus\", "
                   "\"triangles\": 1000, or \"heightfield\": {\"image\": \"heights.png\"}");
    if (file_value || height_value)
        for (const char* key : {"triangles", "seed"})
            if (member(s, key))
                fail_key(at(key), std::string("\"") + key + "\" is only for procedural meshes",
                         "remove it (an OBJ file or a height map has its own triangles)");
    Vec3 translate{0}, scale{1};
    if (const json* v = member(s, "translate")) translate = vec3(*v, at("translate"));
    if (const json* v = member(s, "scale")) {
        scale = v->is_number() ? Vec3(real(*v, at("scale"))) : vec3(*v, at("scale"));
        if (scale.x == 0 || scale.y == 0 || scale.z == 0)
            fail_value(at("scale"), "\"scale\" must not be 0", "use 1 to keep the mesh's size");
    }
    int material = material_of(s, pointer);
    if (shape_value)
        read_procedural_mesh(s, pointer, scale, translate, material);
    else if (height_value)
        read_heightfield_mesh(*height_value, at("heightfield"), scale, translate, material);
    else
        read_obj_mesh(*file_value, at("file"), scale, translate, material);
}

// {"image": "heights.png", "height": 0.3}: one vertex per pixel over [-1, 1]^2 in x and z, y =
// the pixel's grey value (as stored, the mean of the channels of a colour image) * height.
void SceneSections::read_heightfield_mesh(const json& h, const std::string& pointer, Vec3 scale,
                                          Vec3 translate, int material) {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    require_object(h, pointer, R"({"image": "heights.png", "height": 0.3})");
    check_keys(h, pointer, schema::kHeightField);
    const std::string file =
        string(required(h, pointer, "image", "a height field", "\"heights.png\""), at("image"),
               "\"heights.png\"");
    const fs::path path = fs::path(file).is_absolute() ? fs::path(file) : base_dir_ / file;
    double height = 1;
    if (const json* v = member(h, "height"))
        height = real_in(
            *v, at("height"), [](double d) { return d >= 0; }, ">= 0",
            "the height of white above black, in the mesh's units before \"scale\"");
    Image image;
    try {
        image = ::rt::read_image(path, Encoding::Data);  // heights are data, not colour
    } catch (const ImageError& e) {
        fail_value(at("image"), file + ": " + e.problem());
    }
    if (image.width < 2 || image.height < 2)
        fail_value(at("image"),
                   file + " is " + std::to_string(image.width) + " x " +
                       std::to_string(image.height) + " pixels; a height map needs at least 2 x 2",
                   "use a larger image");
    const double triangles = 2.0 * (image.width - 1) * (image.height - 1);
    if (triangles > double(kMaxTriangles - scene_.triangles.size()))
        fail_value(at("image"), "the height map would make more than 20000000 triangles",
                   "use a smaller image");
    std::vector<float> grey;
    grey.reserve(image.pixels.size());
    for (const Color& c : image.pixels) grey.push_back((c.r + c.g + c.b) / 3);
    TriangleMesh mesh = make_heightfield(image.width, image.height, grey, height);
    check_vertex_room(mesh.vertices.size(), at("image"));
    place_mesh(mesh.vertices, mesh.normals, mesh.triangles, scale, translate, [&](std::size_t) {
        fail_value(at("image"), "the mesh is too large to represent once scaled and translated",
                   "use a smaller \"scale\" or \"translate\"");
    });
    append_mesh(mesh.vertices, mesh.normals, mesh.uvs, mesh.triangles,
                [&](std::size_t) { return material; });
}

void SceneSections::read_procedural_mesh(const json& s, const std::string& pointer, Vec3 scale,
                                         Vec3 translate, int material) {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    const std::vector<std::string>& shapes = procedural_shapes();
    const std::string& shape = shapes[choice(*member(s, "procedural"), at("procedural"), shapes)];
    double count = whole_number(required(s, pointer, "triangles", "a procedural mesh", "1000"),
                                at("triangles"));
    if (count < 1 || count > double(kMaxTriangles))
        fail_value(
            at("triangles"),
            "\"triangles\" must be between 1 and 20000000, got " + source_text(at("triangles")),
            "ask for fewer triangles");
    std::uint64_t seed = 1;
    if (const json* v = member(s, "seed")) {
        double d = whole_number(*v, at("seed"));
        if (d < 0 || d > 9007199254740992.0)  // 2^53: every whole number up to it is exact
            fail_value(
                at("seed"),
                "\"seed\" must be between 0 and 9007199254740992, got " + source_text(at("seed")),
                "any whole number in that range will do");
        seed = std::uint64_t(d);
    }
    const std::size_t room = kMaxTriangles - scene_.triangles.size();
    TriangleMesh mesh;
    try {
        ProceduralResolution resolution = procedural_resolution(shape, std::size_t(count));
        if (resolution.triangles > room)
            fail_value(at("triangles"),
                       "the scene would have more than 20000000 triangles (this " + shape +
                           " has " + std::to_string(resolution.triangles) + ")",
                       "ask for fewer triangles");
        mesh = make_procedural_mesh(shape, std::size_t(count), seed);
    } catch (const std::invalid_argument& e) {
        fail_value(at("triangles"), e.what(), "ask for fewer triangles");
    }
    check_vertex_room(mesh.vertices.size(), at("procedural"));
    place_mesh(mesh.vertices, mesh.normals, mesh.triangles, scale, translate, [&](std::size_t) {
        fail_value(member(s, "scale") ? at("scale") : at("translate"),
                   "the mesh is too large to represent once scaled and translated",
                   "use a smaller \"scale\" or \"translate\"");
    });
    append_mesh(mesh.vertices, mesh.normals, mesh.uvs, mesh.triangles,
                [&](std::size_t) { return material; });
}

void SceneSections::read_obj_mesh(const json& file_value, const std::string& file_pointer,
                                  Vec3 scale, Vec3 translate, int material) {
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
        fail_value(file_pointer, e.what());
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
            const std::string made = file + ":" + m.name;
            Material material_made = m.material;
            TextureSlot Material::*slots[4] = {&Material::diffuse_map, &Material::specular_map,
                                               &Material::emissive_map, &Material::normal_map};
            for (int k = 0; k < 4; ++k)
                if (!m.maps[k].file.empty())
                    material_made.*slots[k] = mtl_texture_slot(
                        m.maps[k], k == 3, file + ":" + m.maps[k].file.filename().string(),
                        file_pointer);
            id = scene_.add_material(material_made, made);
            material_ids_.emplace(made, id);
        }
        by_obj_material.push_back(id);
    }
    append_mesh(mesh.vertices, mesh.normals, mesh.uvs, mesh.triangles, [&](std::size_t i) {
        int obj_material = mesh.triangle_material[i];
        return obj_material < 0 ? material : by_obj_material[std::size_t(obj_material)];
    });
}

}  // namespace rt::scene_internal
