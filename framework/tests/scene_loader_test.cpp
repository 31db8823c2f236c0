// Tests of the scene file reader (docs/scene-format.md): good files give the right flat arrays,
// every kind of mistake gives one compiler-style line pointing at it, and no input crashes it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/source_dir.h"
#include "geometry/procedural_mesh.h"
#include "scene/obj_loader.h"
#include "scene/scene_loader.h"
#include "temp_dir.h"

namespace fs = std::filesystem;

namespace {

const fs::path kBadScenes = rt::source_dir() / "framework" / "tests" / "bad_scenes";

using rt::testing::TempDir;

rt::Scene parse(const std::string& text, const fs::path& base_dir = fs::path()) {
    return rt::parse_scene(text, "test.json", base_dir);
}

// The message of the SceneError that parsing `text` throws, or "" if it succeeds.
std::string error_of(const std::string& text, const fs::path& base_dir = fs::path()) {
    try {
        parse(text, base_dir);
    } catch (const rt::SceneError& e) {
        return e.what();
    }
    return "";
}

void expect_vec(const rt::Vec3& actual, rt::Real x, rt::Real y, rt::Real z) {
    EXPECT_NEAR(actual.x, x, 1e-6);
    EXPECT_NEAR(actual.y, y, 1e-6);
    EXPECT_NEAR(actual.z, z, 1e-6);
}

// ---- good scenes ---------------------------------------------------------------------------

TEST(SceneLoader, EmptyObjectGivesTheDefaults) {
    rt::Scene scene = parse("{}");
    EXPECT_EQ(scene.source, "test.json");
    EXPECT_EQ(scene.image.width, 640);
    EXPECT_EQ(scene.image.height, 480);
    EXPECT_EQ(scene.mode, rt::RenderMode::Normals);
    EXPECT_EQ(scene.max_depth, 5);
    expect_vec(rt::Vec3(scene.background), 0, 0, 0);
    expect_vec(rt::Vec3(scene.ambient_light), 0, 0, 0);
    EXPECT_EQ(scene.camera.projection, rt::Projection::Perspective);
    expect_vec(scene.camera.eye, 0, 0, 5);
    expect_vec(scene.camera.w, 0, 0, 1);  // looking at the origin along -z
    expect_vec(scene.camera.u, 1, 0, 0);
    expect_vec(scene.camera.v, 0, 1, 0);
    EXPECT_EQ(scene.camera.vertical_fov_degrees, 45);
    EXPECT_EQ(scene.camera.view_height, 2);
    ASSERT_EQ(scene.materials.size(), 1u);  // the implicit "default" material
    EXPECT_EQ(scene.material_names[0], "default");
    EXPECT_EQ(scene.materials[0].shininess, 32.0f);
    EXPECT_EQ(scene.materials[0].ior, 1.5f);
    EXPECT_TRUE(scene.spheres.empty() && scene.planes.empty() && scene.boxes.empty());
    EXPECT_TRUE(scene.vertices.empty() && scene.triangles.empty() && scene.lights.empty());
}

// "shadows" and "fresnel" default to false; "shadows" becomes a feature only with lights.
TEST(SceneLoader, ShadowsAndFresnelFlags) {
    rt::Scene plain = parse(R"({"lights": [{"type": "point", "position": [0, 1, 0]}]})");
    EXPECT_FALSE(plain.shadows);
    EXPECT_FALSE(plain.fresnel);
    EXPECT_FALSE(plain.features.shadows);
    rt::Scene lit = parse(R"({"render": {"shadows": true, "fresnel": true},
                              "lights": [{"type": "point", "position": [0, 1, 0]}]})");
    EXPECT_TRUE(lit.shadows && lit.fresnel && lit.features.shadows);
    rt::Scene dark = parse(R"({"render": {"shadows": true}})");
    EXPECT_TRUE(dark.shadows);
    EXPECT_FALSE(dark.features.shadows);
}

