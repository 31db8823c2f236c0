// Tests of the OBJ/MTL reader (framework/scene/obj_loader.h) and of the per-vertex shading data
// it feeds (Scene::normals, Scene::uvs, shading_normal, triangle_vertex_uvs): damaged files give one
// clear line naming the file and line, normals and uvs survive OBJ's separate index streams,
// MTL materials become scene materials, and no input crashes the reader.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "core/source_dir.h"
#include "scene/obj_loader.h"
#include "scene/prepared_scene.h"
#include "scene/scene_loader.h"
#include "testing/temp_dir.h"

namespace fs = std::filesystem;

namespace {

using rt::testing::TempDir;

const fs::path kBadObjs = rt::source_dir() / "framework" / "tests" / "bad_objs";

rt::ObjMesh load(const fs::path& file, rt::Vec3 scale = rt::Vec3(1),
                 rt::Vec3 translate = rt::Vec3(0)) {
    return rt::load_obj(file, file.filename().string(), scale, translate, 1'000'000);
}

// The ObjError message loading `file` gives, or "" when it loads.
std::string obj_error_of(const fs::path& file) {
    try {
        load(file);
    } catch (const rt::ObjError& e) {
        return e.what();
    }
    return "";
}

rt::Vec3 geometric_normal(const rt::ObjMesh& mesh, std::size_t i) {
    const auto& t = mesh.triangles[i];
    return glm::normalize(glm::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]],
                                     mesh.vertices[t[2]] - mesh.vertices[t[0]]));
}

// ---- damaged files ---------------------------------------------------------------------------

struct Damage {
    std::string file;
    int line = 0;  // 0: the message names no OBJ line
    std::string part;
};

// framework/tests/bad_objs/expected.txt, shared with the command-line check
// (cmake/check_bad_objs.cmake).
std::vector<Damage> read_expected() {
    std::vector<Damage> out;
    std::ifstream in(kBadObjs / "expected.txt");
    std::string row;
    while (std::getline(in, row)) {
        if (row.empty() || row[0] == '#') continue;
        std::size_t bar1 = row.find('|'), bar2 = row.find('|', bar1 + 1);
        if (bar2 == std::string::npos) {
            ADD_FAILURE() << "malformed row in expected.txt: " << row;
            continue;
        }
        auto trim = [](std::string s) {
            s.erase(0, s.find_first_not_of(' '));
            s.erase(s.find_last_not_of(' ') + 1);
            return s;
        };
        out.push_back({trim(row.substr(0, bar1)), std::stoi(row.substr(bar1 + 1, bar2 - bar1 - 1)),
                       trim(row.substr(bar2 + 1))});
    }
    return out;
}

TEST(ObjLoader, DamagedFilesGiveOneLineErrorsNamingFileAndLine) {
    std::vector<Damage> damages = read_expected();
    EXPECT_GE(damages.size(), 10u);
    for (const Damage& damage : damages) {
        SCOPED_TRACE(damage.file);
        std::string message = obj_error_of(kBadObjs / damage.file);
        ASSERT_NE(message, "") << "loaded without an error";
        std::string start = "mesh \"" + damage.file + "\"" +
                            (damage.line > 0 ? " line " + std::to_string(damage.line) : "") + ": ";
        EXPECT_EQ(message.rfind(start, 0), 0u)
            << "expected to start with: " << start << "\n got: " << message;
        EXPECT_NE(message.find(damage.part), std::string::npos)
            << "expected: " << damage.part << "\n got: " << message;
        EXPECT_EQ(message.find_first_of("\r\n"), std::string::npos) << message;
        EXPECT_NE(message.find("; "), std::string::npos) << "no fix suggested: " << message;
    }
}

TEST(ObjLoader, EveryDamagedFileIsListed) {
    std::set<std::string> listed;
    for (const Damage& damage : read_expected()) listed.insert(damage.file);
    std::set<std::string> present;
    for (const auto& entry : fs::directory_iterator(kBadObjs))
        if (entry.path().extension() == ".obj") present.insert(entry.path().filename().string());
    for (const std::string& file : present)
        EXPECT_TRUE(listed.count(file)) << file << " is not in expected.txt";
    for (const std::string& file : listed) {
        if (file.find("missing-file") != std::string::npos) continue;  // missing on purpose
        EXPECT_TRUE(present.count(file)) << file << " is listed but not in bad_objs/";
    }
}

