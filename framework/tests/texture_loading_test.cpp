// The texture table as scene files fill it (docs/scene-format.md#textures): images read once,
// stored as in the file, sRGB decided by file type and use, slots with scale and offset, and
// the maps of OBJ/MTL materials (map_Kd, map_Ks, map_Ke, norm, map_Bump with -s, -o, -clamp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/source_dir.h"
#include "image/image.h"
#include "scene/prepared_scene.h"
#include "scene/scene_loader.h"
#include "testing/temp_dir.h"

namespace rt {
namespace {

using testing::TempDir;
namespace fs = std::filesystem;

// A 2 x 1 PNG: stored values (64, 128, 255) and (0, 0, 0).
void write_two_texel_png(const fs::path& file) {
    Image8 image;
    image.width = 2;
    image.height = 1;
    image.data = {64, 128, 255, 0, 0, 0};
    write_image8(image, file);
}

// Scene keys are spelled as identifiers are (docs/conventions.md): "color_space". The old key
// "colour_space" still loads, with a warning at its line; both at once are an error.
TEST(TextureLoading, OldSpellingOfColorSpaceLoadsWithAWarning) {
    TempDir dir("textures");
    write_two_texel_png(dir.path() / "t.png");
    const fs::path old = dir.write("old.json", R"({
  "textures": [{"name": "t", "image": "t.png", "colour_space": "linear"}],
  "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]
})");
    ::testing::internal::CaptureStderr();
    const Scene s = load_scene(old);
    const std::string warned = ::testing::internal::GetCapturedStderr();
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_FALSE(s.textures[0].srgb) << "the old key's value is used";
    EXPECT_NE(warned.find("old.json:2:"), std::string::npos) << warned;
    EXPECT_NE(warned.find("warning: \"colour_space\" is the old spelling of \"color_space\""),
              std::string::npos)
        << warned;
    const fs::path both = dir.write("both.json", R"({
  "textures": [{"name": "t", "image": "t.png", "color_space": "srgb", "colour_space": "linear"}],
  "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]
})");
    try {
        load_scene(both);
        ADD_FAILURE() << "both spellings loaded";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("both.json:2:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("remove \"colour_space\""), std::string::npos)
            << e.what();
    }
}

TEST(TextureLoading, ImagesAreReadOnceAndKeptAsStored) {
    TempDir dir("textures");
    write_two_texel_png(dir.path() / "t.png");
    const fs::path scene = dir.write("s.json", R"({
  "textures": [
    {"name": "color", "image": "t.png", "filter": "nearest", "wrap": "mirror"},
    {"name": "bumps", "image": "t.png"},
    {"name": "forced", "image": "t.png", "color_space": "linear"},
    {"name": "checks", "checker": {"a": [1, 0, 0]}}
  ],
  "materials": [
    {"name": "m", "diffuse_map": {"texture": "color", "scale": [4, 2], "offset": [0.5, 0]},
     "normal_map": "bumps", "emissive_map": "checks"}
  ],
  "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]
})");
    const Scene s = load_scene(scene);
    ASSERT_EQ(s.textures.size(), 4u);
    EXPECT_EQ(s.texture_images.size(), 1u) << "one file, read once";
    ASSERT_EQ(s.texels.size(), 2u);
    EXPECT_NEAR(s.texels[0].r, 64.0f / 255, 1e-6f) << "texels as stored (encoded), not decoded";
    EXPECT_EQ(s.textures[0].filter, TextureFilter::Nearest);
    EXPECT_EQ(s.textures[0].wrap, TextureWrap::Mirror);
    EXPECT_TRUE(s.textures[0].srgb) << "a colour texture from a PNG is sRGB";
    EXPECT_FALSE(s.textures[1].srgb) << "a texture used as a normal map is data";
    EXPECT_FALSE(s.textures[2].srgb) << "\"color_space\": \"linear\" wins";
    EXPECT_EQ(s.textures[3].kind, TextureKind::Checker2D);
    EXPECT_EQ(s.textures[3].a, Color(1, 0, 0));
    EXPECT_EQ(s.textures[3].b, Color(1)) << "b defaults to white";
    const Material& m = s.materials[0];
    EXPECT_EQ(m.diffuse_map.texture, 0);
    EXPECT_EQ(m.diffuse_map.scale[0], 4.0f);
    EXPECT_EQ(m.diffuse_map.offset[0], 0.5f);
    EXPECT_EQ(m.normal_map.texture, 1);
    EXPECT_EQ(m.emissive_map.texture, 3);
    EXPECT_FALSE(m.specular_map.used());
    EXPECT_TRUE(scene_features(s).textures);
    EXPECT_TRUE(scene_features(s).normal_maps);
    EXPECT_TRUE(scene_features(s).image_textures);
    EXPECT_TRUE(scene_features(s).checker_textures) << "the emissive map is a checker";
    EXPECT_FALSE(scene_features(s).noise_textures) << "no material uses marble";
    EXPECT_NE(scene_features(s).describe().find("(images checkers)"), std::string::npos)
        << scene_features(s).describe();
}

