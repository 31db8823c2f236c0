// The scene's "surfaces": spheres, planes, triangles, boxes, checkerboards, and the dispatch on
// "type" (meshes are in scene_meshes.cpp).
#include "scene/scene_sections.h"

#include <algorithm>

#include "scene/message_text.h"

namespace rt::schema {
// Each surface type's keys. rt fmt writes a surface's keys in its type's order, and the types
// agree on the order of the keys they share ("type" first, "transform" and "material" last).
const SchemaElement kSphere{"a sphere",
                            "sphere",
                            {"Surfaces", "Sampling"},
                            {{"type", kRequired},
                             {"center", kRequired},
                             {"radius", kRequired},
                             {"velocity"},
                             {"transform"},
                             {"material"}}};
const SchemaElement kPlane{"a plane",
                           "plane",
                           {"Surfaces"},
                           {{"type", kRequired},
                            {"point", kRequired},
                            {"normal", kRequired},
                            {"transform"},
                            {"material"}}};
const SchemaElement kTriangle{
    "a triangle",
    "triangle",
    {"Surfaces"},
    {{"type", kRequired}, {"vertices", kRequired}, {"transform"}, {"material"}}};
const SchemaElement kBox{
    "a box",
    "box",
    {"Surfaces"},
    {{"type", kRequired}, {"min", kRequired}, {"max", kRequired}, {"transform"}, {"material"}}};
const SchemaElement kMesh{"a mesh",
                          "mesh",
                          {"Surfaces"},
                          {{"type", kRequired},
                           {"file"},
                           {"procedural"},
                           {"heightfield"},
                           {"triangles"},
                           {"seed"},
                           {"scale"},
                           {"translate"},
                           {"transform"},
                           {"material"}}};
const SchemaElement kCheckerboard{"a checkerboard",
                                  "checkerboard",
                                  {"Surfaces"},
                                  {{"type", kRequired},
                                   {"min", kRequired},
                                   {"max", kRequired},
                                   {"tiles", kRequired},
                                   {"transform"},
                                   {"materials", kRequired}}};
const SchemaElement kInstance{
    "an instance",
    "instance",
    {"Surfaces", "Transforms and instances"},
    {{"type", kRequired}, {"object", kRequired}, {"transform"}, {"material"}}};
}  // namespace rt::schema