// ---- normals, uvs, placement -------------------------------------------------------------------

TEST(ObjLoader, NormalsAndUvsGetOneVertexPerCombination) {
    TempDir dir("obj-attributes");
    // A quad whose uvs equal the xy of its positions, then a triangle reusing positions 1 and 3
    // with other uvs and normals: those corners need vertices of their own.
    fs::path file = dir.write("m.obj",
                              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.25\n"
                              "vn 0 0 1\nvn 0 0 2\n"
                              "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
                              "f 1/5/2 3/5/2 4/4/1\n");
    rt::ObjMesh mesh = load(file);
    ASSERT_EQ(mesh.triangles.size(), 3u);
    ASSERT_EQ(mesh.vertices.size(), 6u);  // 4 from the quad, 2 new (position, uv, normal) pairs
    ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.vertices.size());
    for (std::size_t i = 0; i < 2; ++i)
        for (std::uint32_t v : mesh.triangles[i]) {
            EXPECT_EQ(mesh.uvs[v],
                      rt::Vec2(mesh.vertices[v].x, 1 - mesh.vertices[v].y));  // v flipped
            EXPECT_EQ(mesh.normals[v], rt::Vec3(0, 0, 1));
        }
    const auto& last = mesh.triangles[2];
    EXPECT_EQ(mesh.uvs[last[0]], rt::Vec2(0.5f, 0.75f));
    EXPECT_EQ(mesh.normals[last[0]], rt::Vec3(0, 0, 1));  // (0, 0, 2) normalised
    EXPECT_NE(last[0], mesh.triangles[0][0]);
    EXPECT_EQ(mesh.vertices[last[0]], mesh.vertices[mesh.triangles[0][0]]);
    EXPECT_EQ(last[2], mesh.triangles[1][2]);  // 4/4/1 is shared with the quad
    // Scene vertices follow the file's vertex order (position 1 twice, position 3 twice).
    const rt::Vec3 order[] = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 0}, {0, 1, 0}};
    for (std::size_t v = 0; v < 6; ++v) EXPECT_EQ(mesh.vertices[v], order[v]) << v;
}

// Some exporters write "f 1/1/1 ..." into files without any "vt" or "vn" line (the dragon of
// ../shared/data/meshes does). Nothing is there to index, so the indices are dropped with a
// warning naming the first such line, rather than refusing the mesh.
TEST(ObjLoader, IndicesIntoAbsentUvAndNormalListsAreDroppedWithAWarning) {
    TempDir dir("dangling");
    const auto file = dir.write(
        "d.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n# faces\nf 1/1/1 2/1/1 3/1/1\nf 2/1/1 4/1/1 3/1/1\n");
    const rt::ObjMesh mesh = load(file);
    EXPECT_EQ(mesh.triangles.size(), 2u);
    EXPECT_EQ(mesh.vertices.size(), 4u) << "no uvs or normals: vertices stay one per position";
    EXPECT_TRUE(mesh.uvs.empty());
    EXPECT_TRUE(mesh.normals.empty());
    ASSERT_EQ(mesh.warnings.size(), 2u);
    EXPECT_EQ(mesh.warnings[0].rfind("mesh \"d.obj\" line 6: faces name texture coordinates", 0),
              0u)
        << mesh.warnings[0];
    EXPECT_EQ(mesh.warnings[1].rfind("mesh \"d.obj\" line 6: faces name normals", 0), 0u)
        << mesh.warnings[1];
    // With one "vt" line the same index 2 is out of range: that stays an error.
    const auto bad = dir.write("e.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/2 2/1 3/1\n");
    EXPECT_NE(obj_error_of(bad).find("texture coordinate index 2 out of range"), std::string::npos)
        << obj_error_of(bad);
}

