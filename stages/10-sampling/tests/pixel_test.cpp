// Stage 10 tests of whole camera samples (framework loop + sampling.cpp + lights.cpp): pixel
// estimates against analytic answers by t-tests (statistics.h), and the furnace: a white
// diffuse sphere in a uniform white world reflects exactly the world's radiance.
#include <cmath>
#include <numbers>

#include "remote/call_each.h"
#include "render/prepare.h"
#include "render/sampled.h"
#include "scene/scene_loader.h"
#include "statistics.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(PixelEstimates, "1-pixel-samples-and-filters");

std::vector<double> pixel_samples(const PreparedScene& scene, int x, int y, int count,
                                  int channel = 0) {
    // Every sample at once (call_each: a few messages when graded, not one per sample).
    std::vector<
        std::tuple<std::reference_wrapper<const PreparedScene>, int, int, int, TraceObserver*>>
        calls;
    for (int s = 0; s < count; ++s) calls.emplace_back(scene, x, y, s, nullptr);
    std::vector<double> values;
    for (const Color& c : testing::call_each<&sample_pixel>(calls)) values.push_back(c[channel]);
    return values;
}

// White diffuse sphere, k_a = 1 under I_a = 1, in a white world (background 1). With one bounce
// of indirect light every sample is 1: the ambient term is replaced, not added (2 would count
// the world's light twice).
TEST_F(PixelEstimates, FurnaceWhiteSphereInAWhiteWorld) {
    const PreparedScene scene = prepare_scene(parse_scene(R"({
  "camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0], "fov": 30},
  "image": {"width": 9, "height": 9},
  "render": {"mode": "shaded", "samples_per_pixel": 64, "seed": 3, "indirect": "diffuse"},
  "background": [1, 1, 1],
  "ambient_light": [1, 1, 1],
  "materials": [{"ambient": [1, 1, 1], "diffuse": [1, 1, 1], "specular": [0, 0, 0]}],
  "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]
})",
                                                          "furnace.json", "."));
    ASSERT_TRUE(scene.features.indirect_diffuse);
    for (auto [x, y] : {std::pair{4, 4}, {3, 5}, {5, 2}})
        stats::expect_mean(pixel_samples(scene, x, y, 256), 1.0,
                           "furnace pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")");
}

// A white floor under a 2 x 2 square light of radiance 3 at height 2, seen from straight above
// through a narrow lens: the pixel is k_d L F with F the form factor (4 corners of 1 x 1).
TEST_F(PixelEstimates, FloorUnderASquareLight) {
    const PreparedScene scene = prepare_scene(parse_scene(R"({
  "camera": {"eye": [0, 5, 0], "look_at": [0, 0, 0], "up": [0, 0, -1], "fov": 0.5},
  "image": {"width": 1, "height": 1},
  "render": {"mode": "shaded", "samples_per_pixel": 4096, "seed": 5, "filter": "tent"},
  "materials": [{"diffuse": [1, 1, 1], "specular": [0, 0, 0]}],
  "surfaces": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]}],
  "lights": [{"type": "rectangle", "corner": [-1, 2, -1], "edge_u": [2, 0, 0], "edge_v": [0, 0, 2], "radiance": [3, 3, 3]}]
})",
                                                          "floor.json", "."));
    const double x = 0.5,
                 form = 4 * (x / std::sqrt(1 + x * x) * std::atan(x / std::sqrt(1 + x * x)) * 2) /
                        (2 * std::numbers::pi);
    stats::expect_mean(pixel_samples(scene, 0, 0, 4096), 3 * form, "the floor's pixel");
}

}  // namespace
}  // namespace rt
