// Stage 10 tests of sampling.cpp: every warp against its density by a chi-square test
// (statistics.h), and the camera's thin lens and shutter. Any correct technique passes: the
// bins are equal-probability regions of the target density, not positions of a particular
// mapping.
#include <cmath>
#include <numbers>
#include <tuple>
#include <vector>

#include "remote/call_each.h"
#include "stage_api/stage10.h"
#include "statistics.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

using stats::kPi;
using stats::kSamples;

RT_TEST_SUITE(Warps, "2-disk-hemisphere-and-sphere");

// Bins of equal probability for a density that is uniform in (a, phi) with a in [0, 1] and
// phi the angle of (x, y): a = r^2 for the disk, 1 - z^2 for the cosine hemisphere, (1 - z) / 2
// for the sphere.
struct PolarBins {
    static constexpr int kA = 10, kPhi = 12;
    std::vector<double> observed = std::vector<double>(kA * kPhi, 0);
    void add(double a, double x, double y) {
        double phi = std::atan2(y, x);
        if (phi < 0) phi += 2 * kPi;
        const int i = std::clamp(int(a * kA), 0, kA - 1);
        const int j = std::clamp(int(phi / (2 * kPi) * kPhi), 0, kPhi - 1);
        observed[std::size_t(i * kPhi + j)] += 1;
    }
    void check(const std::string& what) const {
        stats::expect_chi_square(
            observed, std::vector<double>(observed.size(), double(kSamples) / (kA * kPhi)), what);
    }
};

TEST_F(Warps, UniformDiskIsUniformInArea) {
    stats::Uniform random(1);
    PolarBins bins;
    const auto samples = testing::call_for<&sample_uniform_disk>(
        kSamples, [&](int) { return std::tuple(random.next2()); });
    for (const Vec2 p : samples) {
        const double r2 = double(p.x) * p.x + double(p.y) * p.y;
        ASSERT_LE(r2, 1 + 1e-5) << "a disk sample outside the unit disk";
        bins.add(r2, p.x, p.y);
    }
    bins.check("sample_uniform_disk");
}

TEST_F(Warps, CosineHemisphereFollowsCosOverPi) {
    stats::Uniform random(2);
    PolarBins bins;
    const auto samples = testing::call_for<&sample_cosine_hemisphere>(
        kSamples, [&](int) { return std::tuple(random.next2()); });
    for (int i = 0; i < kSamples; ++i) {
        const Vec3 d = samples[std::size_t(i)];
        ASSERT_NEAR(glm::length(d), 1, 1e-4) << "not a unit direction";
        ASSERT_GE(d.z, 0) << "below the hemisphere";
        // Under cos / pi the projection onto the disk is uniform: 1 - z^2 = r^2 is uniform.
        bins.add(1 - double(d.z) * d.z, d.x, d.y);
        if (i < 100) {
            EXPECT_NEAR(cosine_hemisphere_pdf(d), d.z / kPi, 1e-5) << "the pdf of a sample";
        }
    }
    bins.check("sample_cosine_hemisphere");
    EXPECT_EQ(cosine_hemisphere_pdf(Vec3(0, 0.6f, -0.8f)), 0) << "pdf below the hemisphere";
}

TEST_F(Warps, UniformSphereIsUniform) {
    stats::Uniform random(3);
    PolarBins bins;
    const auto samples = testing::call_for<&sample_uniform_sphere>(
        kSamples, [&](int) { return std::tuple(random.next2()); });
    for (const Vec3 d : samples) {
        ASSERT_NEAR(glm::length(d), 1, 1e-4) << "not a unit direction";
        bins.add((1 - double(d.z)) / 2, d.x, d.y);  // Archimedes: z is uniform
    }
    bins.check("sample_uniform_sphere");
}

