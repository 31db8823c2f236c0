// The scene reader on malformed scenes (framework/tests/bad_scenes/): each gives one SceneError
// naming the file, line and column and what to fix. Good scenes: scene_loader_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/diagnostics.h"
#include "core/source_dir.h"
#include "geometry/procedural_mesh.h"
#include "scene/scene_loader.h"
#include "testing/scene_text.h"
#include "testing/temp_dir.h"

namespace fs = std::filesystem;

namespace {

using rt::testing::error_of;
using rt::testing::parse;
using rt::testing::TempDir;

const fs::path kBadScenes = rt::source_dir() / "framework" / "tests" / "bad_scenes";

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
     R"(unknown "type" "cube"; use "sphere", "plane", "triangle", "box", "mesh", "checkerboard" or "instance")"},
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
    {"63-missing-texture-image", 2, 42,
     R"(error: texture image "no_such_wood.png": no such image file; check the path)"},
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
    {"78-sky-unknown-key", 2, 27, R"(unknown key "sun_color" in "sky")"},
    {"79-environment-negative-ambient", 2, 41, R"("ambient" must be >= 0, got -0.5)"},
    {"80-fog-without-density", 3, 10, R"(the fog needs "density")"},
    {"81-fog-albedo-above-one", 3, 43, R"("albedo" must be between 0 and 1, got 1.2)"},
    {"82-fog-box-without-max", 3, 34, R"(a fog box needs both "min" and "max")"},
    {"83-fog-with-area-light", 3, 10, "fog and area lights together are not supported"},
    {"84-damaged-texture-image", 2, 42,
     R"(error: texture image "84-damaged.png": not a PNG file (its first bytes are wrong))"},
};

class BadSceneFile : public testing::TestWithParam<BadScene> {};

TEST_P(BadSceneFile, ReportsOneLinePointingAtTheMistake) {
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

INSTANTIATE_TEST_SUITE_P(Files, BadSceneFile, testing::ValuesIn(kBadScenesTable),
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
        // Light linking.
        {"{\"materials\": [{\"name\": \"a\"}], \"lights\": [{\"type\": \"point\", \"position\": "
         "[0, "
         "0, 0], \"only\": [\"a\"], \"except\": [\"a\"]}]}",
         "test.json:1:109: error: a light takes \"only\" or \"except\", not both"},
        {"{\"materials\": [{\"name\": \"gold\"}], \"lights\": [{\"type\": \"point\", \"position\": "
         "[0, 0, 0], \"only\": [\"gol\"]}]}",
         "test.json:1:96: error: unknown material \"gol\"; did you mean \"gold\"?"},
        {"{\"lights\": [{\"type\": \"point\", \"position\": [0, 0, 0], \"only\": []}]}",
         "test.json:1:62: error: \"only\" must be a list of material names"},
        {"{\"lights\": [{\"type\": \"directional\", \"direction\": [0, -1, 0], \"shadows\": 1}]}",
         "test.json:1:73: error: \"shadows\" must be true or false"},
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

}  // namespace

// What a program prints for a library's error: the message when it names its place in compiler
// form, else the program's name as the place (core/diagnostics.h).
TEST(Diagnostics, AnErrorWithoutAPlaceGetsTheProgramsName) {
    EXPECT_EQ(rt::error_line("rt",
                             "scene.json:3:5: error: unknown key \"radus\"; did you mean "
                             "\"radius\"?"),
              "scene.json:3:5: error: unknown key \"radus\"; did you mean \"radius\"?");
    EXPECT_EQ(rt::error_line("rt", "cannot open a window (no display)"),
              "rt: error: cannot open a window (no display)");
    EXPECT_EQ(rt::error_line("rt", "a: b\nc: error: d"), "rt: error: a: b\nc: error: d")
        << "only the first line says where";
}
