// Tests of the canonical scene form (`rt fmt`, docs/scene-format.md#canonical-form) and of the
// "checkerboard" shorthand: formatting is idempotent, changes no value, and refuses what the
// loader refuses with the loader's message; a checkerboard is the boxes it stands for.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "core/source_dir.h"
#include "scene/scene_format.h"
#include "scene/scene_loader.h"

namespace fs = std::filesystem;

namespace {

const fs::path kSource = rt::source_dir();

std::string canonical(const std::string& text) {
    return rt::canonical_scene_text(text, "test.json", fs::path());
}

rt::Scene parse_test_scene(const std::string& text) {
    return rt::parse_scene(text, "test.json", fs::path());
}

std::string read_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::uint64_t bits(double d) {
    std::uint64_t b;
    std::memcpy(&b, &d, sizeof b);
    return b;
}

// Every float of the scene's arrays equal bit for bit (so -0 and 0 differ).
void expect_same_scene(const rt::Scene& a, const rt::Scene& b) {
    auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    ASSERT_EQ(a.spheres.size(), b.spheres.size());
    for (std::size_t i = 0; i < a.spheres.size(); ++i) {
        EXPECT_TRUE(same(a.spheres[i].center, b.spheres[i].center)) << i;
        EXPECT_TRUE(same(a.spheres[i].radius, b.spheres[i].radius)) << i;
        EXPECT_EQ(a.spheres[i].material, b.spheres[i].material) << i;
    }
    ASSERT_EQ(a.boxes.size(), b.boxes.size());
    for (std::size_t i = 0; i < a.boxes.size(); ++i) {
        EXPECT_TRUE(same(a.boxes[i].min, b.boxes[i].min)) << i;
        EXPECT_TRUE(same(a.boxes[i].max, b.boxes[i].max)) << i;
        EXPECT_EQ(a.boxes[i].material, b.boxes[i].material) << i;
    }
    ASSERT_EQ(a.planes.size(), b.planes.size());
    for (std::size_t i = 0; i < a.planes.size(); ++i) {
        EXPECT_TRUE(same(a.planes[i].point, b.planes[i].point)) << i;
        EXPECT_TRUE(same(a.planes[i].normal, b.planes[i].normal)) << i;
    }
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
        EXPECT_TRUE(same(a.vertices[i], b.vertices[i])) << i;
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        EXPECT_EQ(a.material_name(int(i)), b.material_name(int(i)));
        EXPECT_TRUE(same(a.materials[i].diffuse, b.materials[i].diffuse)) << i;
        EXPECT_TRUE(same(a.materials[i].specular, b.materials[i].specular)) << i;
        EXPECT_TRUE(same(a.materials[i].shininess, b.materials[i].shininess)) << i;
    }
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        EXPECT_TRUE(same(a.lights[i].position, b.lights[i].position)) << i;
        EXPECT_TRUE(same(a.lights[i].intensity, b.lights[i].intensity)) << i;
    }
    EXPECT_TRUE(same(a.camera.eye, b.camera.eye));
    EXPECT_TRUE(same(a.camera.w, b.camera.w));
    EXPECT_TRUE(same(a.background, b.background));
    EXPECT_EQ(a.image.width, b.image.width);
    EXPECT_EQ(a.mode, b.mode);
    EXPECT_EQ(a.shadows, b.shadows);
}

// A scene dumped one number per line, keys in no particular order, numbers in odd spellings.
const char* const kMessy = R"({
  "lights": [ { "intensity": [ 1.0, 1E0, 10e-1 ], "position": [ 0, 5.000, 0 ], "type": "point" } ],
  "surfaces": [
    {
      "material": "red",
      "radius": 0.10,
      "center": [
        -0.0,
        0.30000000000000004,
        -1.5999999999999996
      ],
      "type": "sphere"
    },
    { "type": "plane", "normal": [0, 1, 0], "point": [0, -1e-7, 0] },
    {"type": "checkerboard", "tiles": [2, 3], "materials": ["red", 0], "min": [-1, -0.1, -1.5], "max": [1, 0, 1.5]},
    { "vertices": [[0,0,0],[1,0,0],[0,1,0]], "type": "triangle" }
  ],
  "materials": [ { "shininess": 32.0, "diffuse": [0.8, 0.1, 0.1], "name": "red" } ],
  "render": { "shadows": true, "mode": "shaded" },
  "image": { "height": 24, "width": 32.0 },
  "camera": { "fov": 45, "look_at": [0, 0, 0], "eye": [0, 1, 12345678901234567890] }
})";

