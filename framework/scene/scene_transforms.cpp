// The scene's "transform"s, named "objects" and their "instance"s
// (docs/scene-format.md#transforms-and-instances). A transform is baked into the surface when the
// shape keeps its kind (triangles, meshes, planes, a sphere under a similarity, a box under
// scales and quarter turns); a rotated box or a non-uniformly scaled sphere becomes an instance
// of an object of its own.
#include <cmath>
#include <utility>

#include "scene/message_text.h"
#include "scene/prepared_scene.h"
#include "scene/scene_sections.h"
#include "scene/transform.h"

namespace rt::schema {
const SchemaElement kObject{
    "an object", "", {"Transforms and instances"}, {{"name", kRequired}, {"surfaces", kRequired}}};
// A step has exactly one of these keys (read_transform_step says so when it has more).
const SchemaElement kTransformStep{
    "a transform step",
    "",
    {"Transforms and instances"},
    {{"translate"}, {"scale"}, {"rotate"}, {"euler_degrees"}, {"matrix"}}};
const SchemaElement kRotation{
    "a rotation", "", {"Transforms and instances"}, {{"axis", kRequired}, {"degrees", kRequired}}};
}  // namespace rt::schema

namespace rt::scene_internal {

namespace {

constexpr const char* kTransformExample =
    R"([{"scale": [1, 2, 1]}, {"rotate": {"axis": [0, 1, 0], "degrees": 30}}, {"translate": [0, 1, 0]}])";

// The arrays a surface reader appends to, swapped in and out while an object is read.
void swap_geometry(Scene& a, Scene& b) {
    std::swap(a.spheres, b.spheres);
    std::swap(a.planes, b.planes);
    std::swap(a.boxes, b.boxes);
    std::swap(a.vertices, b.vertices);
    std::swap(a.normals, b.normals);
    std::swap(a.uvs, b.uvs);
    std::swap(a.triangles, b.triangles);
    std::swap(a.moving_spheres, b.moving_spheres);
    std::swap(a.instances, b.instances);
}

bool singular(const glm::dmat4& m) {
    const glm::dmat3 l(m);
    double largest = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) largest = std::max(largest, std::abs(l[i][j]));
    return !(std::abs(glm::determinant(l)) > 1e-12 * largest * largest * largest);
}

}  // namespace

glm::dvec3 SceneSections::dvec3(const json& value, const std::string& pointer) const {
    require_array_of(value, pointer, 3, "numbers", "numbers", "write it as [x, y, z]");
    glm::dvec3 v;
    for (std::size_t i = 0; i < 3; ++i)
        v[int(i)] = number(value[i], JsonPositions::child(pointer, i));
    return v;
}

// {"matrix": [[a, b, c, d], [e, f, g, h], [i, j, k, l], [0, 0, 0, 1]]}: rows as written.
glm::dmat4 SceneSections::read_matrix(const json& rows, const std::string& pointer) const {
    const std::string fix = "write 4 rows of 4 numbers, the last [0, 0, 0, 1]";
    require_array_of(rows, pointer, 4, "rows", "rows", fix);
    glm::dmat4 m(1);
    for (std::size_t r = 0; r < 4; ++r) {
        const std::string row = JsonPositions::child(pointer, r);
        require_array_of(rows[r], row, 4, "numbers", "numbers", fix);
        for (std::size_t c = 0; c < 4; ++c)
            m[int(c)][int(r)] = number(rows[r][c], JsonPositions::child(row, c));
    }
    if (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1)
        fail_value(JsonPositions::child(pointer, std::size_t(3)),
                   "the matrix is not affine: its last row must be [0, 0, 0, 1]",
                   "projective matrices are not supported; put the translation in the last "
                   "column");
    return m;
}