TEST(ObjLoader, CornersWithoutNormalsGetTheZeroSentinel) {
    TempDir dir("obj-partial-normals");
    fs::path file = dir.write("m.obj",
                              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\n"
                              "f 1//1 2//1 3//1\nf 2 4 3\n");
    rt::ObjMesh mesh = load(file);
    ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
    EXPECT_TRUE(mesh.uvs.empty());
    for (std::uint32_t v : mesh.triangles[0]) EXPECT_EQ(mesh.normals[v], rt::Vec3(0, 0, 1));
    for (std::uint32_t v : mesh.triangles[1]) EXPECT_EQ(mesh.normals[v], rt::Vec3(0));
    // Without any vn or vt, scene vertex i is OBJ vertex i + 1, even an unused one.
    rt::ObjMesh plain = load(dir.write("p.obj", "v 5 5 5\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n"));
    ASSERT_EQ(plain.vertices.size(), 4u);
    EXPECT_EQ(plain.vertices[0], rt::Vec3(5));
    EXPECT_TRUE(plain.normals.empty());
}

TEST(ObjLoader, ScaleAppliesToNormalsAndMirroringKeepsTheOutside) {
    TempDir dir("obj-scale");
    fs::path file = dir.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 1\nf 1//1 2//1 3//1\n");
    rt::ObjMesh stretched = load(file, rt::Vec3(2, 1, 1));
    // The surface x + z = c stretched by 2 in x is x / 2 + z = c: normal (1/2, 0, 1).
    rt::Vec3 expected = glm::normalize(rt::Vec3(0.5f, 0, 1));
    EXPECT_NEAR(stretched.normals[0].x, expected.x, 1e-6);
    EXPECT_NEAR(stretched.normals[0].z, expected.z, 1e-6);
    EXPECT_GT(geometric_normal(stretched, 0).z, 0);
    rt::ObjMesh mirrored = load(file, rt::Vec3(-1, 1, 1));
    EXPECT_GT(geometric_normal(mirrored, 0).z, 0.99f) << "a mirror in x keeps a +z face facing +z";
    EXPECT_NEAR(mirrored.normals[0].x, -std::sqrt(0.5), 1e-6);
    EXPECT_EQ(rt::scale_normal(rt::Vec3(0), rt::Vec3(3)), rt::Vec3(0));
}

TEST(ObjLoader, DirectivesTheMeshDoesNotUseAreIgnored) {
    TempDir dir("obj-ignored");
    // tinyobjloader would size arrays from the tag's counts (-1 here); polylines and points name
    // vertices that do not exist. None of them is a surface, so none may matter.
    fs::path file = dir.write("m.obj",
                              "o thing\ng part\ns 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                              "t crease -1/0/0\nvw 0 -1 0.5\nl 1 2 99\np -50\nf 1 2 3\ns off\n");
    rt::ObjMesh mesh = load(file);
    EXPECT_EQ(mesh.triangles.size(), 1u);
}

// ---- materials ---------------------------------------------------------------------------------

TEST(ObjLoader, MtlMaterialsBecomeSceneMaterials) {
    TempDir dir("obj-mtl");
    dir.write("models/lib.mtl",
              "# four materials\n"
              "newmtl red\nKa 0.1 0 0\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNs 64\nKe 0 0 0.25\n"
              "newmtl glass\nKd 0 0 0\nd 0.25\nNi 1.33\n"
              "newmtl mirror\nKs 0.9 0.9 0.9\nillum 3\n"
              "newmtl plain\nKd 0.2 0.2 0.2\n"
              "newmtl unused\nKd 1 1 1\n");
    dir.write("models/m.obj",
              "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
              "usemtl red\nf 1 2 3\nusemtl glass\nf 1 2 3\nusemtl mirror\nf 1 2 3\n"
              "usemtl plain\nf 1 2 3\n");
    fs::path scene_file = dir.write("scene.json", R"({
      "materials": [{"name": "plain", "diffuse": [0, 1, 0]}, {"name": "other"}],
      "surfaces": [
        {"type": "mesh", "file": "models/m.obj", "material": "other"},
        {"type": "mesh", "file": "models/m.obj", "translate": [0, 0, 1]}
      ]})");
    rt::Scene scene = rt::load_scene(scene_file);
    // The scene's own "plain" wins; red, glass and mirror come from the library, once each.
    ASSERT_EQ(scene.materials.size(), 5u);
    EXPECT_EQ(scene.material_names[2], "models/m.obj:red");
    EXPECT_EQ(scene.material_names[3], "models/m.obj:glass");
    EXPECT_EQ(scene.material_names[4], "models/m.obj:mirror");
    const rt::Material &red = scene.materials[2], &glass = scene.materials[3],
                       &mirror = scene.materials[4];
    EXPECT_EQ(red.ambient, rt::Color(0.1f, 0, 0));
    EXPECT_EQ(red.diffuse, rt::Color(0.8f, 0.1f, 0.1f));
    EXPECT_EQ(red.specular, rt::Color(0.5f));
    EXPECT_EQ(red.shininess, 64);
    EXPECT_EQ(red.emissive, rt::Color(0, 0, 0.25f));
    EXPECT_EQ(red.reflective, rt::Color(0));    // illum not 3..7
    EXPECT_EQ(red.transmissive, rt::Color(0));  // no d
    EXPECT_EQ(red.ior, 1.5f);                   // no Ni: the scene default
    EXPECT_EQ(glass.transmissive, rt::Color(0.75f));
    EXPECT_EQ(glass.ior, 1.33f);
    EXPECT_EQ(glass.diffuse, rt::Color(0));
    EXPECT_EQ(mirror.reflective, rt::Color(0.9f));
    EXPECT_EQ(mirror.diffuse, rt::Color(0.8f));  // no Kd: the scene default
    ASSERT_EQ(scene.triangles.size(), 8u);
    const int expected[] = {2, 3, 4, 0, 2, 3, 4, 0};
    for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(scene.triangles[i].material, expected[i]) << i;
    EXPECT_TRUE(scene_features(scene).reflection && scene_features(scene).refraction &&
                scene_features(scene).emissive);
}

