#include "grading/perceptual.h"

#include <cmath>
#include <vector>

namespace rt::grader {

double ssim_luminance(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height || a.width <= 0 || a.height <= 0) return 0;
    const int w = a.width, h = a.height;
    auto luma = [](const Image8& im, std::vector<double>& out) {
        out.resize(std::size_t(im.width) * im.height);
        for (std::size_t i = 0; i < out.size(); ++i) {
            const std::uint8_t* p = &im.data[i * 3];
            out[i] = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];  // Rec. 601 luma
        }
    };
    std::vector<double> x, y;
    luma(a, x);
    luma(b, y);
    constexpr int r = 5;  // 11x11 window
    double weights[2 * r + 1];
    double sum = 0;
    for (int i = -r; i <= r; ++i) sum += weights[i + r] = std::exp(-(i * i) / (2 * 1.5 * 1.5));
    for (double& v : weights) v /= sum;
    const double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
    // Images smaller than the window: one window over the whole image (uniform weights).
    const int x0 = std::min(r, w / 2), y0 = std::min(r, h / 2);
    double total = 0;
    long long count = 0;
    for (int cy = y0; cy < h - y0 || (cy == y0 && count == 0); ++cy) {
        for (int cx = x0; cx < w - x0 || (cx == x0 && count == 0); ++cx) {
            double mx = 0, my = 0, sxx = 0, syy = 0, sxy = 0, wsum = 0;
            for (int dy = -r; dy <= r; ++dy) {
                const int yy = cy + dy;
                if (yy < 0 || yy >= h) continue;
                for (int dx = -r; dx <= r; ++dx) {
                    const int xx = cx + dx;
                    if (xx < 0 || xx >= w) continue;
                    const double g = weights[dy + r] * weights[dx + r];
                    const double vx = x[std::size_t(yy) * w + xx], vy = y[std::size_t(yy) * w + xx];
                    wsum += g;
                    mx += g * vx;
                    my += g * vy;
                    sxx += g * vx * vx;
                    syy += g * vy * vy;
                    sxy += g * vx * vy;
                }
            }
            mx /= wsum;
            my /= wsum;
            const double vx = sxx / wsum - mx * mx, vy = syy / wsum - my * my;
            const double cov = sxy / wsum - mx * my;
            total +=
                ((2 * mx * my + c1) * (2 * cov + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
            ++count;
        }
    }
    return count ? total / double(count) : 0;
}

}  // namespace rt::grader