glm::dmat4 SceneSections::read_transform_step(const json& step, const std::string& pointer) const {
    require_object(step, pointer, R"({"rotate": {"axis": [0, 1, 0], "degrees": 30}})");
    const std::vector<std::string> keys = schema::kTransformStep.key_names();
    check_keys(step, pointer, schema::kTransformStep);
    if (step.size() != 1)
        fail_value(pointer,
                   "a transform step has exactly one of " + list_of(keys) + ", got " +
                       std::to_string(step.size()),
                   std::string("make a list of steps, applied in order: ") + kTransformExample);
    const std::string key = step.begin().key();
    const std::string at = JsonPositions::child(pointer, key);
    const json& v = step.begin().value();
    if (key == "translate") {
        glm::dmat4 m(1);
        m[3] = glm::dvec4(dvec3(v, at), 1);
        return m;
    }
    if (key == "scale") {
        const glm::dvec3 s = v.is_number() ? glm::dvec3(number(v, at)) : dvec3(v, at);
        if (s.x == 0 || s.y == 0 || s.z == 0)
            fail_value(at, "a \"scale\" of 0 is singular (it flattens the surface)",
                       "use 1 to keep a size; a negative factor mirrors");
        return glm::dmat4(glm::dvec4(s.x, 0, 0, 0), glm::dvec4(0, s.y, 0, 0),
                          glm::dvec4(0, 0, s.z, 0), glm::dvec4(0, 0, 0, 1));
    }
    if (key == "rotate") {
        require_object(v, at, R"({"axis": [0, 1, 0], "degrees": 30})");
        check_keys(v, at, schema::kRotation);
        auto inner = [&](const char* k) { return JsonPositions::child(at, k); };
        const glm::dvec3 axis =
            dvec3(required(v, at, "axis", "a rotation", "[0, 1, 0]"), inner("axis"));
        if (!(glm::length(axis) > 0) || !std::isfinite(glm::length(axis)))
            fail_value(inner("axis"), "the rotation \"axis\" must not be zero",
                       "give the direction to turn about, e.g. [0, 1, 0]");
        const double degrees =
            number(required(v, at, "degrees", "a rotation", "30"), inner("degrees"));
        return axis_rotation(axis, degrees);
    }
    if (key == "euler_degrees") return euler_rotation(dvec3(v, at));
    return read_matrix(v, at);
}

// "transform": one step, or a list of steps applied in order (the first to the surface first).
glm::dmat4 SceneSections::read_transform(const json& value, const std::string& pointer) const {
    glm::dmat4 m(1);
    if (value.is_object()) {
        m = read_transform_step(value, pointer);
    } else {
        require_array(value, pointer, kTransformExample);
        for (std::size_t i = 0; i < value.size(); ++i)
            m = read_transform_step(value[i], JsonPositions::child(pointer, i)) * m;
    }
    for (int c = 0; c < 4; ++c)
        if (!all_finite(m[c]))
            fail_value(pointer, "the transform overflows (its matrix is not finite)",
                       "use smaller scales and translations");
    if (singular(m))
        fail_value(pointer, "the transform is singular (determinant 0): it flattens the surface",
                   "give every axis a non-zero size; check the matrix's first three columns");
    return m;
}

SceneSections::GeometryMark SceneSections::mark_geometry() const {
    return {scene_.spheres.size(), scene_.planes.size(), scene_.boxes.size(),
            scene_.vertices.size(), scene_.triangles.size()};
}

// A shape the transform does not keep (moved out of the scene's arrays into `shape`) becomes an
// instance of an object of its own.
void SceneSections::add_shape_instance(Scene shape, const glm::dmat4& m,
                                       const std::string& pointer) {
    if (reading_object_)
        fail_value(JsonPositions::child(pointer, "transform"),
                   "inside an object, a sphere takes only moves, turns and uniform scales, and a "
                   "box only moves, scales and quarter turns (instances are one level deep)",
                   "put this transform on the object's instances instead");
    shape.source = scene_.source;
    scene_.objects.push_back(std::make_shared<const Scene>(std::move(shape)));
    scene_.object_names.emplace_back();
    scene_.instances.push_back(make_instance(m, scene_.objects.size() - 1, -1));
}

// Applies `m` to what the surface at `pointer` appended since `mark`.
void SceneSections::place_surface(const glm::dmat4& m, const GeometryMark& mark,
                                  const std::string& pointer) {
    const std::string at = JsonPositions::child(pointer, "transform");
    auto check = [&](const Vec3& p) {
        if (!all_finite(p))
            fail_value(at, "the surface is too large to represent once transformed",
                       "use smaller scales and translations");
    };
    if (scene_.spheres.size() > mark.spheres) {  // a sphere surface adds one sphere
        if (!scene_.moving_spheres.empty() && scene_.moving_spheres.back().sphere == mark.spheres)
            fail_value(at, "a moving sphere takes no \"transform\"",
                       "place it with \"center\" and \"radius\"");
        Sphere& s = scene_.spheres.back();
        if (const double scale = similarity_scale(m); scale > 0) {
            s.center = transform_point(m, s.center);
            s.radius = Real(double(s.radius) * scale);
            check(s.center), check(Vec3(s.radius));
        } else {
            Scene shape;
            shape.spheres.push_back(s);
            scene_.spheres.pop_back();
            add_shape_instance(std::move(shape), m, pointer);
        }
    }
    for (std::size_t i = mark.planes; i < scene_.planes.size(); ++i) {
        Plane& p = scene_.planes[i];
        p.point = transform_point(m, p.point);
        p.normal = transform_normal(normal_matrix(m), p.normal);
        check(p.point);
    }
    if (scene_.boxes.size() > mark.boxes) {  // a box surface adds one box
        Box& b = scene_.boxes.back();
        if (keeps_axes(m)) {
            const Vec3 p = transform_point(m, b.min), q = transform_point(m, b.max);
            b.min = glm::min(p, q);
            b.max = glm::max(p, q);
            check(b.min), check(b.max);
        } else {
            Scene shape;
            shape.boxes.push_back(b);
            scene_.boxes.pop_back();
            add_shape_instance(std::move(shape), m, pointer);
        }
    }
    for (std::size_t i = mark.vertices; i < scene_.vertices.size(); ++i)
        check(scene_.vertices[i] = transform_point(m, scene_.vertices[i]));
    const glm::dmat3 n = normal_matrix(m);
    for (std::size_t i = mark.vertices; i < scene_.normals.size(); ++i)
        scene_.normals[i] = transform_normal(n, scene_.normals[i]);
    if (glm::determinant(glm::dmat3(m)) < 0)  // mirrored: keep the outward side outward
        for (std::size_t i = mark.triangles; i < scene_.triangles.size(); ++i)
            std::swap(scene_.triangles[i].v[1], scene_.triangles[i].v[2]);
}