TEST(SceneLoader, FullSceneFillsTheFlatArrays) {
    rt::Scene scene = parse(R"({
      "camera": {"projection": "orthographic", "eye": [0, 2, 0], "look_at": [0, 0, 0],
                 "up": [0, 0, -1], "view_height": 4, "fov": 30},
      "image": {"width": 32, "height": 16},
      "render": {"mode": "shaded", "max_depth": 3},
      "background": [0.1, 0.2, 0.3],
      "ambient_light": [0.5, 0.5, 0.5],
      "materials": [
        {"name": "red", "ambient": [0.1, 0, 0], "diffuse": [0.8, 0.1, 0.1], "specular": [1, 1, 1],
         "shininess": 64, "reflective": [0.2, 0.2, 0.2]},
        {"name": "glass", "transmissive": [0.9, 0.9, 0.9], "ior": 1.33, "emissive": [0, 0, 0.5]}
      ],
      "surfaces": [
        {"type": "sphere", "center": [1, 2, 3], "radius": 0.5, "material": "glass"},
        {"type": "plane", "point": [0, -1, 0], "normal": [0, 3, 4], "material": 1},
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": "red"},
        {"type": "box", "min": [-1, -1, -1], "max": [1, 2, 3]},
        {"type": "sphere", "center": [0, 0, 0], "radius": 2}
      ],
      "lights": [
        {"type": "point", "position": [0, 5, 0], "intensity": [1, 0.5, 0.25], "attenuation": [1, 0.1, 0]},
        {"type": "directional", "direction": [0, -2, 0]}
      ]
    })");
    EXPECT_EQ(scene.camera.projection, rt::Projection::Orthographic);
    EXPECT_EQ(scene.camera.view_height, 4);
    EXPECT_EQ(scene.camera.vertical_fov_degrees, 30);
    expect_vec(scene.camera.w, 0, 1, 0);
    EXPECT_EQ(scene.image.width, 32);
    EXPECT_EQ(scene.image.height, 16);
    EXPECT_EQ(scene.mode, rt::RenderMode::Shaded);
    EXPECT_EQ(scene.max_depth, 3);
    EXPECT_FLOAT_EQ(scene.background.y, 0.2f);
    EXPECT_FLOAT_EQ(scene.ambient_light.x, 0.5f);

    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.material_names[0], "red");
    EXPECT_FLOAT_EQ(scene.materials[0].diffuse.x, 0.8f);
    EXPECT_FLOAT_EQ(scene.materials[0].shininess, 64);
    EXPECT_FLOAT_EQ(scene.materials[0].reflective.z, 0.2f);
    EXPECT_FLOAT_EQ(scene.materials[1].ior, 1.33f);
    EXPECT_FLOAT_EQ(scene.materials[1].diffuse.x, 0.8f);  // default

    ASSERT_EQ(scene.spheres.size(), 2u);
    expect_vec(scene.spheres[0].center, 1, 2, 3);
    EXPECT_EQ(scene.spheres[0].radius, rt::Real(0.5));
    EXPECT_EQ(scene.spheres[0].material, 1);
    EXPECT_EQ(scene.spheres[1].material, 0);  // omitted: material 0
    ASSERT_EQ(scene.planes.size(), 1u);
    expect_vec(scene.planes[0].normal, 0, 0.6f, 0.8f);  // normalised
    EXPECT_EQ(scene.planes[0].material, 1);
    ASSERT_EQ(scene.triangles.size(), 1u);
    ASSERT_EQ(scene.vertices.size(), 3u);
    expect_vec(scene.vertices[scene.triangles[0].v[1]], 1, 0, 0);
    EXPECT_EQ(scene.triangles[0].material, 0);
    ASSERT_EQ(scene.boxes.size(), 1u);
    expect_vec(scene.boxes[0].max, 1, 2, 3);

    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].kind, rt::LightKind::Point);
    expect_vec(scene.lights[0].attenuation, 1, 0.1f, 0);
    EXPECT_FLOAT_EQ(scene.lights[0].intensity.z, 0.25f);
    EXPECT_EQ(scene.lights[1].kind, rt::LightKind::Directional);
    expect_vec(scene.lights[1].direction, 0, -1, 0);  // normalised
    expect_vec(rt::Vec3(scene.lights[1].intensity), 1, 1, 1);

    EXPECT_TRUE(scene.features.spheres && scene.features.planes && scene.features.triangles &&
                scene.features.boxes);
    EXPECT_TRUE(scene.features.reflection && scene.features.refraction && scene.features.emissive);
    EXPECT_TRUE(scene.features.point_lights && scene.features.directional_lights);
}

TEST(SceneLoader, DefaultMaterialCanBeNamed) {
    rt::Scene scene = parse(R"({"surfaces": [
        {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "default"}]})");
    EXPECT_EQ(scene.spheres[0].material, 0);
}

