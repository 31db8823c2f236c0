// Stage 10 tests of the optional fog (sampling.cpp's sample_free_flight, lights.cpp's
// medium_transmittance and sample_fog): free-flight distances against their density by a
// chi-square test (statistics.h), the transmittance against Beer-Lambert's exp(-sigma_t d), the
// chance that a ray passes a slab of fog against that transmittance (a t-test), and a whole
// pixel seen through a slab of fog, without light and with a point light in it.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "remote/call_each.h"
#include "render/prepare.h"
#include "render/sampled.h"
#include "scene/scene_loader.h"
#include "stage_api/stage10.h"
#include "statistics.h"
#include "testing/stage_test.h"

namespace rt {
namespace fog_test {
namespace {

using stats::kSamples;

constexpr const char* kReadFog = "read stages/10-sampling/README.md#optional-fog";

Medium fog_slab(Real density) {  // fog in the slab 1 <= z <= 3, unbounded across it
    Medium m;
    m.density = density;
    m.bounded = true;
    m.min = Vec3(-1e6, -1e6, 1);
    m.max = Vec3(1e6, 1e6, 3);
    return m;
}

RT_TEST_SUITE(Fog, "optional-fog");

TEST_F(Fog, FreeFlightDistancesFollowTheirDensity) {
    // Bins of equal probability under sigma exp(-sigma s): the cumulative distribution
    // 1 - exp(-sigma s) of a correct sample is uniform in [0, 1).
    constexpr int kBins = 50;
    stats::Uniform random(21);
    for (const double sigma : {0.7, 25.0}) {
        std::vector<double> observed(kBins, 0);
        const auto distances = testing::call_for<&sample_free_flight>(
            kSamples, [&](int) { return std::tuple(Real(sigma), random.next()); });
        for (const double s : distances) {
            ASSERT_TRUE(std::isfinite(s) && s >= 0)
                << "sample_free_flight(" << sigma << ", u) = " << s
                << ": a distance is finite and >= 0 for u in [0, 1); " << kReadFog;
            const double cdf = -std::expm1(-sigma * s);
            observed[std::size_t(std::clamp(int(cdf * kBins), 0, kBins - 1))] += 1;
        }
        stats::expect_chi_square(observed, std::vector<double>(kBins, double(kSamples) / kBins),
                                 "sample_free_flight with sigma_t " + std::to_string(sigma) +
                                     " against sigma_t exp(-sigma_t s); " + kReadFog);
    }
}

TEST_F(Fog, TransmittanceIsBeerLambert) {
    const Real sigma = Real(0.8);
    Medium everywhere;
    everywhere.density = sigma;
    // Direction of length 2: t from 0.5 to 2.5 is a distance of 4.
    const Ray ray{Vec3(0, 0, 0), Vec3(0, 0, 2)};
    EXPECT_NEAR(medium_transmittance(everywhere, ray, Interval{0.5f, 2.5f}), std::exp(-0.8 * 4),
                1e-5)
        << "fog everywhere, a distance of 4 (t from 0.5 to 2.5, |d| = 2): exp(-sigma_t d); "
        << kReadFog;
    // The slab 1 <= z <= 3: t from 0.5 to 1.5 inside it, a distance of 2, whatever the range
    // outside it; a range that ends halfway through counts half.
    const Medium slab = fog_slab(sigma);
    EXPECT_NEAR(medium_transmittance(slab, ray, Interval{0, kInfinity}), std::exp(-0.8 * 2), 1e-5)
        << "only the part inside the fog's box counts; " << kReadFog;
    EXPECT_NEAR(medium_transmittance(slab, ray, Interval{0, 1}), std::exp(-0.8 * 1), 1e-5)
        << "a range that ends inside the box: only up to its end; " << kReadFog;
    EXPECT_EQ(medium_transmittance(slab, Ray{Vec3(0, 0, 5), Vec3(0, 0, 1)}, Interval{}), 1)
        << "a ray that never enters the fog passes it all; " << kReadFog;
    EXPECT_EQ(medium_transmittance(slab, ray, Interval{0, 0.25f}), 1)
        << "a range that ends before the fog: 1; " << kReadFog;
}

TEST_F(Fog, RaysPassASlabWithTheTransmittanceAndScatterInside) {
    // A ray crossing the slab (distance 2 through it, aimed obliquely so |d| != 1) with nothing
    // behind: it passes with probability exp(-2 sigma), else it scatters inside the slab.
    const Real sigma = Real(0.6);
    const Medium slab = fog_slab(sigma);
    const Ray ray{Vec3(0.3f, -0.2f, 0), Vec3(0.5f, 0.25f, 1.5f)};
    const double through = std::sqrt(0.25 + 0.0625 + 2.25) / 1.5 * 2;  // path length in it
    stats::Uniform random(22);
    std::vector<double> passed;
    const auto events = testing::call_for<&sample_fog>(
        kSamples, [&](int) { return std::tuple(slab, ray, kInfinity, random.next()); });
    for (const FogEvent& event : events) {
        passed.push_back(event.scattered ? 0 : 1);
        if (event.scattered) {
            const double z = ray.origin.z + event.t * ray.direction.z;
            ASSERT_TRUE(z >= 1 - 1e-5 && z <= 3 + 1e-5)
                << "scattered at z = " << z << ", outside the fog (1 <= z <= 3); " << kReadFog;
        }
    }
    stats::expect_mean(passed, std::exp(-double(sigma) * through),
                       std::string("the fraction of rays that pass the slab of fog, against "
                                   "exp(-sigma_t d); ") +
                           kReadFog);
    // A surface inside the slab stops the flight: the ray can only scatter before it.
    for (int i = 0; i < 1000; ++i) {
        const FogEvent event = sample_fog(slab, ray, Real(1), random.next());
        if (!event.scattered) continue;
        ASSERT_LT(event.t, 1) << "scattered behind the surface at t = 1; " << kReadFog;
    }
}

TEST_F(Fog, PixelThroughAFogSlabDimsTheBackground) {
    // No lights: nothing is scattered towards the camera, and a pixel is the white background
    // times the chance of passing the slab, exp(-sigma_t 2) (the camera looks along -z through
    // the slab -3 <= z <= -1).
    const PreparedScene scene = prepare_scene(parse_scene(R"({
  "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1], "fov": 0.5},
  "image": {"width": 1, "height": 1},
  "render": {"mode": "shaded", "samples_per_pixel": 1, "seed": 9},
  "background": [1, 1, 1],
  "fog": {"density": 0.4, "min": [-100, -100, -3], "max": [100, 100, -1]}
})",
                                                          "fog_slab.json", "."));
    ASSERT_TRUE(scene.features.fog);
    std::vector<double> values;
    for (const Color& c : testing::call_for<&sample_pixel>(
             20000, [&](int s) { return std::tuple(std::cref(scene), 0, 0, s, nullptr); }))
        values.push_back(c.r);
    // The pixel's rays are within 0.25 degrees of the axis: their path differs by < 1e-5.
    stats::expect_mean(values, std::exp(-0.4 * 2),
                       std::string("the pixel behind a slab of fog 2 thick; ") + kReadFog);
}

TEST_F(Fog, LightScatteredByASlabMatchesTheIntegral) {
    // A point light (intensity 2, falling off as 1 / r^2) inside the slab -3 <= z <= -1, the
    // camera looking along -z through it at a black background. One scattering at depth t
    // (1 <= t <= 3) sends I / (4 r^2) times the albedo and the light's transmittance exp(-sigma r)
    // towards the camera (r: from (0, 0, -t) to the light, all inside the fog); free flights
    // reach depth t with density sigma exp(-sigma (t - 1)). The pixel is the integral of the
    // product over t, here by Simpson's rule.
    const PreparedScene scene = prepare_scene(parse_scene(R"({
  "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1], "fov": 0.5},
  "image": {"width": 1, "height": 1},
  "render": {"mode": "shaded", "samples_per_pixel": 1, "seed": 10},
  "fog": {"density": 0.4, "albedo": [0.75, 0.75, 0.75], "min": [-100, -100, -3], "max": [100, 100, -1]},
  "lights": [{"type": "point", "position": [0, 1.5, -2], "intensity": [2, 2, 2], "attenuation": [0, 0, 1]}]
})",
                                                          "fog_light.json", "."));
    const double sigma = 0.4, albedo = 0.75, intensity = 2;
    const auto integrand = [&](double t) {
        const double r = std::sqrt(1.5 * 1.5 + (t - 2) * (t - 2));
        return sigma * std::exp(-sigma * (t - 1)) * albedo * intensity / (4 * r * r) *
               std::exp(-sigma * r);
    };
    constexpr int kSteps = 2000;  // even
    double integral = integrand(1) + integrand(3);
    for (int k = 1; k < kSteps; ++k) integral += (k % 2 ? 4 : 2) * integrand(1 + 2.0 * k / kSteps);
    integral *= 2.0 / kSteps / 3;
    std::vector<double> values;
    for (const Color& c : testing::call_for<&sample_pixel>(
             40000, [&](int s) { return std::tuple(std::cref(scene), 0, 0, s, nullptr); }))
        values.push_back(c.g);
    stats::expect_mean(
        values, integral,
        std::string("the light a slab of fog scatters from a point light; ") + kReadFog);
}

}  // namespace
}  // namespace fog_test
}  // namespace rt
