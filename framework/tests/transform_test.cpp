// Transforms, objects and instances in scene files (docs/scene-format.md#transforms-and-instances):
// what the loader bakes and what it makes an instance, the one-line errors, and the canonical
// form. No student code: the hits are checked in stages/06-bvh/tests/instance_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/source_dir.h"
#include "scene/prepared_scene.h"
#include "scene/scene_format.h"
#include "scene/transform.h"
#include "testing/scene_text.h"
#include "testing/temp_dir.h"

namespace rt {
namespace {

using testing::error_of;
using testing::parse;

// A scene of `surfaces` (the text inside "surfaces": [...]) after `before` (top-level keys).
std::string scene_text(const std::string& surfaces, const std::string& before = "") {
    return "{" + before + "\"surfaces\": [" + surfaces + "]}";
}

void expect_near(const Vec3& a, const Vec3& b, double tolerance = 1e-5) {
    EXPECT_NEAR(a.x, b.x, tolerance) << "x";
    EXPECT_NEAR(a.y, b.y, tolerance) << "y";
    EXPECT_NEAR(a.z, b.z, tolerance) << "z";
}

TEST(Transform, SphereUnderASimilarityIsBaked) {
    // (1, 0, 0) scaled by 2 is (2, 0, 0); a quarter turn about +y takes +x to -z: (0, 0, -2);
    // then up 1. The radius doubles.
    const Scene s = parse(scene_text(
        R"({"type": "sphere", "center": [1, 0, 0], "radius": 1, "transform": [{"scale": 2},
            {"rotate": {"axis": [0, 1, 0], "degrees": 90}}, {"translate": [0, 1, 0]}]})"));
    ASSERT_EQ(s.spheres.size(), 1u);
    EXPECT_TRUE(s.instances.empty());
    expect_near(s.spheres[0].center, {0, 1, -2});
    EXPECT_NEAR(s.spheres[0].radius, 2, 1e-6);
}

TEST(Transform, NonUniformSphereAndRotatedBoxBecomeInstances) {
    const Scene s = parse(scene_text(
        R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "transform": {"scale": [2, 1, 1]}},
           {"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "material": 0,
            "transform": {"rotate": {"axis": [0, 1, 0], "degrees": 45}}})"));
    EXPECT_TRUE(s.spheres.empty());
    EXPECT_TRUE(s.boxes.empty());
    ASSERT_EQ(s.instances.size(), 2u);
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[0]->spheres.size(), 1u);
    EXPECT_EQ(s.objects[1]->boxes.size(), 1u);
    EXPECT_EQ(s.instances[1].object, 1u);
    EXPECT_EQ(s.instances[0].material, -1) << "the shape keeps its own material";
    // The world-to-object map undoes the scale.
    expect_near(Vec3(s.instances[0].world_to_object * glm::vec<4, Real>(2, 0, 0, 1)), {1, 0, 0});
    EXPECT_EQ(s.primitive_count(), 2u);
    EXPECT_TRUE(s.is_primitive(Scene::primitive_id(Scene::Kind::Instance, 1)));
    EXPECT_FALSE(s.is_primitive(Scene::primitive_id(Scene::Kind::Instance, 2)));
}

TEST(Transform, BoxUnderQuarterTurnsIsBaked) {
    // About +y by 90 degrees: x' = z, z' = -x. [0, 1] x [0, 2] x [0, 3] becomes
    // [0, 3] x [0, 2] x [-1, 0].
    const Scene s = parse(scene_text(
        R"({"type": "box", "min": [0, 0, 0], "max": [1, 2, 3],
            "transform": {"rotate": {"axis": [0, 1, 0], "degrees": 90}}})"));
    ASSERT_EQ(s.boxes.size(), 1u);
    EXPECT_TRUE(s.instances.empty());
    expect_near(s.boxes[0].min, {0, 0, -1});
    expect_near(s.boxes[0].max, {3, 2, 0});
}

