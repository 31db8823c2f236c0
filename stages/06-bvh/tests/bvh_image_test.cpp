// Stage 06 images that are not compared with a reference (the graded scenes are, in
// Graded/Image.*): the node-visit heat map, and the BVH giving the very same image as stage 02's
// loop.
#include <algorithm>

#include "bvh_test_support.h"
#include "render/prepare.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(BvhImage, "checking-your-tree");

// The heat map depends on the exact shape of the tree, so it is not compared with a reference
// image (a valid tree built a little differently would fail). Instead: rays that miss the root
// box test one box and are the darkest pixels; the busiest pixel is at the top of the ramp.
TEST_F(BvhImage, NodeVisitsHeatMap) {
    AccelerationReport tree;
    const PreparedScene scene =
        prepare_scene(load_scene(testing::source_dir() / "stages/06-bvh/scenes/node_visits.json"),
                      {.width = 80, .height = 60}, {}, &tree);
    ASSERT_TRUE(tree.built);
    const rt::Image heat = render(scene, RenderMode::BvhVisits);
    float darkest = 1e9f, brightest = 0;
    for (const Color& c : heat.pixels) {
        ASSERT_NE(c, Color(1, 0, 1)) << "a stub was reached";
        darkest = std::min(darkest, c.r + c.g + c.b);
        brightest = std::max(brightest, c.r + c.g + c.b);
    }
    EXPECT_LT(darkest, 0.01f) << "the top-left corner looks past everything: it should be black";
    EXPECT_GT(brightest, 2.0f) << "the busiest pixel should be pale yellow";
    const Color corner = heat.pixels[0];
    EXPECT_LT(corner.r + corner.g + corner.b, 0.01f)
        << "a ray that misses the root box tests one box";
}
// Bit for bit: the tree only skips work, it never changes what a ray hits.
TEST_F(BvhImage, SameAsWithoutTheTree) {
    AccelerationReport tree;  // small: the loop over 55,000 triangles is slow
    PreparedScene scene =
        prepare_scene(load_scene(testing::source_dir() / "stages/06-bvh/scenes/mesh_garden.json"),
                      {.width = 40, .height = 30}, {}, &tree);
    ASSERT_TRUE(tree.built);
    const rt::Image with = render(scene, RenderMode::Shaded);
    scene.accelerator = Accelerator::None;
    scene.bvh = Bvh{};
    const rt::Image without = render(scene, RenderMode::Shaded);
    ASSERT_EQ(with.pixels.size(), without.pixels.size());
    std::size_t different = 0;
    for (std::size_t i = 0; i < with.pixels.size(); ++i)
        different += with.pixels[i] != without.pixels[i];
    EXPECT_EQ(different, 0u) << "pixels differ between the BVH and stage 02's loop";
}

}  // namespace
}  // namespace rt