TEST(TextureLoading, MtlMapsBecomeTextures) {
    TempDir dir("mtl-maps");
    fs::create_directories(dir.path() / "maps");
    write_two_texel_png(dir.path() / "maps" / "wood.png");
    write_two_texel_png(dir.path() / "maps" / "n.png");
    dir.write("m.mtl",
              "newmtl wood\nKd 1 1 1\nmap_Kd -s 2 3 1 -o 0.25 0 0 maps/wood.png\n"
              "map_Bump -clamp on maps/n.png\n"
              "newmtl plain\nKd 0.5 0.5 0.5\n");
    dir.write("m.obj",
              "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
              "usemtl wood\nf 1/1 2/2 3/3\nusemtl plain\nf 1/1 3/3 2/2\n");
    const fs::path scene =
        dir.write("s.json", R"({"surfaces": [{"type": "mesh", "file": "m.obj"}]})");
    const Scene s = load_scene(scene);
    ASSERT_EQ(s.textures.size(), 2u);
    const Material* wood = nullptr;
    for (std::size_t i = 0; i < s.materials.size(); ++i)
        if (s.material_name(int(i)) == "m.obj:wood") wood = &s.materials[i];
    ASSERT_NE(wood, nullptr);
    ASSERT_TRUE(wood->diffuse_map.used());
    EXPECT_EQ(wood->diffuse_map.scale[0], 2.0f);
    EXPECT_EQ(wood->diffuse_map.scale[1], 3.0f);
    EXPECT_EQ(wood->diffuse_map.offset[0], 0.25f);
    EXPECT_TRUE(s.textures[std::size_t(wood->diffuse_map.texture)].srgb) << "map_Kd is colour";
    ASSERT_TRUE(wood->normal_map.used()) << "map_Bump is read as a normal map";
    const Texture& normal = s.textures[std::size_t(wood->normal_map.texture)];
    EXPECT_FALSE(normal.srgb) << "a normal map is data";
    EXPECT_EQ(normal.wrap, TextureWrap::Clamp) << "-clamp on";
    EXPECT_TRUE(scene_features(s).textures);
}

TEST(TextureLoading, AMissingMapIsOneLineNamingTheFile) {
    TempDir dir("mtl-missing");
    dir.write("m.mtl", "newmtl wood\nmap_Kd nowhere.png\n");
    dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl wood\nf 1 2 3\n");
    const fs::path scene =
        dir.write("s.json", R"({"surfaces": [{"type": "mesh", "file": "m.obj"}]})");
    try {
        load_scene(scene);
        FAIL() << "a missing map_Kd file must be an error";
    } catch (const std::exception& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("nowhere.png"), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    }
}

// Every damaged image of the committed corpus (framework/tests/bad_images), used as a texture:
// one line naming the scene file, the line and column of "image", and the image file.
TEST(TextureLoading, DamagedImagesGiveOneLineErrorsAtTheTexture) {
    TempDir dir("bad-textures");
    const fs::path corpus = source_dir() / "framework" / "tests" / "bad_images";
    int checked = 0;
    for (const auto& entry : fs::directory_iterator(corpus)) {
        if (entry.path().extension() == ".txt") continue;
        const std::string image = entry.path().string();
        const fs::path scene = dir.write(
            "s.json", "{\n  \"textures\": [{\"name\": \"t\", \"image\": \"" + image +
                          "\"}],\n  \"surfaces\": [{\"type\": \"sphere\", \"radius\": 1}]\n}\n");
        try {
            load_scene(scene);
            ADD_FAILURE() << image << " loaded as a texture without an error";
        } catch (const std::exception& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
            EXPECT_NE(message.find("s.json:2:"), std::string::npos)
                << "names the scene file and the line of \"image\": " << message;
            EXPECT_NE(message.find(entry.path().filename().string()), std::string::npos)
                << "names the image: " << message;
        }
        ++checked;
    }
    EXPECT_GE(checked, 10) << "the corpus should hold at least 10 kinds of damage";
}

