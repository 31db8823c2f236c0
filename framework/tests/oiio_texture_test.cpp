// The OpenImageIO texture filter (render/oiio_textures.h) on stage 07's filtering scene, a floor
// of fine checks running to the horizon: it must agree with bilinear where the texture is
// magnified and average the checks where one pixel covers many (where nearest aliases). Links
// the course's reference textures.cpp, like `rt`.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/source_dir.h"
#include "image/image.h"
#include "image/oiio_loader.h"
#include "render/accelerate.h"
#include "render/camera_ray.h"
#include "render/nearest_hit.h"
#include "render/oiio_textures.h"
#include "render/prepare.h"
#include "render/render.h"
#include "render/texturing.h"
#include "scene/scene_loader.h"
#include "stage_api/stage08.h"

namespace rt {
namespace {

constexpr int kWidth = 400, kHeight = 300;

PreparedScene filtering_scene() {
    PreparedScene scene =
        prepare_scene(load_scene(source_dir() / "stages/07-textures/scenes/filtering.json"));
    scene.image = ImageSize{kWidth, kHeight};
    return scene;
}

Image render_with(TextureLookup lookup, int width = kWidth, int height = kHeight) {
    PreparedScene scene = filtering_scene();
    scene.image = ImageSize{width, height};
    if (lookup == TextureLookup::Oiio || lookup == TextureLookup::OiioAniso)
        use_oiio_textures(scene, lookup == TextureLookup::OiioAniso);
    else
        scene.texture_lookup = lookup;
    return render(scene, RenderMode::Shaded);
}

// The mean linear value of the checks (the floor is lit by ambient light 1 alone, so a pixel is
// its filtered texel).
float mean_grey() {
    const PreparedScene scene = filtering_scene();
    const TextureView view = scene.texture_view(0, scene.textures[0].srgb);
    double sum = 0;
    for (int j = 0; j < view.height; ++j)
        for (int i = 0; i < view.width; ++i) {
            const float s = view.stored(i, j).g;
            sum += view.srgb ? srgb_to_linear(s) : s;
        }
    return float(sum / (view.width * view.height));
}

// The mean |pixel - grey| (green) over rows [y0, y1), floor pixels only (not the sky).
double mean_deviation(const Image& image, int y0, int y1, float grey, const Color& sky) {
    double sum = 0;
    int count = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Color& c = image.at(x, y);
            if (std::abs(c.r - sky.r) < 1e-4f && std::abs(c.b - sky.b) < 1e-4f) continue;
            sum += std::abs(c.g - grey);
            ++count;
        }
    return count ? sum / count : 1e9;
}

// The first row (from the top) showing floor: the far edge of the boxes.
int far_edge(const Image& image, const Color& sky) {
    for (int y = 0; y < image.height; ++y)
        if (std::abs(image.at(image.width / 2, y).b - sky.b) > 1e-4f) return y;
    return image.height;
}

// A camera 1 above the plane y = 0 looking straight down, 90 degrees over 100 rows: each pixel
// spans 0.02 world units on the plane, which plane_texcoord measures in world units.
TEST(OiioTextures, RayDifferentialsGiveThePixelFootprint) {
    PreparedScene scene;
    scene.image = ImageSize{100, 100};
    scene.camera = make_look_at_camera(Projection::Perspective, Vec3(0, 1, 0), Vec3(0, 0, 0),
                                       Vec3(0, 0, -1), 90, 2);
    scene.planes.push_back(Plane{Vec3(0), Vec3(0, 1, 0), 0});
    for (const auto& [x, y] : {std::pair{50, 50}, std::pair{10, 80}}) {
        const Vec2 center(Real(x) + Real(0.5), Real(y) + Real(0.5));
        const Ray ray = camera_ray(scene.camera, center, scene.image);
        Hit hit;
        ASSERT_TRUE(nearest_hit(scene, ray, Interval{0, kInfinity}, hit));
        SurfacePoint at = surface_point(scene, ray, hit);
        at.texcoord = surface_texcoord(scene, hit, at);
        const RayDifferential rays{camera_ray(scene.camera, center + Vec2(1, 0), scene.image),
                                   camera_ray(scene.camera, center + Vec2(0, 1), scene.image)};
        const TexcoordDerivatives d = texcoord_derivatives(scene, hit, at, rays);
        EXPECT_NEAR(glm::length(d.dx), 0.02, 1e-5) << x << "," << y;
        EXPECT_NEAR(glm::length(d.dy), 0.02, 1e-5) << x << "," << y;
        EXPECT_NEAR(glm::dot(d.dx, d.dy), 0, 1e-7) << "the pixel's sides are perpendicular";
    }
}

TEST(OiioTextures, AgreesWithBilinearWhereMagnified) {
    const Image oiio = render_with(TextureLookup::Oiio);
    const Image bilinear = render_with(TextureLookup::Bilinear);
    // The bottom rows: the floor about 3 units away, each texel several pixels wide.
    double worst = 0;
    for (int y = kHeight - 20; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, double(std::abs(oiio.at(x, y)[c] - bilinear.at(x, y)[c])));
    int between = 0;  // pixels on the checks' edges, where bilinear blends two texels
    for (int x = 0; x < kWidth; ++x) {
        const float g = bilinear.at(x, kHeight - 1).g;
        between += g > 0.01f && g < 0.8f;
    }
    std::printf(
        "bottom 20 rows: largest |oiio - bilinear| %.2e (%d blended pixels in the last row)\n",
        worst, between);
    EXPECT_GT(between, 20) << "the rows compared should cross the checks' edges";
    EXPECT_LT(worst, 0.01) << "OIIO's finest level should be the student's bilinear lookup";
}

TEST(OiioTextures, AveragesTheChecksAtTheHorizonWhereNearestAliases) {
    const Color sky = filtering_scene().background;
    const float grey = mean_grey();
    const Image nearest = render_with(TextureLookup::Nearest);
    const Image oiio = render_with(TextureLookup::Oiio);
    const Image aniso = render_with(TextureLookup::OiioAniso);
    const int top = far_edge(oiio, sky);
    ASSERT_LT(top, kHeight / 2) << "the floor's far edge should be in the upper half";
    const int y0 = top + 1, y1 = top + 16;  // the distant floor, many texels a pixel
    const double nearest_error = mean_deviation(nearest, y0, y1, grey, sky);
    const double oiio_error = mean_deviation(oiio, y0, y1, grey, sky);
    const double aniso_error = mean_deviation(aniso, y0, y1, grey, sky);
    std::printf("mean |pixel - %.4f| in rows %d-%d: nearest %.4f, oiio %.4f, oiio-aniso %.4f\n",
                grey, y0, y1 - 1, nearest_error, oiio_error, aniso_error);
    EXPECT_GT(nearest_error, 0.15) << "nearest should alias: single texels, black or white";
    EXPECT_LT(oiio_error, 0.05) << "trilinear should give about the checks' mean";
    EXPECT_LT(aniso_error, 0.05);
}

// Each filter against the bilinear render supersampled 8 x 8 (box filter), the pixel's true
// average to a good approximation: RMS error over the image, and time.
TEST(OiioTextures, ErrorAgainstASupersampledReference) {
    constexpr int w = 200, h = 150, n = 8;
    const Image fine = render_with(TextureLookup::Bilinear, w * n, h * n);
    Image reference(w, h);
    for (int y = 0; y < h * n; ++y)
        for (int x = 0; x < w * n; ++x) reference.at(x / n, y / n) += fine.at(x, y) / float(n * n);
    double errors[4];
    const TextureLookup lookups[4] = {TextureLookup::Nearest, TextureLookup::Bilinear,
                                      TextureLookup::Oiio, TextureLookup::OiioAniso};
    const char* names[4] = {"nearest", "bilinear", "oiio", "oiio-aniso"};
    for (int k = 0; k < 4; ++k) {
        const auto start = std::chrono::steady_clock::now();
        const Image image = render_with(lookups[k], w, h);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        double sum = 0;
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            const Color d = image.pixels[i] - reference.pixels[i];
            sum += glm::dot(d, d) / 3;
        }
        errors[k] = std::sqrt(sum / double(image.pixels.size()));
        std::printf("%-10s RMS error %.4f, %.0f ms (scene setup included)\n", names[k], errors[k],
                    ms);
    }
    EXPECT_LT(errors[2], errors[1]) << "mip-mapping should beat bilinear on this floor";
    EXPECT_LT(errors[3], errors[1]);
}