const char* const kMessyCanonical = R"({
  "camera": {"eye": [0, 1, 12345678901234567890], "look_at": [0, 0, 0], "fov": 45},
  "image": {"width": 32, "height": 24},
  "render": {"mode": "shaded", "shadows": true},
  "materials": [
    {"name": "red", "diffuse": [0.8, 0.1, 0.1], "shininess": 32}
  ],
  "surfaces": [
    {"type": "sphere", "center": [-0.0, 0.30000000000000004, -1.5999999999999996], "radius": 0.1, "material": "red"},
    {"type": "plane", "point": [0, -1e-07, 0], "normal": [0, 1, 0]},
    {"type": "checkerboard", "min": [-1, -0.1, -1.5], "max": [1, 0, 1.5], "tiles": [2, 3], "materials": ["red", 0]},
    {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}
  ],
  "lights": [
    {"type": "point", "position": [0, 5, 0], "intensity": [1, 1, 1]}
  ]
}
)";

TEST(SceneFormat, WritesTheCanonicalLayout) {
    EXPECT_EQ(canonical(kMessy), kMessyCanonical);
}

TEST(SceneFormat, IsIdempotentAndPreservesEveryValue) {
    const std::string once = canonical(kMessy);
    EXPECT_EQ(canonical(once), once);
    expect_same_scene(parse_test_scene(kMessy), parse_test_scene(once));
    // -0.0 stays negative zero (written "-0.0", since "-0" would read back as the integer 0).
    EXPECT_TRUE(std::signbit(parse_test_scene(once).spheres[0].center.x));
}

TEST(SceneFormat, StageScenesAreCanonicalAndKeepTheirValues) {
    // whitted.json: a checkerboard, spheres, materials with every kind of colour.
    const fs::path file = kSource / "stages/05-recursion/scenes/whitted.json";
    const std::string text = read_file(file);
    const std::string formatted = rt::canonical_scene_text(text, file.string(), file.parent_path());
    EXPECT_EQ(formatted, text) << "run: rt fmt " << file.string();
    EXPECT_EQ(rt::canonical_scene_text(formatted, file.string(), file.parent_path()), formatted);
    expect_same_scene(rt::load_scene(file),
                      rt::parse_scene(formatted, "x.json", file.parent_path()));
    // The same scene one number per line (as the files were dumped before) formats back to it.
    const std::string dumped = nlohmann::json::parse(text).dump(2) + "\n";
    EXPECT_EQ(rt::canonical_scene_text(dumped, file.string(), file.parent_path()), text);
}

TEST(SceneFormat, NumbersReadBackAsTheSameDouble) {
    EXPECT_EQ(rt::canonical_number(0.1), "0.1");
    EXPECT_EQ(rt::canonical_number(1.0), "1");
    EXPECT_EQ(rt::canonical_number(-4.0), "-4");
    EXPECT_EQ(rt::canonical_number(-0.0), "-0.0");
    EXPECT_EQ(rt::canonical_number(0.0), "0");
    EXPECT_EQ(rt::canonical_number(1e-7), "1e-07");
    EXPECT_EQ(rt::canonical_number(1e22), "1e+22");
    EXPECT_EQ(rt::canonical_number(-1.5999999999999996), "-1.5999999999999996");
    EXPECT_EQ(rt::canonical_number(double(0.1f)), "0.10000000149011612");
    std::mt19937_64 random(11);
    for (int i = 0; i < 20000; ++i) {
        double d;
        const std::uint64_t b = random();
        std::memcpy(&d, &b, sizeof d);
        if (!std::isfinite(d)) continue;
        if (i % 2)
            d = std::ldexp(double(random() % 100000), -int(random() % 20));  // short decimals
        const std::string text = rt::canonical_number(d);
        ASSERT_EQ(bits(std::strtod(text.c_str(), nullptr)), bits(d)) << text;
        // ... and through the JSON reader the loader uses (integers included).
        ASSERT_EQ(bits(nlohmann::json::parse(text).get<double>()), bits(d)) << text;
    }
}

