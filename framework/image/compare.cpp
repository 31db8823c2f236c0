#include "image/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace rt {
namespace {

int channel_difference(const std::uint8_t* a, const std::uint8_t* b) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
    return d;
}

// A pixel of the heat map: red where the image is brighter (`signed_sum` of its channels'
// differences > 0), blue where darker; full strength where the pixel fails, else dim with `d`.
void paint_difference(std::uint8_t* heat, double d, double signed_sum, bool fails) {
    const std::uint8_t strength = fails ? 255 : std::uint8_t(std::min(128.0, d * 16));
    heat[signed_sum >= 0 ? 0 : 2] = strength;
}

// The mean linear colour of each block, re-encoded to sRGB on the 0..255 scale.
std::vector<double> block_means(const Image8& image, int block) {
    static const std::vector<double> linear = [] {
        std::vector<double> table(256);
        for (int i = 0; i < 256; ++i) table[std::size_t(i)] = srgb_to_linear(float(i) / 255.0f);
        return table;
    }();
    const int bw = (image.width + block - 1) / block, bh = (image.height + block - 1) / block;
    std::vector<double> means(std::size_t(bw) * bh * 3, 0);
    for (int by = 0; by < bh; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            const int x1 = std::min(image.width, (bx + 1) * block);
            const int y1 = std::min(image.height, (by + 1) * block);
            double sum[3] = {0, 0, 0};
            for (int y = by * block; y < y1; ++y)
                for (int x = bx * block; x < x1; ++x)
                    for (int c = 0; c < 3; ++c) sum[c] += linear[image.at(x, y)[c]];
            const double count = double(x1 - bx * block) * double(y1 - by * block);
            for (int c = 0; c < 3; ++c)
                means[(std::size_t(by) * bw + bx) * 3 + std::size_t(c)] =
                    255.0 * linear_to_srgb(float(sum[c] / count));
        }
    return means;
}

// CompareOptions::block: the same result fields, over block means.
CompareResult compare_block_means(const Image8& actual, const Image8& reference,
                                  const CompareOptions& options, CompareResult result) {
    const int w = actual.width, h = actual.height, block = options.block;
    const int bw = (w + block - 1) / block;
    const std::vector<double> a = block_means(actual, block), r = block_means(reference, block);
    double total = 0, signed_total = 0, largest = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t b = (std::size_t(y / block) * bw + std::size_t(x / block)) * 3;
            double d = 0;
            double signed_sum = 0;
            for (int c = 0; c < 3; ++c) {
                const double dc = a[b + std::size_t(c)] - r[b + std::size_t(c)];
                d = std::max(d, std::abs(dc));
                total += std::abs(dc);
                signed_sum += dc;
            }
            signed_total += signed_sum;
            largest = std::max(largest, d);
            const bool fails = d > options.tolerance;
            if (fails) ++result.failing_pixels;
            paint_difference(result.heat_map.at(x, y), d, signed_sum, fails);
        }
    const double pixels = double(w) * h;
    result.max_difference = int(std::ceil(largest));
    result.failing_percent = 100.0 * double(result.failing_pixels) / pixels;
    result.mean_abs_difference = total / (pixels * 3);
    result.mean_signed_difference = signed_total / (pixels * 3);
    result.passed = result.failing_percent <= options.max_failing_percent;
    return result;
}

}  // namespace

// Off both ways alike when the signed mean is under half the absolute one.
std::string CompareResult::direction() const {
    if (mean_abs_difference == 0) return "the same as the reference";
    if (std::abs(mean_signed_difference) < 0.5 * mean_abs_difference)
        return "as much brighter as darker";
    char words[96];
    std::snprintf(words, sizeof words, "%s than the reference by %.2f on average",
                  mean_signed_difference > 0 ? "brighter" : "darker",
                  std::abs(mean_signed_difference));
    return words;
}

std::string CompareResult::summary() const {
    if (!size_matches) return "image size differs from the reference";
    char line[320];
    std::snprintf(line, sizeof line,
                  "%s: %lld failing pixels (%.3f%%), max channel difference %d, mean %.3f%s; "
                  "yours is %s",
                  passed ? "match" : "MISMATCH", failing_pixels, failing_percent, max_difference,
                  mean_abs_difference,
                  block > 0 ? (" (of the means over " + std::to_string(block) + "x" +
                               std::to_string(block) + " blocks)")
                                  .c_str()
                            : "",
                  direction().c_str());
    return line;
}

CompareResult compare_images(const Image8& actual, const Image8& reference,
                             const CompareOptions& options) {
    CompareResult result;
    if (actual.width != reference.width || actual.height != reference.height || actual.width <= 0 ||
        actual.height <= 0)
        return result;
    result.size_matches = true;
    const int w = actual.width, h = actual.height;
    result.heat_map = Image8{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3, 0)};
    if (options.block > 0) {
        result.block = options.block;
        return compare_block_means(actual, reference, options, std::move(result));
    }
    double total = 0, signed_total = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* a = actual.at(x, y);
            const std::uint8_t* r = reference.at(x, y);
            const int d = channel_difference(a, r);
            int signed_sum = 0;
            for (int c = 0; c < 3; ++c) {
                total += std::abs(int(a[c]) - int(r[c]));
                signed_sum += int(a[c]) - int(r[c]);
            }
            signed_total += signed_sum;
            result.max_difference = std::max(result.max_difference, d);
            bool fails = d > options.tolerance;
            if (fails && options.neighbourhood) {
                for (int dy = -1; dy <= 1 && fails; ++dy)
                    for (int dx = -1; dx <= 1 && fails; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                        fails = channel_difference(a, reference.at(nx, ny)) > options.tolerance;
                    }
            }
            if (fails) ++result.failing_pixels;
            paint_difference(result.heat_map.at(x, y), d, signed_sum, fails);
        }
    }
    const double pixels = double(w) * h;
    result.failing_percent = 100.0 * double(result.failing_pixels) / pixels;
    result.mean_abs_difference = total / (pixels * 3);
    result.mean_signed_difference = signed_total / (pixels * 3);
    result.passed = result.failing_percent <= options.max_failing_percent;
    return result;
}

}  // namespace rt
