// Stage 11's histograms of directions (Nori's warptest): the sphere cut into bins of theta and
// phi, the expected count of each bin the integral of a density over it (a midpoint rule on
// sub-cells), and one more bin for the samples that fail (weight 0: absorbed), expected to hold
// the mass the density leaves out. statistics.h (stage 10) does the chi-square test.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "../../10-sampling/tests/statistics.h"

namespace rt::stats {

struct SphereBins {
    static constexpr int kTheta = 40, kPhi = 24, kSub = 8;
    std::vector<double> observed = std::vector<double>(kTheta * kPhi + 1, 0);

    static std::size_t bin(const Vec3& d) {
        const double theta = std::acos(std::clamp(double(d.z), -1.0, 1.0));
        double phi = std::atan2(double(d.y), double(d.x));
        if (phi < 0) phi += 2 * kPi;
        const int i = std::clamp(int(theta / kPi * kTheta), 0, kTheta - 1);
        const int j = std::clamp(int(phi / (2 * kPi) * kPhi), 0, kPhi - 1);
        return std::size_t(i * kPhi + j);
    }
    void add(const Vec3& d) { observed[bin(d)] += 1; }
    void add_failed() { observed.back() += 1; }

    // The midpoints of the bins' sub-cells, in the order expected() reads their densities.
    static std::vector<Vec3> grid() {
        std::vector<Vec3> g;
        g.reserve(std::size_t(kTheta * kSub * kPhi * kSub));
        for (int i = 0; i < kTheta * kSub; ++i)
            for (int j = 0; j < kPhi * kSub; ++j) g.push_back(direction(i, j));
        return g;
    }

    // The integral of a density over each bin, times `samples`, from its values at grid()'s
    // directions (taken in one call_each: in a grading each call would cross to the worker
    // alone); the last bin gets what is left of 1. `total` receives the integral over the sphere.
    template <class Density>
    static std::vector<double> expected(const std::vector<Density>& density, int samples,
                                        double& total) {
        std::vector<double> e(kTheta * kPhi + 1, 0);
        total = 0;
        std::size_t k = 0;
        for (int i = 0; i < kTheta * kSub; ++i) {
            const double theta = cell_theta(i);
            for (int j = 0; j < kPhi * kSub; ++j) {
                const double mass = double(density.at(k++)) * std::sin(theta) * kDtheta * kDphi;
                e[std::size_t((i / kSub) * kPhi + j / kSub)] += samples * mass;
                total += mass;
            }
        }
        e.back() = std::max(0.0, samples * (1 - total));
        return e;
    }

  private:
    static constexpr double kDtheta = kPi / (kTheta * kSub), kDphi = 2 * kPi / (kPhi * kSub);
    static double cell_theta(int i) { return (i + 0.5) * kDtheta; }
    static Vec3 direction(int i, int j) {
        const double theta = cell_theta(i), phi = (j + 0.5) * kDphi;
        return Vec3(Real(std::sin(theta) * std::cos(phi)), Real(std::sin(theta) * std::sin(phi)),
                    Real(std::cos(theta)));
    }
};

}  // namespace rt::stats