TEST(SceneLoader, MeshSurfaceLoadsAnObj) {
    TempDir dir("mesh");
    // A unit quad (two triangles after triangulation) and a triangle using a scene material.
    dir.write("models/quad.obj",
              "# test quad\n"
              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
              "usemtl unknown_to_the_scene\n"
              "f 1 2 3 4\n"
              "usemtl blue\n"
              "f -4 -3 -2\n");
    fs::path scene_file = dir.write("scene.json", R"({
      "materials": [{"name": "red"}, {"name": "blue"}],
      "surfaces": [
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
        {"type": "mesh", "file": "models/quad.obj", "scale": [2, 3, 1], "translate": [10, 0, -1],
         "material": "red"},
        {"type": "mesh", "file": "models/quad.obj", "scale": 0.5}
      ]})");
    rt::Scene scene = rt::load_scene(scene_file);
    ASSERT_EQ(scene.vertices.size(), 3u + 4u + 4u);
    ASSERT_EQ(scene.triangles.size(), 1u + 3u + 3u);
    // Scale, then translate.
    expect_vec(scene.vertices[3 + 2], 12, 3, -1);
    expect_vec(scene.vertices[7 + 2], 0.5f, 0.5f, 0);
    for (std::size_t i = 1; i < scene.triangles.size(); ++i)
        for (std::uint32_t v : scene.triangles[i].v) {
            EXPECT_GE(v, i <= 3 ? 3u : 7u);
            EXPECT_LT(v, i <= 3 ? 7u : 11u);
        }
    // usemtl "blue" names a scene material; the other name falls back to the surface's.
    EXPECT_EQ(scene.triangles[1].material, 0);
    EXPECT_EQ(scene.triangles[2].material, 0);
    EXPECT_EQ(scene.triangles[3].material, 1);
    EXPECT_EQ(scene.triangles[4].material, 0);  // omitted "material": 0
    EXPECT_EQ(scene.triangles[6].material, 1);
    // "f -4 -3 -2" after 4 vertices counts back from the last one: vertices 1, 2, 3 (1-based).
    EXPECT_EQ(scene.triangles[3].v[0], 3u + 0u);
    EXPECT_EQ(scene.triangles[3].v[2], 3u + 2u);
    EXPECT_TRUE(scene.features.triangles);
}

// A procedural mesh is the generator's mesh, scaled then translated, with its normals and uvs.
TEST(SceneLoader, ProceduralMeshes) {
    rt::Scene scene = parse(R"({
      "materials": [{"name": "a"}, {"name": "b"}],
      "surfaces": [
        {"type": "sphere", "center": [0, 0, 0], "radius": 1},
        {"type": "mesh", "procedural": "torus", "triangles": 2000, "seed": 3, "material": "b",
         "scale": [2, 1, 1], "translate": [0, 5, 0]},
        {"type": "mesh", "procedural": "soup", "triangles": 7, "seed": 9}
      ]})");
    rt::TriangleMesh torus = rt::make_procedural_mesh("torus", 2000, 3);
    rt::TriangleMesh soup = rt::make_procedural_mesh("soup", 7, 9);
    ASSERT_EQ(scene.triangles.size(), torus.triangles.size() + 7);
    ASSERT_EQ(scene.vertices.size(), torus.vertices.size() + soup.vertices.size());
    EXPECT_GE(torus.triangles.size(), 2000u);
    for (std::size_t v = 0; v < torus.vertices.size(); ++v) {
        const rt::Vec3& p = torus.vertices[v];
        ASSERT_EQ(scene.vertices[v], rt::Vec3(p.x * 2, p.y + 5, p.z)) << v;
        ASSERT_EQ(scene.uvs[v], torus.uvs[v]);
        ASSERT_EQ(scene.normals[v], rt::scale_normal(torus.normals[v], rt::Vec3(2, 1, 1)));
    }
    for (std::size_t i = 0; i < torus.triangles.size(); ++i) {
        ASSERT_EQ(scene.triangles[i].v, torus.triangles[i]);
        ASSERT_EQ(scene.triangles[i].material, 1);
    }
    const std::size_t first_soup_vertex = torus.vertices.size();
    EXPECT_EQ(scene.vertices[first_soup_vertex], soup.vertices[0]);
    EXPECT_EQ(scene.normals[first_soup_vertex], rt::Vec3(0));  // no normals: the sentinel
    EXPECT_EQ(scene.triangles.back().material, 0);
    EXPECT_TRUE(scene.features.triangles);
}

// A mirroring scale turns the triangles around, so a closed mesh still faces outwards.
TEST(SceneLoader, MirroredProceduralMeshStillFacesOutwards) {
    rt::Scene scene = parse(R"({"surfaces": [
        {"type": "mesh", "procedural": "icosphere", "triangles": 80, "scale": [-1, 2, 1]}]})");
    double volume = 0;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        rt::Vec3 a, b, c;
        scene.triangle_vertices(i, a, b, c);
        volume += glm::dot(glm::dvec3(a), glm::cross(glm::dvec3(b), glm::dvec3(c))) / 6;
        rt::Vec3 n = rt::shading_normal(scene, i, {0.2f, 0.2f});
        EXPECT_GT(glm::dot(n, a + b + c), 0) << i;
    }
    EXPECT_GT(volume, 0);
}

