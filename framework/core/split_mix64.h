// splitmix64 (Steele, Lea and Flood 2014): a tiny generator whose output is fixed by its seed, the
// same on every machine (unlike the standard distributions). Used where generated data must be
// reproducible bit for bit: procedural meshes, the BVH benchmark's rays, the seeds of stage 10's
// sample streams (render/sampled.cpp).
#pragma once

#include <cstdint>

namespace rt {

class SplitMix64 {
  public:
    constexpr explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    constexpr std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, 1): the top 53 bits as a fraction.
    constexpr double unit() { return double(next() >> 11) * 0x1.0p-53; }
    constexpr double between(double lo, double hi) { return lo + (hi - lo) * unit(); }

    // The first output of a generator seeded with x: a 64-bit hash of x (a counter-based
    // generator: the numbers of item i depend on (seed, i) only).
    static constexpr std::uint64_t hash(std::uint64_t x) { return SplitMix64(x).next(); }

  private:
    std::uint64_t state_;
};
static_assert(SplitMix64::hash(0) == 0xE220A8397B1DCDAFull);  // the reference implementation's

}  // namespace rt
