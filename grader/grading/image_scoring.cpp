// The grader's image scoring (docs/grading.md, "Image scoring") and how it reads a render.
#include "grading/image_scoring.h"

#include <cmath>
#include <cstdio>

#include "grading/perceptual.h"
namespace fs = std::filesystem;

namespace rt::grader {

// Reads the child's EXR after it has exited. NaN or Inf pixels fail the image.
bool read_render(const fs::path& file, Image& image, std::string& why) {
    std::error_code ec;
    const auto st = fs::symlink_status(file, ec);
    if (ec || !fs::is_regular_file(st)) {
        why = "the renderer wrote no image";
        return false;
    }
    try {
        image = read_image(file, Encoding::Data);  // the renderer writes linear EXR
    } catch (const ImageError& e) {
        // Not e.what(): it names the grader's copy; the student needs only what is wrong with it.
        why = "the rendered image: " + e.problem();
        return false;
    }
    if (image.width > 8192 || image.height > 8192) {
        why = "the rendered image has an impossible size";
        return false;
    }
    return true;
}

ImageScore score_image(const Image8& actual, const Image8& reference, const ImageThresholds& th) {
    ImageScore score;
    score.compare = compare_images(actual, reference, th.compare_options());
    if (!score.compare.size_matches) {
        score.metrics = "the image is " + std::to_string(actual.width) + "x" +
                        std::to_string(actual.height) + ", the reference " +
                        std::to_string(reference.width) + "x" + std::to_string(reference.height);
        return score;
    }
    const double failing = score.compare.failing_percent;
    if (failing <= th.pass_percent)
        score.fraction = 1;
    else if (failing < th.fail_percent)
        score.fraction = (th.fail_percent - failing) / (th.fail_percent - th.pass_percent);
    score.ssim = ssim_luminance(actual, reference);
    char line[400];
    const std::string blocks = th.block > 0 ? " in their " + std::to_string(th.block) + "x" +
                                                  std::to_string(th.block) + "-block means"
                                            : "";
    std::snprintf(line, sizeof line,
                  "%.3f%% of the pixels differ%s by more than %d (full points up to %.2f%%, none "
                  "from %.2f%%); max difference %d; yours is %s; SSIM %.4f (reported, not "
                  "graded)",
                  failing, blocks.c_str(), th.tolerance, th.pass_percent, th.fail_percent,
                  score.compare.max_difference, score.compare.direction().c_str(), score.ssim);
    score.metrics = line;
    return score;
}

}  // namespace rt::grader
