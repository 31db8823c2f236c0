// The random numbers of one camera sample (stage 10's and stage 11's): a PCG32 generator seeded
// with the scene's seed and the pixel, on the stream of the sample number
// (docs/conventions.md#sampling). Used by render/sampled.h and stage_api/stage11.h.
#pragma once

#include <cstdint>
#include <limits>
#include <type_traits>

#include <pcg_random.hpp>

#include "core/real.h"
#include "core/split_mix64.h"

namespace rt {

// A camera sample's random numbers. Stage 11's path_radiance draws from it as long as its path
// lasts; inline, so that the student files and a grading judge, which link no renderer, can use it.
class SampleStream {
  public:
    SampleStream() : SampleStream(0, 0, 0) {}
    // SplitMix64's hash spreads neighbouring pixel indices over the generator's state.
    SampleStream(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample)
        : rng_(SplitMix64::hash(seed ^ SplitMix64::hash(pixel)), sample) {}
    // Uniform in [0, 1): as many random bits as Real holds exactly (24 for float, 32 for
    // double), so next() < 1.
    Real next() {
        constexpr int kBits =
            std::numeric_limits<Real>::digits < 32 ? std::numeric_limits<Real>::digits : 32;
        return Real(rng_() >> (32 - kBits)) * (Real(1) / Real(std::uint64_t(1) << kBits));
    }
    Vec2 next2() {
        const Real a = next();
        return Vec2(a, next());
    }

  private:
    pcg32 rng_;
};
static_assert(std::is_trivially_copyable_v<SampleStream>);  // it crosses to a grading worker

}  // namespace rt
