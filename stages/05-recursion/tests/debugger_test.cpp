// The ray-tree debugger on Whitted's scene: the tree of a pixel on the glass sphere holds a
// reflected and a refracted ray, and the contributions of its nodes sum to the pixel's colour.
#include <nlohmann/json.hpp>

#include "render/prepare.h"
#include "render/ray_tree.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(Debugger, "the-ray-tree-debugger");

// A pixel on the glass sphere of whitted.json (found with `rt render --debug-pixel`).
constexpr int kX = 126, kY = 62;

void walk(const nlohmann::json& node, Color& sum, int& reflections, int& refractions) {
    const auto& c = node.at("contribution");
    sum += Color(c[0].get<float>(), c[1].get<float>(), c[2].get<float>());
    reflections += node.at("kind") == "reflection";
    refractions += node.at("kind") == "refraction";
    for (const auto& child : node.at("children")) walk(child, sum, reflections, refractions);
}

TEST_F(Debugger, WhittedPixelTreeSumsToPixel) {
    const PreparedScene scene = prepare_scene(
        load_scene(testing::source_dir() / "stages/05-recursion/scenes/whitted.json"));
    const PixelTree tree = debug_pixel(scene, kX, kY);
    const auto json = nlohmann::json::parse(ray_tree_json(scene, tree));
    Color sum(0);
    int reflections = 0, refractions = 0;
    walk(json.at("tree"), sum, reflections, refractions);
    EXPECT_GE(reflections, 1);
    EXPECT_GE(refractions, 1);
    EXPECT_EQ(json.at("tree").at("kind"), "camera");
    EXPECT_FALSE(json.at("tree").at("shadow_rays").empty());

    // The colour the debugger reports is the rendered pixel's, and the nodes add up to it.
    const Image image = render(scene, RenderMode::Shaded);
    const Color pixel = image.at(kX, kY);
    const auto& color = json.at("color");
    for (int k = 0; k < 3; ++k) {
        EXPECT_FLOAT_EQ(color[std::size_t(k)].get<float>(), pixel[k]);
        EXPECT_NEAR(sum[k], pixel[k], 1e-4f * std::max(1.0f, pixel[k])) << "channel " << k;
    }
    EXPECT_NE(ray_tree_text(scene, tree).find("refraction ray"), std::string::npos);
}

// The overlay draws the camera ray's pixel red and the secondary rays in their colours.
TEST_F(Debugger, OverlayDrawsTheTree) {
    const PreparedScene scene = prepare_scene(
        load_scene(testing::source_dir() / "stages/05-recursion/scenes/whitted.json"));
    const PixelTree tree = debug_pixel(scene, kX, kY);
    Image image(scene.image.width, scene.image.height, Color(0.5f));
    draw_ray_tree(scene, tree, image);
    int red = 0, blue = 0, yellow = 0, magenta = 0;
    for (const Color& c : image.pixels) {
        red += c == Color(1, 0, 0);
        blue += c == Color(0, 0, 1);
        yellow += c == Color(1, 1, 0);
        magenta += c == Color(1, 0, 1);
    }
    EXPECT_GT(red, 0);
    EXPECT_GT(blue, 0);
    EXPECT_GT(yellow, 0);
    EXPECT_GT(magenta, 0);
}

}  // namespace
}  // namespace rt