TEST(SceneFormat, RefusesWhatTheLoaderRefusesWithItsMessage) {
    const char* const bad[] = {
        "",
        "not json",
        "[1, 2]",
        R"({"surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1},]})",
        R"({"surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}]})",
        R"({"surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "color": 1}]})",
        R"({"camera": {"fov": 45, "fov": 50}})",
        R"({"comment": "unknown keys are errors, as in the loader"})",
        "{\"image\": {\"width\": 10}} // no comments",
        R"({"surfaces": [{"type": "mesh", "file": "no-such.obj"}]})",
    };
    for (const char* text : bad) {
        std::string loader, formatter;
        try {
            parse_test_scene(text);
        } catch (const rt::SceneError& e) {
            loader = e.what();
        }
        try {
            canonical(text);
        } catch (const rt::SceneError& e) {
            formatter = e.what();
        }
        EXPECT_FALSE(loader.empty()) << text;
        EXPECT_EQ(formatter, loader) << text;
        EXPECT_EQ(formatter.rfind("test.json:", 0), 0u) << formatter;
    }
}

TEST(SceneFormat, EmptyAndSmallScenes) {
    EXPECT_EQ(canonical("{}"), "{}\n");
    EXPECT_EQ(canonical(" { \"surfaces\" : [ ] } "), "{\n  \"surfaces\": []\n}\n");
    EXPECT_EQ(canonical("{\"materials\": [{}], \"background\": [0.5, 0.5, 0.5]}"),
              "{\n  \"background\": [0.5, 0.5, 0.5],\n  \"materials\": [\n    {}\n  ]\n}\n");
    // Strings keep their characters (JSON escapes only where JSON needs them).
    EXPECT_EQ(canonical("{\"materials\": [{\"name\": \"gr\\u00fcn \\\"A\\\"\"}]}"),
              "{\n  \"materials\": [\n    {\"name\": \"gr\xC3\xBCn \\\"A\\\"\"}\n  ]\n}\n");
}

// ---- the checkerboard shorthand --------------------------------------------------------------

TEST(Checkerboard, ExpandsToTheBoxesOfTheFloor) {
    rt::Scene scene =
        parse_test_scene(R"({"materials": [{"name": "dark"}, {"name": "light"}], "surfaces": [
        {"type": "box", "min": [5, 5, 5], "max": [6, 6, 6], "material": "light"},
        {"type": "checkerboard", "min": [-2, -0.1, -1.5], "max": [2, 0, 1.5], "tiles": [2, 3], "materials": ["dark", "light"]},
        {"type": "box", "min": [7, 7, 7], "max": [8, 8, 8]}]})");
    ASSERT_EQ(scene.boxes.size(), 8u);
    EXPECT_EQ(scene.boxes[0].min.x, 5);
    EXPECT_EQ(scene.boxes[7].min.x, 7);
    const rt::Real x[] = {-2, 0, 2}, z[] = {-1.5, -0.5, 0.5, 1.5};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 3; ++j) {
            const rt::Box& b = scene.boxes[std::size_t(1 + i * 3 + j)];  // x outer, z inner
            EXPECT_EQ(b.min, rt::Vec3(x[i], rt::Real(-0.1), z[j])) << i << " " << j;
            EXPECT_EQ(b.max, rt::Vec3(x[i + 1], 0, z[j + 1])) << i << " " << j;
            EXPECT_EQ(b.material, (i + j) % 2) << i << " " << j;
        }
}

TEST(Checkerboard, EdgesAreComputedInDoubleFromTheNumbersAsWritten) {
    // edge k = min + (max - min) * k / n, then rounded once to Real; the last edge is max.
    rt::Scene scene = parse_test_scene(R"({"surfaces": [
        {"type": "checkerboard", "min": [0.1, 0, 0], "max": [0.7, 1, 1], "tiles": [3, 1], "materials": [0, 0]}]})");
    ASSERT_EQ(scene.boxes.size(), 3u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(scene.boxes[std::size_t(k)].min.x, rt::Real(0.1 + (0.7 - 0.1) * k / 3)) << k;
        EXPECT_EQ(scene.boxes[std::size_t(k)].max.x,
                  k == 2 ? rt::Real(0.7) : rt::Real(0.1 + (0.7 - 0.1) * (k + 1) / 3))
            << k;
    }
}

