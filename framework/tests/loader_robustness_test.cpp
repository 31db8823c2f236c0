// The scene and OBJ/MTL readers under damaged input: every prefix of a valid file and random
// byte edits of it give success or the reader's own one-line error (SceneError, ObjError), never
// a crash, a hang or another exception. (The readers' behaviour on good and known-bad files:
// scene_loader_test.cpp, obj_loader_test.cpp.)
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

#include "mutate.h"
#include "scene/obj_loader.h"
#include "scene/scene_loader.h"
#include "testing/scene_text.h"
#include "testing/temp_dir.h"

namespace fs = std::filesystem;

namespace {

using rt::testing::TempDir;

using rt::testing::parse;

// ---- scene files: SceneError or success, never a crash -------------------

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

// ---- OBJ and MTL: ObjError or success, never a crash ---------------------------------------------

// A small valid OBJ using most of the format: comments, groups, every face-entry form, negative
// indices, a quad, a pentagon, materials from a library, CRLF line ends.
const char* const kValidObj =
    "# test object\r\nmtllib lib.mtl\r\no thing\r\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 0\nv 0 0 1\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1 0\nvn 0 0 1\nvn 0 0 -1\n"
    "g front\ns 1\nusemtl red\nf 1/1/1 2/2/1 3/3/1 4/4/1\n"
    "usemtl blue\nf 4//1 3//1 5//1\nf 1/1 2/2 6/3\nf -6 -5 -4 -2 -3\n"
    "g back\nusemtl red\nf 1 6 2\n";
const char* const kValidMtl =
    "newmtl red\nKd 0.8 0.1 0.1\nNs 10\nillum 3\nKs 1 1 1\n"
    "newmtl blue\nKd 0.1 0.1 0.8\nd 0.5\nNi 1.4\n";

// Loads `dir`/m.obj; anything other than success or a one-line ObjError fails the test. On
// success the mesh must be well formed.
void expect_no_crash(const TempDir& dir, const std::string& what) {
    try {
        rt::ObjMesh mesh =
            rt::load_obj(dir.path() / "m.obj", "m.obj", rt::Vec3(2, -1, 1), rt::Vec3(0.5f), 1000);
        for (const auto& t : mesh.triangles)
            for (std::uint32_t v : t) ASSERT_LT(v, mesh.vertices.size()) << what;
        ASSERT_TRUE(mesh.normals.empty() || mesh.normals.size() == mesh.vertices.size()) << what;
        ASSERT_TRUE(mesh.uvs.empty() || mesh.uvs.size() == mesh.vertices.size()) << what;
        ASSERT_EQ(mesh.triangle_material.size(), mesh.triangles.size()) << what;
        for (const rt::Vec3& p : mesh.vertices) ASSERT_TRUE(rt::all_finite(p)) << what;
    } catch (const rt::ObjError& e) {
        std::string message = e.what();
        ASSERT_EQ(message.find_first_of("\r\n"), std::string::npos) << message;
        ASSERT_EQ(message.rfind("mesh \"m.obj\"", 0), 0u) << message;
    } catch (const std::exception& e) {
        FAIL() << "not an ObjError: " << e.what() << "\n  input: " << what;
    }
}

TEST(ObjLoaderRobustness, TheValidObjLoads) {
    TempDir dir("obj-valid");
    dir.write("m.obj", kValidObj);
    dir.write("lib.mtl", kValidMtl);
    rt::ObjMesh mesh = rt::load_obj(dir.path() / "m.obj", "m.obj", rt::Vec3(1), rt::Vec3(0), 1000);
    EXPECT_EQ(mesh.triangles.size(), 2u + 1u + 1u + 3u + 1u);
    EXPECT_EQ(mesh.materials.size(), 2u);
    EXPECT_TRUE(mesh.materials[0].defined && mesh.materials[1].defined);
}

TEST(ObjLoaderRobustness, EveryPrefixOfAValidObj) {
    TempDir dir("obj-prefixes");
    dir.write("lib.mtl", kValidMtl);
    const std::string obj = kValidObj;
    for (std::size_t length = 0; length <= obj.size(); ++length) {
        dir.write("m.obj", obj.substr(0, length));
        expect_no_crash(dir, obj.substr(0, length));
    }
}

TEST(ObjLoaderRobustness, EveryPrefixOfAValidMtl) {
    TempDir dir("mtl-prefixes");
    dir.write("m.obj", kValidObj);
    const std::string mtl = kValidMtl;
    for (std::size_t length = 0; length <= mtl.size(); ++length) {
        dir.write("lib.mtl", mtl.substr(0, length));
        expect_no_crash(dir, mtl.substr(0, length));
    }
}

TEST(ObjLoaderRobustness, RandomByteEditsOfAValidObj) {
    TempDir dir("obj-edits");
    dir.write("lib.mtl", kValidMtl);
    const std::string obj = kValidObj;
    const std::string alphabet =
        std::string("0123456789-+./ \n\r\tvtnfe#lpsgo") + '\0' + "\x01\xff\xc3";
    std::mt19937 random(2718);  // fixed seed: a failure names the input and is reproducible
    for (int round = 0; round < 1000; ++round) {
        const std::string mutant = rt::testing::mutate(obj, alphabet, random);
        dir.write("m.obj", mutant);
        expect_no_crash(dir, mutant);
        if (HasFatalFailure()) return;
    }
}

TEST(ObjLoaderRobustness, RandomByteEditsOfAValidMtl) {
    TempDir dir("mtl-edits");
    dir.write("m.obj", kValidObj);
    const std::string mtl = kValidMtl;
    const std::string alphabet = std::string("0123456789-+. \nKdsNiTrlum#") + '\0' + "\xff";
    std::mt19937 random(3141);
    for (int round = 0; round < 300; ++round) {
        std::string mutant = mtl;
        for (int e = 0; e < 2 && !mutant.empty(); ++e) {
            std::size_t at = random() % mutant.size();
            char c = alphabet[random() % alphabet.size()];
            if (random() % 2)
                mutant[at] = c;
            else
                mutant.insert(mutant.begin() + long(at), c);
        }
        dir.write("lib.mtl", mutant);
        expect_no_crash(dir, mutant);
        if (HasFatalFailure()) return;
    }
}

}  // namespace