// The column of the first `marker` in `text` (1-based; the texts below are one line).
std::string at(const std::string& text, const std::string& marker) {
    return "test.json:1:" + std::to_string(text.find(marker) + 1) + ": error: ";
}

TEST(SceneLoader, ProceduralMeshMistakes) {
    const std::string mesh = R"({"surfaces": [{"type": "mesh", )";
    const std::pair<std::string, std::string> cases[] = {
        {R"("file": "m.obj", "procedural": "torus", "triangles": 10}]})",
         "\"procedural\"|a mesh has one of \"file\", \"procedural\" and \"heightfield\""},
        {R"("scale": 2}]})",
         "{\"type\": \"mesh\"|a mesh needs \"file\", \"procedural\" or \"heightfield\""},
        {R"("procedural": "cube", "triangles": 10}]})",
         "\"cube\"|unknown \"procedural\" \"cube\"; use \"icosphere\", \"torus\", \"terrain\" or "
         "\"soup\""},
        {R"("procedural": "Torus", "triangles": 10}]})",
         "\"Torus\"|unknown \"procedural\" \"Torus\"; did you mean \"torus\"?"},
        {R"("procedural": "torus"}]})",
         "{\"type\": \"mesh\"|a procedural mesh needs \"triangles\""},
        {R"("procedural": "soup", "triangles": 0}]})",
         "0}|\"triangles\" must be between 1 and 20000000, got 0"},
        {R"("procedural": "soup", "triangles": 2.5}]})",
         "2.5|\"triangles\" must be a whole number"},
        {R"("procedural": "soup", "triangles": 20000001}]})",
         "20000001|\"triangles\" must be between 1 and 20000000"},
        {R"("procedural": "icosphere", "triangles": 6000000}]})",
         "6000000|the scene would have more than 20000000 triangles (this icosphere has 20971520)"},
        {R"("procedural": "soup", "triangles": 5, "seed": -1}]})",
         "-1|\"seed\" must be between 0 and 9007199254740992"},
        {R"("procedural": "soup", "triangles": 5, "seed": "x"}]})",
         "\"x\"|\"seed\" must be a number"},
        {R"("file": "m.obj", "triangles": 5}]})",
         "\"triangles\"|\"triangles\" is only for procedural meshes"},
        {R"("file": "m.obj", "seed": 5}]})", "\"seed\"|\"seed\" is only for procedural meshes"},
        {R"("procedural": "soup", "triangles": 5, "count": 3}]})",
         "\"count\"|unknown key \"count\" in a mesh"},
    };
    std::vector<std::pair<std::string, std::string>> all(std::begin(cases), std::end(cases));
    if (sizeof(rt::Real) == sizeof(float))  // 3e38 + 3e38 overflows float only
        all.emplace_back(
            R"("procedural": "soup", "triangles": 5, "scale": 3e38, "translate": [3e38, 0, 0]}]})",
            "3e38,|the mesh is too large to represent");
    for (const auto& [rest, expected] : all) {
        const std::string text = mesh + rest;
        const std::size_t bar = expected.find('|');
        const std::string want = at(text, expected.substr(0, bar)) + expected.substr(bar + 1);
        std::string message = error_of(text);
        EXPECT_EQ(message.rfind(want, 0), 0u)
            << "scene: " << text << "\n  got: " << message << "\n want: " << want;
    }
}

// ---- malformed scenes ----------------------------------------------------------------------

struct BadScene {
    const char* file;     // in framework/tests/bad_scenes, without ".json"
    int line, column;     // where the error must point
    const char* message;  // a part of the message
};

