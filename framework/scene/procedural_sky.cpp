#include "scene/procedural_sky.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rt {

namespace {

constexpr double kPiD = std::numbers::pi;

}  // namespace

Vec3 latlong_direction(Real u, Real v) {
    const Real phi = 2 * std::numbers::pi_v<Real> * (u - Real(0.5));
    const Real theta = std::numbers::pi_v<Real> * v;
    return Vec3(-std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
}

Color sky_radiance(const SkyParameters& sky, const Vec3& d) {
    Color c = sky.ground;
    if (d.y >= 0) {
        // Most of the sky stays near the horizon colour; the zenith's deep blue shows high up.
        const float t = std::sqrt(float(d.y));
        c = sky.horizon * (1 - t) + sky.zenith * t;
    }
    const double cos_radius = std::cos(double(sky.sun_radius_degrees) * kPiD / 180);
    if (sky.sun_radius_degrees > 0 &&
        double(glm::dot(d, glm::normalize(sky.sun_direction))) >= cos_radius)
        c = sky.sun;
    return c;
}

Image bake_sky(const SkyParameters& sky) {
    const int h = sky.height, w = 2 * h;
    Image image(w, h);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const Vec3 d =
                latlong_direction((Real(i) + Real(0.5)) / Real(w), (Real(j) + Real(0.5)) / Real(h));
            image.at(i, j) = sky_radiance(sky, d);
        }
    return image;
}

Color mean_environment_radiance(const Scene& scene) {
    const Environment& env = scene.environment;
    double sum[3] = {0, 0, 0}, weights = 0;
    const auto add = [&](const TextureView& view, int i, int j, double weight) {
        const Color c = view.stored(i, j);
        for (int k = 0; k < 3; ++k) sum[k] += weight * double(c[k]);
        weights += weight;
    };
    if (env.kind == EnvironmentKind::LatLong) {
        // A row at polar angle theta covers a band of solid angle proportional to sin(theta).
        const TextureView view = scene.texture_view(std::size_t(env.image), false);
        for (int j = 0; j < view.height; ++j) {
            const double weight = std::sin(kPiD * (j + 0.5) / view.height);
            for (int i = 0; i < view.width; ++i) add(view, i, j, weight);
        }
    } else if (env.kind == EnvironmentKind::CubeMap) {
        // A face texel at (s, t) in [-1, 1]^2 subtends a solid angle proportional to
        // (1 + s^2 + t^2)^(-3/2).
        for (int f = 0; f < kCubeFaces; ++f) {
            const TextureView view = scene.texture_view(std::size_t(env.faces[f]), false);
            for (int j = 0; j < view.height; ++j)
                for (int i = 0; i < view.width; ++i) {
                    const double s = 2 * (i + 0.5) / view.width - 1;
                    const double t = 2 * (j + 0.5) / view.height - 1;
                    add(view, i, j, std::pow(1 + s * s + t * t, -1.5));
                }
        }
    }
    if (weights == 0) return Color(0);
    return Color(float(sum[0] / weights), float(sum[1] / weights), float(sum[2] / weights)) *
           env.intensity;
}

}  // namespace rt