TEST(Transform, PlaneNormalGoesByTheInverseTranspose) {
    // The plane x + y = 0 stretched 2x along x is x / 2 + y = 0: normal (0.5, 1, 0) normalised,
    // not the stretched normal (2, 1, 0).
    const Scene s = parse(scene_text(
        R"({"type": "plane", "point": [0, 0, 0], "normal": [1, 1, 0],
            "transform": [{"scale": [2, 1, 1]}, {"translate": [0, 3, 0]}]})"));
    ASSERT_EQ(s.planes.size(), 1u);
    expect_near(s.planes[0].normal, Vec3(0.5, 1, 0) / std::sqrt(Real(1.25)));
    expect_near(s.planes[0].point, {0, 3, 0});
}

TEST(Transform, MirroredTriangleKeepsItsFront) {
    // Mirrored in x, (0,0,0) (1,0,0) (0,1,0) would face -z as written; the loader reverses the
    // winding so that its front still faces +z, as the original's did.
    const Scene s = parse(scene_text(
        R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
            "transform": {"scale": [-1, 1, 1]}})"));
    Vec3 a, b, c;
    s.triangle_vertices(0, a, b, c);
    expect_near(glm::normalize(glm::cross(b - a, c - a)), {0, 0, 1});
}

TEST(Transform, MirroredMeshKeepsOutwardNormals) {
    // An icosphere around the origin, mirrored and stretched: every face and vertex normal must
    // still point away from the centre.
    const Scene s = parse(scene_text(
        R"({"type": "mesh", "procedural": "icosphere", "triangles": 80,
            "transform": [{"scale": [-2, 1, 0.5]}, {"rotate": {"axis": [1, 1, 0], "degrees": 33}}]})"));
    ASSERT_EQ(s.triangles.size(), 80u);
    ASSERT_EQ(s.normals.size(), s.vertices.size());
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
        Vec3 a, b, c;
        s.triangle_vertices(i, a, b, c);
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), a + b + c), 0) << "triangle " << i;
    }
    for (std::size_t v = 0; v < s.vertices.size(); ++v) {
        EXPECT_GT(glm::dot(s.normals[v], s.vertices[v]), 0) << "vertex " << v;
        EXPECT_NEAR(glm::length(s.normals[v]), 1, 1e-5);
    }
}

// The vertices of one triangle placed by `transform`.
std::vector<Vec3> placed(const std::string& transform) {
    const Scene s = parse(scene_text(
        R"({"type": "triangle", "vertices": [[1, 2, 3], [-2, 0.5, 1], [0.25, -1, 2]],
            "transform": )" +
        transform + "}"));
    return s.vertices;
}

void expect_same_vertices(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) expect_near(a[i], b[i]);
}

TEST(Transform, EulerAnglesAreXThenYThenZ) {
    expect_same_vertices(placed(R"({"euler_degrees": [30, 40, 50]})"),
                         placed(R"([{"rotate": {"axis": [1, 0, 0], "degrees": 30}},
                   {"rotate": {"axis": [0, 1, 0], "degrees": 40}},
                   {"rotate": {"axis": [0, 0, 1], "degrees": 50}}])"));
}

TEST(Transform, MatrixRowsAsWritten) {
    // A quarter turn about +z (x -> y, y -> -x), then a move by (1, 2, 3).
    expect_same_vertices(
        placed(R"({"matrix": [[0, -1, 0, 1], [1, 0, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]})"),
        placed(R"([{"rotate": {"axis": [0, 0, 5], "degrees": 90}}, {"translate": [1, 2, 3]}])"));
    EXPECT_NEAR(
        placed(R"({"matrix": [[0, -1, 0, 1], [1, 0, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]})")[0].x, -1,
        1e-6)
        << "(1, 2, 3) turns to (-2, 1, 3) and moves to (-1, 3, 6)";
}

TEST(Transform, ScaleAndTranslateOfAMeshComeFirst) {
    // "scale" and "translate" place the mesh, then "transform" moves the result.
    const Scene a = parse(scene_text(
        R"({"type": "mesh", "procedural": "soup", "triangles": 3, "scale": 2, "translate": [1, 0, 0],
            "transform": {"rotate": {"axis": [0, 0, 1], "degrees": 90}}})"));
    const Scene b = parse(scene_text(
        R"({"type": "mesh", "procedural": "soup", "triangles": 3, "transform": [{"scale": 2},
            {"translate": [1, 0, 0]}, {"rotate": {"axis": [0, 0, 1], "degrees": 90}}]})"));
    expect_same_vertices(a.vertices, b.vertices);
}