// Positions were worked out from the files by hand (and by a script placing a marker at the
// offending character), not copied from the loader's output.
const BadScene kBadScenesTable[] = {
    {"01-trailing-comma", 4, 3, R"(remove the trailing comma)"},
    {"02-truncated-file", 3, 1, R"(the file ends too early)"},
    {"03-empty-file", 1, 1, R"(the file is empty)"},
    {"04-top-level-array", 1, 1, R"(the top level must be a JSON object, got an array)"},
    {"05-unknown-top-level-key", 3, 3,
     R"(unknown key "surface" in the scene; did you mean "surfaces"?)"},
    {"06-misspelled-sphere-key", 3, 45, R"(did you mean "radius"?)"},
    {"07-number-written-as-string", 3, 55, R"("radius" must be a number, got the string "1")"},
    {"08-wrong-array-length", 3, 34, R"("center" must be an array of 3 numbers, got 2 numbers)"},
    {"09-unknown-surface-type", 3, 14,
     R"(unknown "type" "cube"; use "sphere", "plane", "triangle", "box", "mesh" or "checkerboard")"},
    {"10-unknown-projection", 3, 19,
     R"(unknown "projection" "ortho"; did you mean "orthographic"? (allowed: "perspective" or "orthographic"))"},
    {"11-unknown-render-mode", 2, 22, R"(unknown "mode" "shade")"},
    {"12-unknown-material-name", 4, 70, R"(unknown material "blue")"},
    {"13-material-index-out-of-range", 4, 76,
     R"(material index 2 out of range (the scene has 2 materials))"},
    {"14-duplicate-material-name", 4, 14, R"(duplicate material name "red")"},
    {"15-non-finite-number", 3, 55,
     R"("radius" must be a finite number, got 1e999; use an ordinary number)"},
    {"16-negative-colour", 3, 38, R"("diffuse"[1] must be >= 0, got -0.1)"},
    {"17-image-side-too-large", 2, 22, R"("width" must be between 1 and 16384, got 20000)"},
    {"18-too-many-pixels", 2, 12, R"(more than the 67108864)"},
    {"19-max-depth-out-of-range", 2, 45, R"("max_depth" must be between 0 and 64, got 1000)"},
    {"20-negative-radius", 3, 55,
     R"("radius" must be > 0, got -1; give the sphere a positive radius)"},
    {"21-fov-out-of-range", 2, 50, R"("fov" must be between 0 and 180 degrees)"},
    {"22-box-min-above-max", 3, 50, R"("max" must not be below "min", but y is -1 < 0)"},
    {"23-zero-plane-normal", 3, 53, R"("normal" must have a non-zero, finite length)"},
    {"24-eye-equals-look-at", 4, 16, R"("look_at" equals "eye")"},
    {"25-up-parallel-to-view", 5, 11, R"("up" is zero or parallel to the viewing direction)"},
    {"26-sphere-without-radius", 3, 5, R"(a sphere needs "radius")"},
    {"27-surface-without-type", 4, 5, R"(a surface needs "type")"},
    {"28-duplicate-key", 3, 58, R"(duplicate key "radius")"},
    {"29-surfaces-not-an-array", 2, 15, R"("surfaces" must be an array, got an object)"},
    {"30-missing-mesh-file", 3, 30, R"(mesh "no-such-mesh.obj": file not found)"},
    {"31-mesh-face-index-out-of-range", 3, 30,
     R"(mesh "31-face-index.obj" line 7: face index 9 out of range (the file has 4 vertices); fix the face or the vertex list)"},
    {"32-mesh-non-finite-vertex", 3, 30,
     R"(mesh "32-not-finite.obj" line 3: vertex coordinate "1e999" is not finite)"},
    {"33-mesh-without-faces", 3, 30, R"(mesh "33-no-faces.obj": contains no triangles)"},
    {"34-zero-light-direction", 3, 42, R"("direction" must have a non-zero, finite length)"},
    {"35-invalid-utf8", 2, 29, R"(ill-formed UTF-8 byte; save the file as UTF-8)"},
    {"36-zero-view-height", 2, 59, R"("view_height" must be > 0, got 0)"},
    {"37-material-wrong-type", 3, 70, R"("material" must be a material name or index, got true)"},
    {"38-key-of-other-light-type", 3, 46, R"(unknown key "direction" in a point light)"},
    {"39-nesting-too-deep", 1, 113, R"(nested more than 100 deep)"},
    {"40-negative-shininess", 2, 48, R"("shininess" must be >= 0, got -5)"},
    {"41-shadows-not-a-boolean", 2, 43, R"("shadows" must be true or false, got the string "yes")"},
    {"42-unknown-procedural-mesh", 3, 36,
     R"(unknown "procedural" "donut"; use "icosphere", "torus", "terrain" or "soup")"},
    {"43-procedural-mesh-too-large", 3, 60,
     R"("triangles" must be between 1 and 20000000, got 1e9)"},
    {"60-unknown-accelerator", 2, 48, R"(unknown "accelerator" "kdtree"; use "none" or "bvh")"},
    {"61-heat-map-without-bvh", 2, 22, R"(add "accelerator": "bvh" to "render")"},
    {"62-unknown-texture", 3, 49, R"(unknown texture "brick"; did you mean "bricks"?)"},
    {"63-missing-texture-image", 2, 42, R"(no_such_wood.png: error: no such image file)"},
    {"64-texture-with-two-sources", 2, 16, R"(a texture has one source, got "image" and "marble")"},
    {"65-unknown-wrap-mode", 2, 115, R"(unknown "wrap" "tile"; use "repeat", "clamp" or "mirror")"},
    {"70-environment-missing-image", 2, 30,
     R"(environment image "no-such-sky.exr": no such image file; check the path)"},
    {"71-environment-unknown-key", 2, 79,
     R"(unknown key "rotate" in "environment"; did you mean "rotate_y"?)"},
    {"72-cube-face-not-square", 2, 34, R"(cube face "px" is 2x1, not square)"},
    {"73-cube-faces-differ-in-size", 2, 329, R"(cube face "nz" is 16x16 but "px" is 32x32)"},
    {"74-cube-missing-face", 2, 27, R"(a cube map needs "nz")"},
    {"75-environment-latlong-and-cube", 2, 79,
     R"(an environment is one of "latlong", "cube" and "sky")"},
    {"76-sky-sun-narrower-than-a-texel", 2, 49, R"(narrower than a texel of the baked sky)"},
    {"77-environment-sky-and-latlong", 2, 79,
     R"(an environment is one of "latlong", "cube" and "sky")"},
    {"78-sky-unknown-key", 2, 27, R"(unknown key "sun_colour" in "sky")"},
    {"79-environment-negative-ambient", 2, 41, R"("ambient" must be >= 0, got -0.5)"},
    {"80-fog-without-density", 3, 10, R"(the fog needs "density")"},
    {"81-fog-albedo-above-one", 3, 43, R"("albedo" must be between 0 and 1, got 1.2)"},
    {"82-fog-box-without-max", 3, 34, R"(a fog box needs both "min" and "max")"},
    {"83-fog-with-area-light", 3, 10, "fog and area lights together are not supported"},
};

