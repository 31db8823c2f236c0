// Stage 10: distribution ray tracing, part 1: turning uniform numbers into the distributions a
// camera needs. Handout: stages/10-sampling/README.md. Conventions: docs/conventions.md#sampling
//
// You edit only this file and lights.cpp. Tests: ctest --test-dir build -L stage10
// The contracts are in framework/stage_api/stage10.h. Every u is uniform in [0, 1): the
// framework draws it; your functions only warp it.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/not_implemented.h"
#include "stage_api/stage10.h"

namespace rt {

// Sample `index` of `count`, jittered inside its cell of an n x n grid.
Vec2 stratified_sample(int index, int count, Vec2 u) {
    // BEGIN SOLUTION
    int n = std::max(1, int(std::sqrt(double(std::max(count, 1)))));
    while ((n + 1) * (n + 1) <= count) ++n;  // sqrt may round below a perfect square
    while (n * n > count && n > 1) --n;
    if (index < 0 || index >= n * n) return u;
    const Vec2 cell(Real(index % n), Real(index / n));
    return (cell + u) / Real(n);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#1-pixel-samples-and-filters");
    // (void)index, (void)count;
    // return u;
    // END SOLUTION
}

Vec2 box_filter_offset(Vec2 u) {
    // BEGIN SOLUTION
    return u - Vec2(0.5);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#1-pixel-samples-and-filters");
    // (void)u;
    // return Vec2(0);
    // END SOLUTION
}

// The tent's inverse cumulative distribution, one axis at a time.
Vec2 tent_filter_offset(Vec2 u) {
    // BEGIN SOLUTION
    const auto tent = [](Real x) {
        return x < Real(0.5) ? std::sqrt(2 * x) - 1 : 1 - std::sqrt(2 - 2 * x);
    };
    return Vec2(tent(u.x), tent(u.y));
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#1-pixel-samples-and-filters");
    // (void)u;
    // return Vec2(0);
    // END SOLUTION
}

Vec2 sample_uniform_disk(Vec2 u) {
    // BEGIN SOLUTION
    // Polar mapping: r = sqrt(u.x) makes the area below r grow as r^2, as it must.
    const Real r = std::sqrt(u.x), phi = 2 * std::numbers::pi_v<Real> * u.y;
    return Vec2(r * std::cos(phi), r * std::sin(phi));
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#2-disk-hemisphere-and-sphere");
    // (void)u;
    // return Vec2(0);
    // END SOLUTION
}

Vec3 sample_cosine_hemisphere(Vec2 u) {
    // BEGIN SOLUTION
    // Malley's method: points uniform on the disk, lifted onto the hemisphere.
    const Vec2 d = sample_uniform_disk(u);
    return Vec3(d.x, d.y, std::sqrt(std::max(Real(0), 1 - d.x * d.x - d.y * d.y)));
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#2-disk-hemisphere-and-sphere");
    // (void)u;
    // return Vec3(0, 0, 1);
    // END SOLUTION
}

Real cosine_hemisphere_pdf(const Vec3& direction) {
    // BEGIN SOLUTION
    return direction.z > 0 ? direction.z / std::numbers::pi_v<Real> : Real(0);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#2-disk-hemisphere-and-sphere");
    // (void)direction;
    // return 0;
    // END SOLUTION
}

Vec3 sample_uniform_sphere(Vec2 u) {
    // BEGIN SOLUTION
    // z uniform in [-1, 1] (Archimedes: equal heights, equal areas), then a longitude.
    const Real z = 1 - 2 * u.x, r = std::sqrt(std::max(Real(0), 1 - z * z));
    const Real phi = 2 * std::numbers::pi_v<Real> * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#2-disk-hemisphere-and-sphere");
    // (void)u;
    // return Vec3(0, 0, 1);
    // END SOLUTION
}

// Every lens point sees the point of the plane in focus that the pinhole ray sees.
Ray thin_lens_ray(const Camera& camera, const Ray& pinhole, Real aperture, Real focus_distance,
                  Vec2 u) {
    // BEGIN SOLUTION
    const Real along_view = glm::dot(pinhole.direction, -camera.w);
    const Vec3 focus = pinhole.origin + pinhole.direction * (focus_distance / along_view);
    const Vec2 d = sample_uniform_disk(u) * (aperture / 2);
    const Vec3 lens = camera.eye + d.x * camera.u + d.y * camera.v;
    return Ray{lens, glm::normalize(focus - lens)};
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#3-depth-of-field-and-motion-blur");
    // (void)camera, (void)aperture, (void)focus_distance, (void)u;
    // return pinhole;
    // END SOLUTION
}

Real shutter_time(Real open, Real close, Real u) {
    // BEGIN SOLUTION
    return open + u * (close - open);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#3-depth-of-field-and-motion-blur");
    // (void)close, (void)u;
    // return open;
    // END SOLUTION
}

// Optional (fog): invert the cumulative distribution 1 - exp(-sigma_t s).
Real sample_free_flight(Real sigma_t, Real u) {
    // BEGIN SOLUTION
    // log1p(-u) keeps the digits of small u; u < 1, so the log is finite.
    return -std::log1p(-u) / sigma_t;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/10-sampling/README.md#optional-fog");
    // (void)sigma_t, (void)u;
    // return 0;
    // END SOLUTION
}

}  // namespace rt
