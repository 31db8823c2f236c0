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
#include "scene/prepared_scene.h"
#include "scene/scene_loader.h"
#include "testing/scene_text.h"
#include "testing/temp_dir.h"

namespace fs = std::filesystem;

namespace {

using rt::testing::TempDir;

using rt::testing::error_of;
using rt::testing::parse;

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
    EXPECT_FALSE(scene_features(plain).shadows);
    rt::Scene lit = parse(R"({"render": {"shadows": true, "fresnel": true},
                              "lights": [{"type": "point", "position": [0, 1, 0]}]})");
    EXPECT_TRUE(lit.shadows && lit.fresnel && scene_features(lit).shadows);
    rt::Scene dark = parse(R"({"render": {"shadows": true}})");
    EXPECT_TRUE(dark.shadows);
    EXPECT_FALSE(scene_features(dark).shadows);
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

    EXPECT_TRUE(scene_features(scene).spheres && scene_features(scene).planes &&
                scene_features(scene).triangles && scene_features(scene).boxes);
    EXPECT_TRUE(scene_features(scene).reflection && scene_features(scene).refraction &&
                scene_features(scene).emissive);
    EXPECT_TRUE(scene_features(scene).point_lights && scene_features(scene).directional_lights);
}

// Light linking: "only" and "except" become a mask of the first 32 materials and whether later
// ones are lit; "shadows": false clears casts_shadows (docs/scene-format.md#light-linking).
TEST(SceneLoader, LightLinksAreReadAsMasks) {
    const rt::Scene scene = rt::parse_scene(
        R"({"materials": [{"name": "a"}, {"name": "b"}, {"name": "c"}],
            "lights": [{"type": "point", "position": [0, 1, 0], "only": ["b"], "shadows": false},
                       {"type": "directional", "direction": [0, -1, 0], "except": ["a", 2]},
                       {"type": "point", "position": [0, 2, 0]}]})",
        "links.json", ".");
    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[0].reach_mask, 0b010u);
    EXPECT_FALSE(scene.lights[0].reach_rest);
    EXPECT_FALSE(scene.lights[0].casts_shadows);
    EXPECT_TRUE(rt::light_reaches(scene.lights[0], 1));
    EXPECT_FALSE(rt::light_reaches(scene.lights[0], 40)) << "\"only\": later materials are dark";
    EXPECT_EQ(scene.lights[1].reach_mask, ~0b101u);
    EXPECT_TRUE(scene.lights[1].reach_rest);
    EXPECT_TRUE(rt::light_reaches(scene.lights[1], 40)) << "\"except\": later materials are lit";
    EXPECT_EQ(scene.lights[2].reach_mask, ~0u) << "no linking: every material";
    EXPECT_TRUE(scene.lights[2].casts_shadows);
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
    EXPECT_TRUE(scene_features(scene).triangles);
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
    EXPECT_TRUE(scene_features(scene).triangles);
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

}  // namespace