class BadSceneTest : public testing::TestWithParam<BadScene> {};

TEST_P(BadSceneTest, ReportsOneLinePointingAtTheMistake) {
    const BadScene& bad = GetParam();
    const std::string path = (kBadScenes / (std::string(bad.file) + ".json")).string();
    std::string message;
    try {
        rt::load_scene(path);
        FAIL() << path << " loaded without an error";
    } catch (const rt::SceneError& e) {
        message = e.what();
    }
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find('\r'), std::string::npos) << message;
    const std::string prefix =
        path + ":" + std::to_string(bad.line) + ":" + std::to_string(bad.column) + ": error: ";
    EXPECT_EQ(message.rfind(path, 0), 0u) << message;
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << "expected " << prefix << "\n     got " << message;
    EXPECT_NE(message.find(bad.message), std::string::npos)
        << "expected to contain: " << bad.message << "\n                 got: " << message;
    EXPECT_NE(message.find("; "), std::string::npos) << "no fix suggested: " << message;
}

INSTANTIATE_TEST_SUITE_P(Files, BadSceneTest, testing::ValuesIn(kBadScenesTable),
                         [](const testing::TestParamInfo<BadScene>& info) {
                             std::string name = info.param.file;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

TEST(SceneLoader, EveryBadSceneFileIsInTheTable) {
    std::set<std::string> listed;
    for (const BadScene& bad : kBadScenesTable) listed.insert(std::string(bad.file) + ".json");
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(kBadScenes)) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        EXPECT_TRUE(listed.count(entry.path().filename().string())) << entry.path();
    }
    EXPECT_EQ(files, listed.size());
    EXPECT_GE(files, 20u);
}

TEST(SceneLoader, MissingFileNamesThePath) {
    const std::string path = (kBadScenes / "does-not-exist.json").string();
    try {
        rt::load_scene(path);
        FAIL();
    } catch (const rt::SceneError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ":", 0), 0u) << e.what();
        EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
    }
}

TEST(SceneLoader, DirectoryIsNotAScene) {
    try {
        rt::load_scene(kBadScenes);
        FAIL();
    } catch (const rt::SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
    }
}