TEST(TextureLoading, AGreyNormalMapIsRefused) {
    TempDir dir("grey-normal");
    // A 1 x 1 one-channel (grey) PNG, by hand: the framework writes RGB only.
    const unsigned char png[] = {
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
        0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
        0x00, 0x3a, 0x7e, 0x9b, 0x55, 0x00, 0x00, 0x00, 0x0a, 0x49, 0x44, 0x41, 0x54, 0x78,
        0x9c, 0x63, 0x68, 0x00, 0x00, 0x00, 0x82, 0x00, 0x81, 0x77, 0xcd, 0x72, 0xb6, 0x00,
        0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
    std::ofstream(dir.path() / "grey.png", std::ios::binary)
        .write(reinterpret_cast<const char*>(png), sizeof png);
    const fs::path scene = dir.write("s.json", R"({
  "textures": [{"name": "bumps", "image": "grey.png"}],
  "materials": [{"name": "m", "normal_map": "bumps"}],
  "surfaces": [{"type": "sphere", "radius": 1}]
})");
    try {
        load_scene(scene);
        FAIL() << "a one-channel normal map must be refused";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("needs RGB"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("s.json:2:"), std::string::npos) << e.what();
    }
}

// Height maps (the scene file's "heightfield" meshes): one vertex per pixel over [-1, 1]^2,
// y = grey value as stored * height, uv along the image, every triangle facing up.
TEST(Heightfield, OneVertexPerPixelFromTheStoredGrey) {
    TempDir dir("heightfield");
    Image8 image;
    image.width = 3;
    image.height = 2;
    image.data = {0, 0, 0, 255, 255, 255, 0, 0, 0, 51, 51, 51, 51, 51, 51, 51, 51, 51};
    write_image8(image, dir.path() / "h.png");
    const fs::path scene = dir.write("s.json", R"({
  "surfaces": [{"type": "mesh", "heightfield": {"image": "h.png", "height": 2}}]
})");
    const Scene s = load_scene(scene);
    ASSERT_EQ(s.vertices.size(), 6u);
    ASSERT_EQ(s.triangles.size(), 4u);
    EXPECT_EQ(s.vertices[0], Vec3(-1, 0, -1)) << "row 0 at the far edge, column 0 on the left";
    EXPECT_EQ(s.vertices[1], Vec3(0, 2, -1)) << "white: the full height (data, not decoded)";
    EXPECT_NEAR(s.vertices[4].y, 0.4f, 1e-6f) << "51/255 * 2";
    EXPECT_EQ(s.vertices[5], Vec3(1, Real(0.4f), 1));
    ASSERT_EQ(s.uvs.size(), 6u);
    EXPECT_EQ(s.uvs[5], Vec2(1, 1));
    for (const Triangle& t : s.triangles) {
        const Vec3 n = glm::cross(s.vertices[t.v[1]] - s.vertices[t.v[0]],
                                  s.vertices[t.v[2]] - s.vertices[t.v[0]]);
        EXPECT_GT(n.y, 0) << "every triangle faces up";
    }
}

TEST(Heightfield, TooSmallOrMissingImagesAreOneLineErrors) {
    TempDir dir("heightfield-bad");
    Image8 tiny;
    tiny.width = 1;
    tiny.height = 1;
    tiny.data = {9, 9, 9};
    write_image8(tiny, dir.path() / "tiny.png");
    for (const char* file : {"tiny.png", "none.png"}) {
        const fs::path scene = dir.write(
            "s.json", std::string(R"({"surfaces": [{"type": "mesh", "heightfield": {"image": ")") +
                          file + R"("}}]})");
        try {
            load_scene(scene);
            ADD_FAILURE() << file << " loaded";
        } catch (const std::exception& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(file), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

}  // namespace
}  // namespace rt
