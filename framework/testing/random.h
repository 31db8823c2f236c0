// Seeded random numbers for tests and benchmarks: a fixed-seed 64-bit Mersenne twister, mapped
// by hand. std::mt19937_64's sequence is fixed by the standard, but the standard distributions
// differ between library implementations; this mapping does not, so every machine sees the same
// numbers. Used by the exact reference cases (testing/exact_*), the accuracy lab (tools/bench)
// and every stage test that draws random cases.
#pragma once

#include <cstdint>
#include <random>

#include "core/ray.h"

namespace rt::testing {

struct Random {
    std::mt19937_64 engine;
    explicit Random(std::uint64_t seed) : engine(seed) {}
    // Uniform in [lo, hi), computed in double: the top 53 bits as a fraction.
    double uniform(double lo, double hi) {
        return lo + (hi - lo) * double(engine() >> 11) * 0x1p-53;
    }
    int integer(int lo, int hi) { return lo + int(engine() % std::uint64_t(hi - lo + 1)); }
    // A point in [lo, hi)^3 (x, then y, then z), each coordinate rounded to Real.
    Vec3 vec(double lo, double hi) {
        const double x = uniform(lo, hi), y = uniform(lo, hi), z = uniform(lo, hi);
        return Vec3(Real(x), Real(y), Real(z));
    }
    // A unit vector: points in the unit ball (not too near its centre), normalised.
    Vec3 unit() {
        for (;;) {
            const Vec3 v = vec(-1, 1);
            const Real l = glm::length(v);
            if (l > Real(0.1) && l <= 1) return v / l;
        }
    }
};

}  // namespace rt::testing