TEST(SceneLoader, MeshErrorsNameTheObjLine) {
    TempDir dir("obj-errors");
    auto mesh_error = [&](const std::string& obj) {
        dir.write("m.obj", obj);
        return error_of(R"({"surfaces": [{"type": "mesh", "file": "m.obj"}]})", dir.path());
    };
    const std::string position = "test.json:1:40: error: mesh \"m.obj\"";
    std::string e = mesh_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n");
    EXPECT_EQ(e.rfind(position + " line 4: face index 0 is invalid", 0), 0u) << e;
    e = mesh_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n");
    EXPECT_EQ(e.rfind(position + " line 4: face has 2 vertices", 0), 0u) << e;
    e = mesh_error("v 0 0 0\nv 1 0 0\nf 1 2 -3\nv 0 1 0\n");
    EXPECT_EQ(e.rfind(position + " line 3: face index -3 out of range", 0), 0u) << e;
    e = mesh_error("v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(e.rfind(position + " line 2: vertex coordinate \"nan\" is not finite", 0), 0u) << e;
    e = mesh_error("v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(e.rfind(position + " line 2: vertex has 2 coordinates", 0), 0u) << e;
    e = mesh_error("v 0 0 0\r\nv 1 0 0\r\nv 0 x 0\r\nf 1 2 3\r\n");
    EXPECT_EQ(e.rfind(position + " line 3: vertex coordinate \"x\" is not a number", 0), 0u) << e;
    e = mesh_error("v 0 0 0\nv 3e38 0 0\nv 0 1 0\nf 1 2 3\n");  // fine alone, not scaled by 10
    EXPECT_EQ(e, "");
    dir.write("big.obj", "v 0 0 0\nv 3e38 0 0\nv 0 1 0\nf 1 2 3\n");
    e = error_of(R"({"surfaces": [{"type": "mesh", "file": "big.obj", "scale": 10}]})", dir.path());
    EXPECT_NE(e.find("line 2: vertex is too large"), std::string::npos) << e;
}

TEST(SceneLoader, OtherMistakesAreReported) {
    // Smaller cases that need no file of their own: (text, expected start of the message).
    const std::pair<const char*, const char*> cases[] = {
        {"{\"image\": {\"width\": 2.5}}",
         "test.json:1:21: error: \"width\" must be a whole number"},
        {"{\"image\": {\"height\": 0}}", "test.json:1:22: error: \"height\" must be between 1"},
        {"{\"render\": {\"max_depth\": -1}}",
         "test.json:1:26: error: \"max_depth\" must be between 0"},
        {"{\"materials\": [{\"name\": \"a\", \"ior\": 0}]}",
         "test.json:1:37: error: \"ior\" must be > 0"},
        {"{\"materials\": [{\"name\": \"\"}]}",
         "test.json:1:25: error: a material name must not be empty"},
        {"{\"materials\": [7]}", "test.json:1:16: error: \"materials\"[0] must be an object"},
        {"{\"camera\": {\"eye\": [0, 0, 1e39]}}", "test.json:1:27: error: \"eye\"[2] is too large"},
        {"{\"background\": [1, \"0\", 1]}",
         "test.json:1:20: error: \"background\"[1] must be a number"},
        {"{\"lights\": [{\"type\": \"point\"}]}",
         "test.json:1:13: error: a point light needs \"position\""},
        {"{\"lights\": [{\"type\": \"spot\"}]}",
         "test.json:1:22: error: unknown \"type\" \"spot\""},
        {"{\"lights\": [{\"type\": \"point\", \"position\": [0, 0, 0], \"attenuation\": [0, 0, "
         "0]}]}",
         "test.json:1:69: error: \"attenuation\" must not be all zero"},
        {"{\"surfaces\": [{\"type\": \"mesh\", \"file\": \"m.obj\", \"scale\": 0}]}",
         "test.json:1:58: error: \"scale\" must not be 0"},
        {"{\"surfaces\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, "
         "\"material\": -1}]}",
         "test.json:1:80: error: material index -1 out of range"},
        {"{\"surfaces\": [{\"type\": \"triangle\", \"vertices\": [[0, 0, 0], [1, 0, 0]]}]}",
         "test.json:1:48: error: \"vertices\" must be an array of 3 points, got 2"},
        {"{\"camera\": {\"eye\": [0, 0, 5]}, \"camera\": {}}",
         "test.json:1:32: error: duplicate key \"camera\""},
        {"{\"a\\u0062c\": 1}", "test.json:1:2: error: unknown key \"abc\""},
        {"  \n\t", "test.json:1:1: error: the file is empty"},
        {"{\"x\": tru}", "test.json:1:10: error: invalid JSON"},  // nlohmann stops after the word
        {"// comment\n{}", "test.json:1:1: error: invalid JSON"},
        {"{} {}", "test.json:1:4: error: invalid JSON"},
    };
    for (const auto& [text, expected] : cases) {
        std::string message = error_of(text);
        EXPECT_EQ(message.rfind(expected, 0), 0u)
            << "scene: " << text << "\n  got: " << message << "\n want: " << expected;
    }
}

// ---- robustness: whatever the input, SceneError or success, never a crash -------------------