// UTF-16 without a byte-order mark (the corpus has one with a mark) is named as such, not
// reported as a file without triangles; binary garbage with zero bytes is not taken for it.
TEST(ObjLoader, Utf16WithoutMarkIsNamed) {
    TempDir dir("obj-utf16");
    std::string wide;
    for (char c : std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")) wide += {c, '\0'};
    const fs::path file = dir.write("wide.obj", wide);
    try {
        load(file);
        FAIL() << "a UTF-16 file loaded";
    } catch (const rt::ObjError& e) {
        EXPECT_NE(std::string(e.what()).find("is UTF-16"), std::string::npos) << e.what();
    }
}

// Material names may hold spaces (Blender writes "newmtl Material.001 copy"): the whole rest of
// the newmtl and usemtl lines is the name, and two names sharing a first word stay apart.
TEST(ObjLoader, MaterialNamesWithSpaces) {
    TempDir dir("obj-mtl-spaces");
    dir.write("lib.mtl", "newmtl my glass\nKd 0 0 0\nd 0.25\nnewmtl my  red  \nKd 0.8 0.1 0.1\n");
    dir.write("m.obj",
              "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
              "usemtl my glass\nf 1 2 3\nusemtl my  red\nf 1 2 3\n");
    fs::path scene_file =
        dir.write("scene.json", R"({"surfaces": [{"type": "mesh", "file": "m.obj"}]})");
    rt::Scene scene = rt::load_scene(scene_file);
    ASSERT_EQ(scene.materials.size(), 3u);  // the default and the two from the library
    EXPECT_EQ(scene.material_names[1], "m.obj:my glass");
    EXPECT_EQ(scene.material_names[2], "m.obj:my  red");
    EXPECT_FLOAT_EQ(scene.materials[1].transmissive.r, 0.75f);
    EXPECT_FLOAT_EQ(scene.materials[2].diffuse.r, 0.8f);
    ASSERT_EQ(scene.triangles.size(), 2u);
    EXPECT_EQ(scene.triangles[0].material, 1);
    EXPECT_EQ(scene.triangles[1].material, 2);
}

TEST(ObjLoader, SceneMaterialsNamedAfterTheFileOverrideTheLibrary) {
    TempDir dir("obj-mtl-override");
    dir.write("lib.mtl", "newmtl red\nKd 0.8 0.1 0.1\n");
    dir.write("m.obj", "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    rt::Scene scene = rt::parse_scene(R"({
      "materials": [{"name": "m.obj:red", "diffuse": [0, 0, 1]}],
      "surfaces": [{"type": "mesh", "file": "m.obj"}]})",
                                      "test.json", dir.path());
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.triangles[0].material, 0);
}