TEST(Transform, ObjectsAndInstances) {
    const Scene s = parse(scene_text(R"({"type": "instance", "object": "pair"},
                      {"type": "instance", "object": "pair", "material": "blue",
                       "transform": {"translate": [3, 0, 0]}})",
                                     R"("materials": [{"name": "red"}, {"name": "blue"}],
                      "objects": [{"name": "pair", "surfaces": [
                        {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red"},
                        {"type": "mesh", "procedural": "icosphere", "triangles": 20}]}],)"));
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.object_names[0], "pair");
    EXPECT_EQ(s.objects[0]->spheres.size(), 1u);
    EXPECT_EQ(s.objects[0]->triangles.size(), 20u);
    EXPECT_EQ(s.objects[0]->normals.size(), s.objects[0]->vertices.size());
    EXPECT_TRUE(s.spheres.empty() && s.triangles.empty()) << "objects are not drawn by themselves";
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.instances[0].material, -1);
    EXPECT_EQ(s.instances[1].material, 1);
    EXPECT_EQ(s.instances[1].object_to_world[3].x, 3);
    // Features count what the instances show.
    EXPECT_TRUE(scene_features(s).triangles);
}

// ---- one-line errors ---------------------------------------------------------------------

struct BadTransform {
    const char* surfaces;  // after {"surfaces": [
    const char* objects;   // "" or the "objects" list (then the surfaces are on line 2)
    const char* at;        // the message points at the first place this text stands
    const char* message;   // a part of the message
};

const BadTransform kBadTransforms[] = {
    {R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "transform": {"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1]]}})",
     "", R"({"matrix")", "the transform is singular (determinant 0)"},
    {R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "transform": {"matrix": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]}})",
     "", "[0, 0, 1, 1]", "the matrix is not affine: its last row must be [0, 0, 0, 1]"},
    {R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "transform": [{"scale": [1, 0, 1]}]})",
     "", "[1, 0, 1]", "a \"scale\" of 0 is singular"},
    {R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "transform": {"rotate": {"axis": [0, 0, 0], "degrees": 5}}})",
     "", "[0, 0, 0], \"degrees\"", "the rotation \"axis\" must not be zero"},
    {R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "transform": {"translate": [0, 1e999, 0]}})",
     "", "1e999", "must be a finite number, got 1e999"},
    {R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "transform": [{"scale": 1e300}, {"scale": 1e300}]})",
     "", "[{\"scale\"", "the transform overflows"},
    {R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "transform": {"scale": 2, "translate": [1, 0, 0]}})",
     "", "{\"scale\"", "a transform step has exactly one of"},
    {R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "transform": {"rotation": {}}})", "",
     "\"rotation\"", "unknown key \"rotation\" in a transform step"},
    {R"({"type": "instance", "object": "pwn"})",
     R"([{"name": "pawn", "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]}])",
     "\"pwn\"", "unknown object \"pwn\"; did you mean \"pawn\"?"},
    {R"({"type": "instance", "object": "pawn"})", "", "\"pawn\"",
     "unknown object \"pawn\"; define it in the top-level \"objects\" list"},
    {R"({"type": "checkerboard", "min": [0, 0, 0], "max": [1, 1, 1], "tiles": [2, 2], "materials": [0, 0], "transform": {"scale": 2}})",
     "", "\"transform\"", "a checkerboard takes no \"transform\""},
    {R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "velocity": [1, 0, 0], "transform": {"scale": 2}})",
     "", "{\"scale\"", "a moving sphere takes no \"transform\""},
};