// Parses `text`; anything other than success or SceneError fails the test.
void expect_no_crash(const std::string& text, const fs::path& base_dir = fs::path()) {
    try {
        parse(text, base_dir);
    } catch (const rt::SceneError& e) {
        std::string message = e.what();
        ASSERT_EQ(message.find('\n'), std::string::npos) << message;
        ASSERT_EQ(message.rfind("test.json:", 0), 0u) << message;
    } catch (const std::exception& e) {
        FAIL() << "not a SceneError: " << e.what() << "\n  input: " << text;
    }
}

const char* const kValidScene = R"({
  "camera": {"projection": "perspective", "eye": [0, 1, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 50},
  "image": {"width": 64, "height": 48},
  "render": {"mode": "shaded", "max_depth": 4},
  "background": [0.1, 0.1, 0.2], "ambient_light": [0.1, 0.1, 0.1],
  "materials": [{"name": "red", "diffuse": [0.8, 0.1, 0.1], "specular": [0.5, 0.5, 0.5], "shininess": 20},
                {"name": "glass", "transmissive": [1, 1, 1], "ior": 1.5}],
  "surfaces": [
    {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red"},
    {"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0], "material": 1},
    {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
    {"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "material": "glass"},
    {"type": "mesh", "file": "tri.obj", "translate": [0, 1e-3, 0], "scale": 2}
  ],
  "lights": [{"type": "point", "position": [0, 5, 0], "intensity": [1, 1, 1], "attenuation": [1, 0, 0.01]},
             {"type": "directional", "direction": [1, -1, 0], "intensity": [0.5, 0.5, 0.5]}]
}
)";

TEST(SceneLoaderRobustness, EveryPrefixOfAValidScene) {
    TempDir dir("prefix");
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string text = kValidScene;
    ASSERT_NO_THROW(parse(text, dir.path()));
    for (std::size_t length = 0; length < text.size(); ++length)
        expect_no_crash(text.substr(0, length), dir.path());
}

TEST(SceneLoaderRobustness, RandomMutationsOfAValidScene) {
    TempDir dir("mutate");
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string text = kValidScene;
    const std::string alphabet = "{}[]\":,-+.eE0123456789 \n\\/tfnu\x01\xff\xc3";
    std::mt19937 random(12345);  // fixed seed: failures are reproducible
    for (int round = 0; round < 3000; ++round) {
        const std::string mutant = rt::testing::mutate(text, alphabet, random);
        expect_no_crash(mutant, dir.path());
    }
}

TEST(SceneLoaderRobustness, PathologicalInputs) {
    expect_no_crash(std::string(1'000'000, '['));
    expect_no_crash("{\"surfaces\": " + std::string(100'000, '[') + std::string(100'000, ']') +
                    "}");
    expect_no_crash(std::string("{\"background\": [1, 2, 3]}\0garbage", 33));
    expect_no_crash(std::string(1000, '\0'));
    expect_no_crash("\xEF\xBB\xBF{}");
    expect_no_crash("{\"image\": {\"width\": 1e308, \"height\": -1e308}}");
    expect_no_crash("{\"image\": {\"width\": 99999999999999999999999}}");
    expect_no_crash("{\"render\": {\"max_depth\": 18446744073709551615}}");
    expect_no_crash("{\"camera\": {\"eye\": [3e38, 0, 0], \"look_at\": [-3e38, 0, 0]}}");
    expect_no_crash(
        "{\"surfaces\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1e-999}]}");
    expect_no_crash("{\"surfaces\": [{\"type\": \"mesh\", \"file\": \"/\"}]}");
    expect_no_crash("{\"surfaces\": [{\"type\": \"mesh\", \"file\": \"/dev/null\"}]}");
    std::string key_soup = "{";
    for (int i = 0; i < 2000; ++i) key_soup += "\"k" + std::to_string(i) + "\": {\"~/\": [1]},";
    expect_no_crash(key_soup + "\"end\": 0}");
    std::mt19937 random(99);
    for (int round = 0; round < 200; ++round) {
        std::string garbage(random() % 512, '\0');
        for (char& c : garbage) c = char(random() % 256);
        expect_no_crash(garbage);
    }
}

TEST(SceneLoaderRobustness, EveryPrefixOfAnObj) {
    TempDir dir("obj-prefix");
    const std::string obj =
        "# quad\nmtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
        "usemtl a\nf 1//1 2//1 3//1 4//1\nf -1 -2 -3\nl 1 2\n";
    for (std::size_t length = 0; length <= obj.size(); ++length) {
        dir.write("m.obj", obj.substr(0, length));
        expect_no_crash(R"({"surfaces": [{"type": "mesh", "file": "m.obj"}]})", dir.path());
    }
}

}  // namespace