// {"type": "instance", "object": "pawn", "transform": ..., "material": ...}
void SceneSections::read_instance(const json& s, const std::string& pointer) {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    const std::string name =
        string(required(s, pointer, "object", "an instance", "\"name\""), at("object"), "\"pawn\"");
    if (reading_object_)
        fail_value(
            at("object"),
            "object " + quote(*reading_object_) + " holds an instance of " +
                (name == *reading_object_ ? std::string("itself") : "object " + quote(name)) +
                "; instances are one level deep (objects hold surfaces only)",
            "place the instance among the scene's \"surfaces\"");
    std::size_t object = scene_.object_names.size();
    for (std::size_t i = 0; i < scene_.object_names.size(); ++i)
        if (!scene_.object_names[i].empty() && scene_.object_names[i] == name) object = i;
    if (object == scene_.object_names.size()) {
        std::vector<std::string> known;
        for (const std::string& n : scene_.object_names)
            if (!n.empty()) known.push_back(n);
        fail_value(at("object"), "unknown object " + quote(name),
                   known.empty() ? std::string("define it in the top-level \"objects\" list")
                                 : suggestion(name, known));
    }
    glm::dmat4 m(1);
    if (const json* t = member(s, "transform")) m = read_transform(*t, at("transform"));
    const int material = member(s, "material") ? material_of(s, pointer) : -1;
    scene_.instances.push_back(make_instance(m, object, material));
}

// "objects": [{"name": "pawn", "surfaces": [...]}]: surfaces read into scenes of their own.
void SceneSections::read_objects(const json& root) {
    const json* list = member(root, "objects");
    if (!list) return;
    const std::string example = R"([{"name": "pawn", "surfaces": [{"type": "sphere", ...}]}])";
    require_array(*list, "/objects", example);
    for (std::size_t k = 0; k < list->size(); ++k) {
        const std::string pointer = JsonPositions::child("/objects", k);
        auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
        const json& o = (*list)[k];
        require_object(o, pointer, R"({"name": "pawn", "surfaces": [...]})");
        check_keys(o, pointer, schema::kObject);
        const std::string name =
            string(required(o, pointer, "name", "an object", "\"pawn\""), at("name"), "\"pawn\"");
        if (name.empty()) fail_value(at("name"), "an object's \"name\" is empty", "name it");
        for (const std::string& known : scene_.object_names)
            if (known == name)
                fail_value(at("name"), "two objects are named " + quote(name),
                           "give each object a name of its own");
        const json& surfaces = required(o, pointer, "surfaces", "an object", "[...]");
        require_array(surfaces, at("surfaces"), R"([{"type": "sphere", ...}])");
        if (surfaces.empty())
            fail_value(at("surfaces"), "object " + quote(name) + " has no surfaces",
                       "give it at least one, or remove it");
        Scene object;
        swap_geometry(scene_, object);  // read into empty arrays
        reading_object_ = name;
        for (std::size_t i = 0; i < surfaces.size(); ++i) {
            const std::string s = JsonPositions::child(at("surfaces"), i);
            read_surface(surfaces[i], s);
            if (!scene_.planes.empty())
                fail_value(s, "an object cannot hold a plane (a plane has no bounds to place)",
                           "put planes among the scene's \"surfaces\"");
            if (!scene_.moving_spheres.empty())
                fail_value(JsonPositions::child(s, "velocity"),
                           "an object cannot hold a moving sphere (its box would change with "
                           "time)",
                           "put moving spheres among the scene's \"surfaces\"");
        }
        pad_shading_data();
        reading_object_.reset();
        swap_geometry(scene_, object);
        object.source = scene_.source;
        scene_.objects.push_back(std::make_shared<const Scene>(std::move(object)));
        scene_.object_names.push_back(name);
    }
}

}  // namespace rt::scene_internal