TEST(Transform, BadScenesGiveOneLineErrors) {
    for (const BadTransform& bad : kBadTransforms) {
        const std::string objects =
            *bad.objects ? std::string("\"objects\": ") + bad.objects + ",\n" : "";
        const std::string surfaces = std::string("\"surfaces\": [") + bad.surfaces + "]}";
        const std::string message = error_of("{" + objects + surfaces);
        SCOPED_TRACE(bad.surfaces);
        EXPECT_NE(message.find(bad.message), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
        // Line 1 starts with "{", line 2 (after the objects) with the surfaces.
        const std::size_t column = surfaces.find(bad.at) + (objects.empty() ? 2 : 1);
        const std::string where = "test.json:" + std::string(objects.empty() ? "1" : "2") + ":" +
                                  std::to_string(column) + ": error: ";
        EXPECT_EQ(message.rfind(where, 0), 0u) << message << "\nexpected at " << where;
    }
}

TEST(Transform, BadObjectsGiveOneLineErrors) {
    const std::string sphere = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})";
    struct Case {
        std::string objects;
        const char* message;
    };
    const Case cases[] = {
        {R"([{"name": "a", "surfaces": [{"type": "instance", "object": "a"}]}])",
         "object \"a\" holds an instance of itself; instances are one level deep"},
        {R"([{"name": "a", "surfaces": [)" + sphere +
             R"(]}, {"name": "b", "surfaces": [{"type": "instance", "object": "a"}]}])",
         "object \"b\" holds an instance of object \"a\""},
        {R"([{"name": "a", "surfaces": [)" + sphere + R"(]}, {"name": "a", "surfaces": [)" +
             sphere + "]}]",
         "two objects are named \"a\""},
        {R"([{"name": "a", "surfaces": []}])", "object \"a\" has no surfaces"},
        {R"([{"name": "a", "surfaces": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}]}])",
         "an object cannot hold a plane"},
        {R"([{"name": "a", "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "velocity": [1, 0, 0]}]}])",
         "an object cannot hold a moving sphere"},
        {R"([{"name": "a", "surfaces": [{"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "transform": {"rotate": {"axis": [0, 1, 0], "degrees": 10}}}]}])",
         "put this transform on the object's instances instead"},
        {R"([{"name": "a", "surfaces": [)" + sphere + R"(], "scale": 2}])",
         "unknown key \"scale\" in an object"},
    };
    for (const Case& c : cases) {
        const std::string message = error_of("{\"objects\": " + c.objects + "}");
        SCOPED_TRACE(c.objects);
        EXPECT_NE(message.find(c.message), std::string::npos) << message;
        EXPECT_EQ(message.rfind("test.json:1:", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
    }
}

// ---- canonical form ----------------------------------------------------------------------

TEST(Transform, CanonicalFormOrdersObjectsAndSteps) {
    const std::string messy =
        R"({"surfaces": [{"transform": [{"rotate": {"degrees": 30, "axis": [0, 1, 0]}},
        {"translate": [0, 1.0, 0]}], "material": 0, "object": "o", "type": "instance"}],
      "objects": [{"surfaces": [{"radius": 1, "type": "sphere", "center": [0, 0, 0],
        "transform": {"scale": [2, 2, 2]}}], "name": "o"}], "materials": [{"name": "m"}]})";
    const std::string expected =
        "{\n"
        "  \"materials\": [\n"
        "    {\"name\": \"m\"}\n"
        "  ],\n"
        "  \"objects\": [\n"
        "    {\"name\": \"o\", \"surfaces\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], "
        "\"radius\": 1, \"transform\": {\"scale\": [2, 2, 2]}}]}\n"
        "  ],\n"
        "  \"surfaces\": [\n"
        "    {\"type\": \"instance\", \"object\": \"o\", \"transform\": [{\"rotate\": {\"axis\": "
        "[0, 1, 0], \"degrees\": 30}}, {\"translate\": [0, 1, 0]}], \"material\": 0}\n"
        "  ]\n"
        "}\n";
    const std::string once = canonical_scene_text(messy, "test.json", {});
    EXPECT_EQ(once, expected);
    EXPECT_EQ(canonical_scene_text(once, "test.json", {}), once) << "a fixed point";
}

TEST(Transform, DemoSceneIsCanonical) {
    const std::filesystem::path file =
        source_dir() / "framework" / "tests" / "scenes" / "instance_field.json";
    const std::string text = read_scene_text(file);
    EXPECT_EQ(canonical_scene_text(text, file.string(), file.parent_path()), text);
}

}  // namespace
}  // namespace rt
