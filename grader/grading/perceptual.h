// A perceptual similarity figure reported next to the graded pixel comparison (never graded).
// SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) on the luma of the sRGB-encoded images, with the
// paper's 11x11 Gaussian window (sigma 1.5) and constants K1 = 0.01, K2 = 0.03, L = 255.
#pragma once

#include "image/image.h"

namespace rt::grader {

// Mean SSIM over the valid windows; 1 for identical images. Returns 0 on a size mismatch.
double ssim_luminance(const Image8& a, const Image8& b);

}  // namespace rt::grader