TEST(Checkerboard, Mistakes) {
    const std::string head =
        R"({"materials": [{"name": "a"}, {"name": "b"}], "surfaces": [{"type": "checkerboard", )";
    const std::pair<std::string, std::string> cases[] = {
        {R"("max": [1, 0, 1], "tiles": [2, 2], "materials": ["a", "b"]}]})",
         "{\"type\": \"checkerboard\"|a checkerboard needs \"min\""},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "materials": ["a", "b"]}]})",
         "{\"type\": \"checkerboard\"|a checkerboard needs \"tiles\""},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "tiles": [2, 2]}]})",
         "{\"type\": \"checkerboard\"|a checkerboard needs \"materials\""},
        {R"("min": [0, 0, 0], "max": [0, 0, 1], "tiles": [2, 2], "materials": ["a", "b"]}]})",
         "0, 0, 1]|\"max\" must be above \"min\", but x is 0 <= 0"},
        {R"("min": [0, 0, 0], "max": [1, -1, 1], "tiles": [2, 2], "materials": ["a", "b"]}]})",
         "-1, 1]|\"max\" must not be below \"min\", but y is -1 < 0"},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "tiles": [2], "materials": ["a", "b"]}]})",
         "[2]|\"tiles\" must be an array of 2 whole numbers"},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "tiles": [2, 1.5], "materials": ["a", "b"]}]})",
         "1.5]|\"tiles\"[1] must be a whole number"},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "tiles": [0, 2], "materials": ["a", "b"]}]})",
         "0, 2]|\"tiles\"[0] must be between 1 and 1024, got 0"},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "tiles": [2, 2000], "materials": ["a", "b"]}]})",
         "2000]|\"tiles\"[1] must be between 1 and 1024"},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "tiles": [2, 2], "materials": "a"}]})",
         "\"a\"}]|\"materials\" must be an array of 2 materials, got the string"},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "tiles": [2, 2], "materials": ["a", "c"]}]})",
         "\"c\"]|unknown material \"c\""},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "tiles": [2, 2], "materials": ["a", 5]}]})",
         "5]|material index 5 out of range"},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "tiles": [2, 2], "materials": [true, "a"]}]})",
         "true|\"materials\"[0] must be a material name or index"},
        {R"("min": [0, 0, 0], "max": [1, 0, 1], "tiles": [2, 2], "materials": ["a", "b"], "material": "a"}]})",
         "\"material\"|unknown key \"material\" in a checkerboard; did you mean \"materials\"?"},
    };
    for (const auto& [rest, expected] : cases) {
        const std::string text = head + rest;
        const std::size_t bar = expected.find('|');
        const std::string want =
            "test.json:1:" + std::to_string(text.find(expected.substr(0, bar)) + 1) +
            ": error: " + expected.substr(bar + 1);
        std::string message;
        try {
            parse_test_scene(text);
        } catch (const rt::SceneError& e) {
            message = e.what();
        }
        EXPECT_EQ(message.rfind(want, 0), 0u)
            << "scene: " << text << "\n  got: " << message << "\n want: " << want;
    }
}

}  // namespace

namespace {

// The environment section: after "background", its keys and the cube faces in table order.
TEST(SceneFormat, EnvironmentKeysInTableOrder) {
    const fs::path cube = kSource / "stages/08-environment/scenes/cube";
    std::string faces;
    for (const char* f : {"nz", "pz", "ny", "py", "nx", "px"})
        faces += std::string(faces.empty() ? "" : ", ") + "\"" + f + "\": \"" +
                 (cube / (std::string(f) + ".png")).string() + "\"";
    const std::string text = "{\"environment\": {\"rotate_y\": 10, \"cube\": {" + faces +
                             "}, \"intensity\": 2}, \"background\": [0, 0, 0]}";
    const std::string out = canonical(text);
    EXPECT_LT(out.find("\"background\""), out.find("\"environment\""));
    EXPECT_LT(out.find("\"cube\""), out.find("\"intensity\""));
    EXPECT_LT(out.find("\"intensity\""), out.find("\"rotate_y\""));
    const char* order[] = {"\"px\"", "\"nx\"", "\"py\"", "\"ny\"", "\"pz\"", "\"nz\""};
    for (int i = 0; i + 1 < 6; ++i) EXPECT_LT(out.find(order[i]), out.find(order[i + 1])) << out;
    EXPECT_EQ(canonical(out), out);
}

}  // namespace
