#include "image/compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace rt {
namespace {

int channel_difference(const std::uint8_t* a, const std::uint8_t* b) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
    return d;
}

}  // namespace

std::string CompareResult::summary() const {
    if (!size_matches) return "image size differs from the reference";
    char line[200];
    std::snprintf(line, sizeof line,
                  "%s: %lld failing pixels (%.3f%%), max channel difference %d, mean %.3f",
                  passed ? "match" : "MISMATCH", failing_pixels, failing_percent, max_difference,
                  mean_abs_difference);
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
    double total = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* a = actual.at(x, y);
            const std::uint8_t* r = reference.at(x, y);
            const int d = channel_difference(a, r);
            for (int c = 0; c < 3; ++c) total += std::abs(int(a[c]) - int(r[c]));
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
            std::uint8_t* heat = result.heat_map.at(x, y);
            if (fails) {
                ++result.failing_pixels;
                heat[0] = heat[1] = heat[2] = 255;
            } else {
                heat[0] = std::uint8_t(std::min(255, d * 32));
            }
        }
    }
    const double pixels = double(w) * h;
    result.failing_percent = 100.0 * double(result.failing_pixels) / pixels;
    result.mean_abs_difference = total / (pixels * 3);
    result.passed = result.failing_percent <= options.max_failing_percent;
    return result;
}

}  // namespace rt
