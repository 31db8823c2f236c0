// Image comparison used by the stage image tests and by the grader: the semantics of
// OpenImageIO's idiff and Blender's render tests. A pixel fails when some channel differs from
// the reference by more than `tolerance` (8-bit sRGB steps); the image passes when at most
// `max_failing_percent` of its pixels fail.
#pragma once

#include <string>

#include "image/image.h"

namespace rt {

struct CompareOptions {
    int tolerance = 2;                 // 8-bit steps a channel may differ (rounding, -O levels)
    double max_failing_percent = 0.1;  // share of pixels allowed past the tolerance
    // Forgive anti-aliased edges: a pixel also passes when some reference pixel in its 3x3
    // neighbourhood is within tolerance.
    bool neighbourhood = false;
    // Noise-aware comparison of Monte Carlo renders (stage 10): > 0 compares the mean linear
    // colour of each `block` x `block` square (the last row and column of blocks may be
    // smaller), re-encoded to 8-bit sRGB steps, instead of single pixels. Two correct renders
    // with different random numbers differ per pixel but hardly in their block means; a biased
    // one (light counted twice, a wrong pdf) shifts whole blocks. A failing block fails all its
    // pixels; `neighbourhood` is ignored.
    int block = 0;
};

struct CompareResult {
    bool size_matches = false;
    int max_difference = 0;  // largest channel difference, 0..255
    long long failing_pixels = 0;
    double failing_percent = 100;
    double mean_abs_difference = 0;  // per channel, in 8-bit steps
    // The mean of (actual - reference) per channel: > 0 the image is brighter than the
    // reference on average, < 0 darker.
    double mean_signed_difference = 0;
    int block = 0;  // the options' block: differences are of block means
    bool passed = false;
    // Black where equal; red where the image is brighter than the reference (the sum of its
    // channels), blue where darker, dim below the tolerance and full where the pixel fails.
    Image8 heat_map;

    std::string summary() const;  // one line for logs and test failures
    // Which way the image is off: "darker than the reference by 2.10 on average", "brighter
    // ...", "as much brighter as darker" (noise, a shifted edge), or "the same as the reference".
    std::string direction() const;
};

CompareResult compare_images(const Image8& actual, const Image8& reference,
                             const CompareOptions& options = {});

}  // namespace rt