namespace rt::scene_internal {

namespace {

constexpr double kMaxCheckerTiles = 1024;  // per side of a "checkerboard"

}  // namespace

void SceneSections::read_surfaces(const json& root) {
    const json* list = member(root, "surfaces");
    if (!list) return;
    require_array(*list, "/surfaces",
                  "[{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}]");
    for (std::size_t i = 0; i < list->size(); ++i)
        read_surface((*list)[i], JsonPositions::child("/surfaces", i));
    pad_shading_data();
}

void SceneSections::read_surface(const json& s, const std::string& pointer) {
    // Each "type", its keys (scene_schema.h) and its reader, in the order messages list them.
    struct Kind {
        const SchemaElement& element;
        void (SceneSections::*read)(const json& s, const std::string& pointer);
    };
    static const Kind kinds[] = {
        {schema::kSphere, &SceneSections::read_sphere},
        {schema::kPlane, &SceneSections::read_plane},
        {schema::kTriangle, &SceneSections::read_triangle},
        {schema::kBox, &SceneSections::read_box},
        {schema::kMesh, &SceneSections::read_mesh},
        {schema::kCheckerboard, &SceneSections::read_checkerboard},
        {schema::kInstance, &SceneSections::read_instance},
    };
    static const std::vector<std::string> types = [] {
        std::vector<std::string> names;
        for (const Kind& kind : kinds) names.push_back(kind.element.type);
        return names;
    }();
    require_object(s, pointer, "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}");
    const json& type_value = required(s, pointer, "type", "a surface", list_of(types));
    const Kind& kind = kinds[choice(type_value, JsonPositions::child(pointer, "type"), types)];
    check_keys(s, pointer, kind.element);
    const GeometryMark mark = mark_geometry();
    (this->*kind.read)(s, pointer);
    const json* transform = member(s, "transform");
    if (transform && kind.read != &SceneSections::read_instance)  // an instance keeps its own
        place_surface(read_transform(*transform, JsonPositions::child(pointer, "transform")), mark,
                      pointer);
}

void SceneSections::read_sphere(const json& s, const std::string& pointer) {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    Sphere sphere;
    sphere.center = vec3(required(s, pointer, "center", "a sphere", "[x, y, z]"), at("center"));
    sphere.radius = real_in(
        required(s, pointer, "radius", "a sphere", "1"), at("radius"),
        [](double d) { return d > 0; }, "> 0", "give the sphere a positive radius");
    sphere.material = material_of(s, pointer);
    if (const json* v = member(s, "velocity")) {  // stage 10: motion blur
        if (scene_.accelerator == Accelerator::Bvh)
            fail_value(at("velocity"),
                       "a moving sphere cannot be in a BVH (its box would change with time)",
                       "use \"accelerator\": \"none\" or drop \"velocity\"");
        scene_.moving_spheres.push_back(
            MovingSphere{scene_.spheres.size(), vec3(*v, at("velocity"))});
    }
    scene_.spheres.push_back(sphere);
}

void SceneSections::read_plane(const json& s, const std::string& pointer) {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    Plane plane;
    plane.point = vec3(required(s, pointer, "point", "a plane", "[x, y, z]"), at("point"));
    plane.normal = unit_direction(required(s, pointer, "normal", "a plane", "[0, 1, 0]"),
                                  at("normal"), "give the plane a normal such as [0, 1, 0]");
    plane.material = material_of(s, pointer);
    scene_.planes.push_back(plane);
}

void SceneSections::read_triangle(const json& s, const std::string& pointer) {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    const json& corners =
        required(s, pointer, "vertices", "a triangle", "[[x, y, z], [x, y, z], [x, y, z]]");
    require_array_of(corners, at("vertices"), 3, "points", "points",
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
}

void SceneSections::read_box(const json& s, const std::string& pointer) {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    Box box;
    box.min = vec3(required(s, pointer, "min", "a box", "[x, y, z]"), at("min"));
    box.max = vec3(required(s, pointer, "max", "a box", "[x, y, z]"), at("max"));
    check_corners(box.min, box.max, at("min"), at("max"));
    box.material = material_of(s, pointer);
    scene_.boxes.push_back(box);
}

void SceneSections::check_corners(const Vec3& min, const Vec3& max, const std::string& at_min,
                                  const std::string& at_max) const {
    for (int k = 0; k < 3; ++k)
        if (min[k] > max[k])
            fail_value(JsonPositions::child(at_max, std::size_t(k)),
                       std::string("\"max\" must not be below \"min\", but ") + "xyz"[k] + " is " +
                           source_text(JsonPositions::child(at_max, std::size_t(k))) + " < " +
                           source_text(JsonPositions::child(at_min, std::size_t(k))),
                       "swap the values or fix the corner");
}

// A "checkerboard": shorthand for a floor of tiles[0] x tiles[1] boxes between "min" and
// "max" (docs/scene-format.md). Tile (i, j) spans x edges i..i+1 and z edges j..j+1, where
// edge k = min + (max - min) * k / n in double (edge n is max itself), and all of min.y..max.y;
// it gets materials[(i + j) % 2]. Boxes are appended with i outer, j inner.
void SceneSections::read_checkerboard(const json& s, const std::string& pointer) {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    if (member(s, "transform"))
        fail_key(at("transform"),
                 "a checkerboard takes no \"transform\" (its tiles are boxes "
                 "along the axes)",
                 "give \"min\" and \"max\" where the board lies, or transform boxes one by one");
    const json& lo_value = required(s, pointer, "min", "a checkerboard", "[x, y, z]");
    const json& hi_value = required(s, pointer, "max", "a checkerboard", "[x, y, z]");
    const Vec3 lo = vec3(lo_value, at("min")), hi = vec3(hi_value, at("max"));
    for (int k = 0; k < 3; ++k) {
        const bool flat = k != 1;  // the board needs an area in x and z; y may be thin
        const double a = lo_value[std::size_t(k)].get<double>(),
                     b = hi_value[std::size_t(k)].get<double>();
        if (flat ? !(a < b) : !(a <= b)) {
            const std::string element = JsonPositions::child(at("max"), std::size_t(k));
            fail_value(
                element,
                std::string("\"max\" must ") + (flat ? "be above" : "not be below") +
                    " \"min\", but " + "xyz"[k] + " is " + source_text(element) +
                    (flat ? " <= " : " < ") +
                    source_text(JsonPositions::child(at("min"), std::size_t(k))),
                flat ? "give the board an area in x and z" : "swap the values or fix the corner");
        }
    }
    const json& tiles = required(s, pointer, "tiles", "a checkerboard", "[8, 8]");
    require_array_of(tiles, at("tiles"), 2, "whole numbers (along x, along z)", "numbers",
                     "write it as [8, 8]");
    std::size_t count[2];
    for (std::size_t k = 0; k < 2; ++k) {
        const std::string element = JsonPositions::child(at("tiles"), k);
        const double d = whole_number(tiles[k], element);
        if (d < 1 || d > kMaxCheckerTiles)
            fail_value(element,
                       label(element) + " must be between 1 and " +
                           std::to_string(int(kMaxCheckerTiles)) + ", got " + source_text(element),
                       "use fewer, larger tiles");
        count[k] = std::size_t(d);
    }
    const json& materials =
        required(s, pointer, "materials", "a checkerboard", "[\"dark\", \"light\"]");
    require_array_of(materials, at("materials"), 2, "materials", "entries",
                     "write it as [\"dark\", \"light\"] (names or indices)");
    const int material[2] = {
        material_ref(materials[0], JsonPositions::child(at("materials"), std::size_t(0))),
        material_ref(materials[1], JsonPositions::child(at("materials"), std::size_t(1)))};
    // The edges in double, from the numbers as written (not from their Real roundings).
    auto edges = [](double a, double b, std::size_t n) {
        std::vector<Real> e(n + 1);
        for (std::size_t k = 0; k < n; ++k)
            e[k] = Real(std::min(a + (b - a) * double(k) / double(n), b));
        e[n] = Real(b);
        return e;
    };
    const std::vector<Real> ex =
        edges(lo_value[0].get<double>(), hi_value[0].get<double>(), count[0]);
    const std::vector<Real> ez =
        edges(lo_value[2].get<double>(), hi_value[2].get<double>(), count[1]);
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

void SceneSections::check_vertex_room(std::size_t more, const std::string& pointer) const {
    if (scene_.vertices.size() + more > std::size_t(UINT32_MAX))
        fail_value(pointer, "too many vertices in the scene", "use smaller meshes");
}

void SceneSections::check_triangle_room(std::size_t more, const std::string& pointer) const {
    if (scene_.triangles.size() + more > kMaxTriangles)
        fail_value(pointer, "the scene has more than 20000000 triangles", "use smaller meshes");
}

}  // namespace rt::scene_internal