// Offsets binned on a grid over [-extent, extent)^2 against the per-axis density's CDF.
template <auto filter>
void check_filter(double extent, double (*cdf)(double), const char* what) {
    constexpr int kBins = 10;
    std::vector<double> observed(kBins * kBins, 0), expected(kBins * kBins, 0);
    stats::Uniform random(4);
    const auto offsets =
        testing::call_for<filter>(kSamples, [&](int) { return std::tuple(random.next2()); });
    for (const Vec2 o : offsets) {
        ASSERT_TRUE(std::abs(o.x) <= extent && std::abs(o.y) <= extent)
            << what << " gave an offset outside its support: (" << o.x << ", " << o.y << ")";
        const int bx = std::clamp(int((o.x + extent) / (2 * extent) * kBins), 0, kBins - 1);
        const int by = std::clamp(int((o.y + extent) / (2 * extent) * kBins), 0, kBins - 1);
        observed[std::size_t(by * kBins + bx)] += 1;
    }
    for (int by = 0; by < kBins; ++by)
        for (int bx = 0; bx < kBins; ++bx) {
            auto mass = [&](int b) {
                const double lo = -extent + 2 * extent * b / kBins;
                return cdf(lo + 2 * extent / kBins) - cdf(lo);
            };
            expected[std::size_t(by * kBins + bx)] = kSamples * mass(bx) * mass(by);
        }
    stats::expect_chi_square(observed, expected, what);
}

TEST_F(Warps, BoxFilterIsUniformOverThePixel) {
    check_filter<&box_filter_offset>(
        0.5, [](double x) { return x + 0.5; }, "box_filter_offset");
}

TEST_F(Warps, TentFilterFollowsOneMinusAbsX) {
    check_filter<&tent_filter_offset>(
        1, [](double x) { return x < 0 ? (1 + x) * (1 + x) / 2 : 1 - (1 - x) * (1 - x) / 2; },
        "tent_filter_offset");
}

RT_TEST_SUITE(PixelSamples, "1-pixel-samples-and-filters");

TEST_F(PixelSamples, EachSampleOfASquareCountHasItsOwnCell) {
    stats::Uniform random(5);
    for (int count : {1, 4, 9, 16}) {
        const int n = int(std::lround(std::sqrt(count)));
        std::vector<int> hits(std::size_t(count), 0);
        for (int i = 0; i < count; ++i) {
            const Vec2 p = stratified_sample(i, count, random.next2());
            ASSERT_TRUE(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1) << "outside the unit square";
            hits[std::size_t(std::min(n - 1, int(p.y * n)) * n + std::min(n - 1, int(p.x * n)))]++;
        }
        for (int h : hits) EXPECT_EQ(h, 1) << count << " samples: a cell got " << h;
    }
}

// Jittered: over many pixels, the samples of each cell are uniform within it (a sample always
// at the cell's centre, "no jitter", fails here).
TEST_F(PixelSamples, JitterIsUniformWithinEachCell) {
    for (int count : {4, 10}) {  // 10: nine stratified samples and one free one
        constexpr int kSub = 6;
        std::vector<double> observed(kSub * kSub, 0);
        stats::Uniform random(6);
        const int pixels = kSamples / count;
        const auto samples = testing::call_for<&stratified_sample>(
            pixels * count, [&](int k) { return std::tuple(k % count, count, random.next2()); });
        for (const Vec2 s : samples) {
            const int x = std::clamp(int(s.x * kSub), 0, kSub - 1);
            const int y = std::clamp(int(s.y * kSub), 0, kSub - 1);
            observed[std::size_t(y * kSub + x)] += 1;
        }
        stats::expect_chi_square(
            observed, std::vector<double>(observed.size(), double(pixels) * count / (kSub * kSub)),
            "stratified_sample with " + std::to_string(count) + " samples");
        // Within one cell of a 2 x 2 grid (count 4, sample 0): uniform in [0, 0.5)^2.
        if (count != 4) continue;
        std::vector<double> cell(kSub * kSub, 0);
        const auto firsts = testing::call_for<&stratified_sample>(
            kSamples, [&](int) { return std::tuple(0, 4, random.next2()); });
        for (const Vec2 first : firsts) {
            const Vec2 s = first * Real(2);
            ASSERT_TRUE(s.x < 1 && s.y < 1) << "sample 0 of 4 left its cell";
            cell[std::size_t(std::min(kSub - 1, int(s.y * kSub)) * kSub +
                             std::min(kSub - 1, int(s.x * kSub)))] += 1;
        }
        stats::expect_chi_square(cell, std::vector<double>(cell.size(), double(kSamples) / 36),
                                 "sample 0 of 4 within its cell");
    }
}

