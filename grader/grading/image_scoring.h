// The grader's image scoring and how it reads a render (image_scoring.cpp).
#pragma once

#include <filesystem>
#include <string>

#include "course/manifest.h"
#include "image/compare.h"
#include "image/image.h"

namespace rt::grader {

// The grader's image scoring (docs/grading.md, "Image scoring"), shared by grading and
// `rt-grade compare` (calibration).
struct ImageScore {
    double fraction = 0;  // of the scene's points
    double ssim = 0;      // reported, never graded
    CompareResult compare;
    std::string metrics;  // one line for the report
};
ImageScore score_image(const Image8& actual, const Image8& reference, const ImageThresholds& th);

// Reads a rendered EXR (linear) as the grader does; NaN or infinite pixels fail with `why`.
bool read_render(const std::filesystem::path& file, Image& image, std::string& why);

}  // namespace rt::grader