TEST(ObjLoader, MissingLibraryIsAnErrorOnlyWhenItIsNeeded) {
    TempDir dir("obj-mtl-missing");
    dir.write("m.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    // The scene defines "red": the library is not needed.
    rt::Scene scene = rt::parse_scene(R"({"materials": [{"name": "x"}, {"name": "red"}],
      "surfaces": [{"type": "mesh", "file": "m.obj"}]})",
                                      "test.json", dir.path());
    EXPECT_EQ(scene.triangles[0].material, 1);
    // Otherwise it is, and the message points at the mesh's "file" value and the mtllib line.
    try {
        rt::parse_scene(R"({"surfaces": [{"type": "mesh", "file": "m.obj"}]})", "test.json",
                        dir.path());
        FAIL() << "no error";
    } catch (const rt::SceneError& e) {
        std::string message = e.what();
        EXPECT_EQ(message.rfind("test.json:1:40: error: mesh \"m.obj\" line 1: material library "
                                "\"gone.mtl\" file not found",
                                0),
                  0u)
            << message;
    }
}

TEST(ObjLoader, MalformedLibrariesAreReported) {
    TempDir dir("obj-mtl-bad");
    dir.write("m.obj", "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    auto mtl_error = [&](const std::string& mtl) {
        dir.write("lib.mtl", mtl);
        return obj_error_of(dir.path() / "m.obj");
    };
    const std::pair<const char*, const char*> cases[] = {
        {"newmtl a\nKd 0.5\n", "mesh \"m.obj\": \"lib.mtl\" line 2: \"Kd\" has 1 number, not 3"},
        {"newmtl a\nKd 0.5 -1 0\n", "\"lib.mtl\" line 2: \"Kd\" must be >= 0, got \"-1\""},
        {"newmtl a\nNs inf\n", "\"lib.mtl\" line 2: \"Ns\" value \"inf\" is not finite"},
        {"newmtl a\nd 1.5\n", "\"lib.mtl\" line 2: \"d\" must be between 0 and 1"},
        {"newmtl a\nillum 2.5\n", "\"illum\" must be a whole number 0..10"},
        {"Kd 1 1 1\nnewmtl a\n", "\"lib.mtl\" line 1: \"Kd\" comes before any \"newmtl\""},
        {"newmtl a\nnewmtl a\n",
         "\"lib.mtl\" line 2: material \"a\" is defined again (first on line 1)"},
        // Names may hold spaces (MaterialNamesWithSpaces); a newmtl without one is refused.
        {"newmtl \nKd 1 1 1\n", "\"lib.mtl\" line 1: \"newmtl\" needs a name"},
        {"newmtl b\n", "mesh \"m.obj\" line 5: usemtl \"a\" is not defined in \"lib.mtl\""},
    };
    for (const auto& [mtl, expected] : cases) {
        std::string message = mtl_error(mtl);
        EXPECT_NE(message.find(expected), std::string::npos)
            << "mtl: " << mtl << "\n got: " << message;
    }
    EXPECT_EQ(mtl_error("newmtl a\nNi 0\nmap_Kd texture.png\nPr 0.5\n"), "");  // ignored or lenient
}

// ---- shading data in the scene -----------------------------------------------------------------