RT_TEST_SUITE(Lens, "3-depth-of-field-and-motion-blur");

Camera test_camera() {
    return make_look_at_camera(Projection::Perspective, Vec3(0, 1, 5), Vec3(0, 0, 0), Vec3(0, 1, 0),
                               40, 2);
}

TEST_F(Lens, ThinLensRaysMeetInThePlaneInFocus) {
    const Camera camera = test_camera();
    const Real focus = 4, aperture = 0.5f;
    stats::Uniform random(7);
    PolarBins bins;
    std::vector<std::tuple<Camera, Ray, Real, Real, Vec2>> calls;
    for (int i = 0; i < kSamples; ++i) {
        const Vec3 d = glm::normalize(Vec3(random.next() - 0.5f, random.next() - 0.5f, -1));
        const Ray pinhole{camera.eye, camera.u * d.x + camera.v * d.y - camera.w * d.z};
        calls.emplace_back(camera, pinhole, aperture, focus, random.next2());
    }
    const auto rays = testing::call_each<&thin_lens_ray>(calls);
    for (int i = 0; i < kSamples; ++i) {
        const Ray& pinhole = std::get<1>(calls[std::size_t(i)]);
        const Vec3 direction = pinhole.direction;
        const Ray& ray = rays[std::size_t(i)];
        ASSERT_NEAR(glm::length(ray.direction), 1, 1e-4) << "not a unit direction";
        // The lens point: in the lens plane, within the aperture.
        const Vec3 offset = ray.origin - camera.eye;
        ASSERT_NEAR(glm::dot(offset, camera.w), 0, 1e-4) << "the ray does not start on the lens";
        const double x = glm::dot(offset, camera.u) / (aperture / 2);
        const double y = glm::dot(offset, camera.v) / (aperture / 2);
        ASSERT_LE(x * x + y * y, 1 + 1e-4) << "a lens point outside the aperture";
        bins.add(x * x + y * y, x, y);
        // Both rays reach the plane in focus (distance `focus` along -w) at the same point.
        const Vec3 sharp =
            pinhole.origin + pinhole.direction * (focus / glm::dot(direction, -camera.w));
        const Vec3 through = ray.origin + ray.direction * ((focus - glm::dot(offset, -camera.w)) /
                                                           glm::dot(ray.direction, -camera.w));
        ASSERT_NEAR(glm::length(through - sharp), 0, 1e-4) << "the ray misses the point in focus";
    }
    bins.check("thin_lens_ray's lens points (uniform over the aperture)");
}

TEST_F(Lens, ApertureZeroIsThePinhole) {
    const Camera camera = test_camera();
    const Ray pinhole{camera.eye, glm::normalize(Vec3(0.1f, -0.2f, -1))};
    const Ray ray = thin_lens_ray(camera, pinhole, 0, 3, Vec2(0.7f, 0.2f));
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(ray.origin[c], pinhole.origin[c], 1e-6);
        EXPECT_NEAR(ray.direction[c], pinhole.direction[c], 1e-5);
    }
}

TEST_F(Lens, ShutterTimesAreUniform) {
    constexpr int kBins = 20;
    std::vector<double> observed(kBins, 0);
    stats::Uniform random(8);
    const auto times = testing::call_for<&shutter_time>(
        kSamples, [&](int) { return std::tuple(Real(2), Real(3), random.next()); });
    for (const Real t : times) {
        ASSERT_TRUE(t >= 2 && t <= 3) << "a time outside the shutter interval: " << t;
        observed[std::size_t(std::clamp(int((t - 2) * kBins), 0, kBins - 1))] += 1;
    }
    stats::expect_chi_square(observed, std::vector<double>(kBins, double(kSamples) / kBins),
                             "shutter_time");
}

}  // namespace
}  // namespace rt
