// The accuracy lab's stage 10 rows (docs/accuracy.md, "Sampling: error against samples"): each
// Monte Carlo scene of stage 10 rendered with 1 to 256 samples per pixel, timed, and compared
// with a 1024-sample render of another seed, by RMSE and by the grader's block metric. The
// measuring function renders with the reference solution, so it lives in rt_sampling_bench (it
// links student code); the rows are plain data, which the report writers (rt_accuracy) print.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace rt {
struct Image8;  // image/image.h
}  // namespace rt

namespace rt::bench {

struct SamplingPoint {
    std::string scene;
    int spp = 1;
    double ms = 0;             // the render, all threads
    double rmse = 0;           // 8-bit sRGB units against the reference
    double block_percent = 0;  // pixels in failing 8x8 blocks (tolerance 6), as the grader
};

struct SamplingSeries {
    std::vector<SamplingPoint> points;
    int width = 0, height = 0, reference_spp = 0, threads = 0;
};

// The least-squares slope of log(RMSE) against log(spp) of one scene's points (-0.5 expected;
// in rt_accuracy, report_data.cpp, with the report writers that print it).
double rmse_slope(const std::vector<SamplingPoint>& points, const std::string& scene);

// The root mean square difference of two images of one size, in 8-bit units (rt_sampling_bench).
double rmse8(const Image8& a, const Image8& b);

// Renders stages/10-sampling/scenes/*.json at width x height (rt_sampling_bench).
SamplingSeries measure_sampling_error(int width, int height, int reference_spp,
                                      const std::function<void(const std::string&)>& progress);

}  // namespace rt::bench