TEST(SceneShading, ShadingNormalInterpolatesOrFallsBack) {
    rt::Scene scene;
    scene.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    scene.triangles.resize(1);
    scene.triangles[0].v = {0, 1, 2};
    const rt::Vec2 center(1.0f / 3, 1.0f / 3);
    EXPECT_EQ(rt::shading_normal(scene, 0, center), rt::Vec3(0, 0, 1));  // no normals: geometric
    rt::Vec2 ua, ub, uc;  // no uvs in the scene: the texture spans the triangle
    rt::triangle_vertex_uvs(scene, 0, ua, ub, uc);
    EXPECT_EQ(ua, rt::Vec2(0, 0));
    EXPECT_EQ(ub, rt::Vec2(1, 0));
    EXPECT_EQ(uc, rt::Vec2(0, 1));
    scene.normals = {
        glm::normalize(rt::Vec3(-1, 0, 1)), glm::normalize(rt::Vec3(1, 0, 1)), {0, 0, 1}};
    scene.uvs = {{0.5f, 0}, {1, 0.25f}, {0, 1}};
    rt::Vec3 at_b = rt::shading_normal(scene, 0, {1, 0});  // beta = 1: vertex b
    EXPECT_NEAR(at_b.x, scene.normals[1].x, 1e-6);
    EXPECT_NEAR(at_b.z, scene.normals[1].z, 1e-6);
    rt::Vec3 halfway = rt::shading_normal(scene, 0, {0.5f, 0});  // between a and b: straight up
    EXPECT_NEAR(halfway.x, 0, 1e-6);
    EXPECT_NEAR(glm::length(halfway), 1, 1e-6);
    rt::triangle_vertex_uvs(scene, 0, ua, ub, uc);
    EXPECT_EQ(ua, scene.uvs[0]);
    EXPECT_EQ(ub, scene.uvs[1]);
    EXPECT_EQ(uc, scene.uvs[2]);
    // Normals on the other side of the winding are turned to the geometric side.
    for (rt::Vec3& n : scene.normals) n = -n;
    EXPECT_GT(rt::shading_normal(scene, 0, center).z, 0);
    // A corner without a normal (the zero sentinel) means the geometric normal.
    scene.normals[2] = rt::Vec3(0);
    EXPECT_EQ(rt::shading_normal(scene, 0, center), rt::Vec3(0, 0, 1));
    // Normals that cancel out give the geometric normal too, never NaN.
    scene.normals = {{1, 0, 0}, {-1, 0, 0}, {1, 0, 0}};
    EXPECT_EQ(rt::shading_normal(scene, 0, {0.5f, 0}), rt::Vec3(0, 0, 1));
}

TEST(SceneShading, MixedSurfacesKeepTheArraysParallel) {
    TempDir dir("obj-mixed");
    dir.write("n.obj",
              "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0.6 0.8\nvt 0.5 0.5\nf 1/1/1 2/1/1 3/1/1\n");
    dir.write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    rt::Scene scene = rt::parse_scene(R"({"surfaces": [
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]},
        {"type": "mesh", "file": "plain.obj"},
        {"type": "mesh", "file": "n.obj"},
        {"type": "mesh", "procedural": "soup", "triangles": 2},
        {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}]})",
                                      "test.json", dir.path());
    ASSERT_EQ(scene.triangles.size(), 6u);
    ASSERT_EQ(scene.normals.size(), scene.vertices.size());
    ASSERT_EQ(scene.uvs.size(), scene.vertices.size());
    for (std::size_t t = 0; t < scene.triangles.size(); ++t) {
        bool from_n = t == 2;
        for (std::uint32_t v : scene.triangles[t].v) {
            rt::Vec3 expected = from_n ? rt::Vec3(0, 0.6f, 0.8f) : rt::Vec3(0);
            EXPECT_NEAR(glm::length(scene.normals[v] - expected), 0, 1e-6) << t;
            EXPECT_EQ(scene.uvs[v], from_n ? rt::Vec2(0.5f) : rt::Vec2(0)) << t;
        }
        rt::Vec3 n = rt::shading_normal(scene, t, {0.2f, 0.3f});
        EXPECT_NEAR(glm::length(n), 1, 1e-6);
        if (from_n) {
            EXPECT_NEAR(n.y, 0.6f, 1e-6);
        }
    }
    EXPECT_EQ(rt::shading_normal(scene, 0, {0.2f, 0.3f}), rt::Vec3(0, 0, 1));
    // A scene without any vertex normals or uvs keeps both arrays empty.
    rt::Scene plain = rt::parse_scene(R"({"surfaces": [{"type": "mesh", "file": "plain.obj"},
        {"type": "mesh", "procedural": "soup", "triangles": 3}]})",
                                      "test.json", dir.path());
    EXPECT_TRUE(plain.normals.empty() && plain.uvs.empty());
}

}  // namespace