// The course's lat-long convention is OpenImageIO's (docs/conventions.md#environment-maps): the
// reference environment_radiance (stage 08) and TextureSystem::environment, both bilinear in
// the finest level, agree on random directions. Away from the poles (|y| < 0.95), where stage
// 08 clamps v to the row centres and OpenImageIO does not; tolerance 1e-3 for the rounding of
// two different but equivalent formulas (texels are in [0, 1], neighbours differ by up to 1).
TEST(OiioTextures, LatLongAgreesWithEnvironment) {
    const image_files::OiioPlugin& plugin = image_files::oiio_plugin();
    ASSERT_TRUE(plugin.textures_create) << plugin.problem;
    constexpr int w = 64, h = 32;
    std::vector<Color> texels;
    std::vector<float> rgb;
    std::uint32_t state = 12345;
    const auto next = [&state] {
        return float((state = state * 1664525u + 1013904223u) >> 8) / 16777216.0f;
    };
    for (int k = 0; k < w * h; ++k) {
        const Color c(next(), next(), next());
        texels.push_back(c);
        rgb.insert(rgb.end(), {c.r, c.g, c.b});
    }
    PreparedScene scene;
    scene.environment.kind = EnvironmentKind::LatLong;
    scene.environment.image = scene.add_texture_image(w, h, texels);
    refresh_features(scene);

    char error[512] = "";
    RtOiioTextures* system = plugin.textures_create(error, sizeof error);
    ASSERT_TRUE(system) << error;
    const int index = plugin.environment_add(system, rgb.data(), w, h, error, sizeof error);
    ASSERT_GE(index, 0) << error;
    double worst = 0;
    for (int k = 0; k < 2000; ++k) {
        const Vec3 d(2 * next() - 1, 2 * next() - 1, 2 * next() - 1);
        const Real length = glm::length(d);
        if (length < 0.1f || std::abs(d.y) > 0.95f * length) continue;
        const Color ours = environment_radiance(scene, d);
        float theirs[3];
        plugin.environment_lookup(system, index, d.x, d.y, d.z, theirs);
        const double diff = std::max({std::abs(ours.r - theirs[0]), std::abs(ours.g - theirs[1]),
                                      std::abs(ours.b - theirs[2])});
        worst = std::max(worst, diff);
        EXPECT_LT(diff, 1e-3) << "direction (" << d.x << ", " << d.y << ", " << d.z << "): ours ("
                              << ours.r << ", " << ours.g << ", " << ours.b << "), OpenImageIO's ("
                              << theirs[0] << ", " << theirs[1] << ", " << theirs[2] << ")";
        if (diff >= 1e-3) break;
    }
    plugin.textures_destroy(system);
    std::printf("largest difference over the directions: %.2g\n", worst);
}

TEST(OiioTextures, MissingPluginIsOneLineNamingTheFix) {
    const image_files::OiioPlugin plugin =
        image_files::open_oiio_plugin({"/nonexistent/lib/librt_oiio.so"});
    EXPECT_EQ(plugin.textures_create, nullptr);
    EXPECT_EQ(plugin.problem.find('\n'), std::string::npos);
    EXPECT_NE(plugin.problem.find("/nonexistent/lib/librt_oiio.so"), std::string::npos);
    EXPECT_NE(plugin.problem.find("RT_OIIO_PLUGIN"), std::string::npos);
    EXPECT_NE(plugin.problem.find("rt_oiio"), std::string::npos);
}

}  // namespace
}  // namespace rt
