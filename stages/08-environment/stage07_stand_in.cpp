// TEMPORARY, until stage 07 (stages/07-textures/textures.cpp) is merged into this branch: a weak
// sample_bilinear to the contract of framework/stage_api/stage07.h, so that stage 08 links.
// Delete this file (and its line in CMakeLists.txt) at the merge; the weak symbol would lose to
// stage 07's definition anyway.
#include <algorithm>
#include <cmath>

#include "stage_api/stage07.h"

namespace rt {

__attribute__((weak)) Color sample_bilinear(const TextureView& image, Vec2 uv, TextureWrap wrap) {
    const double x = double(uv.x) * image.width - 0.5, y = double(uv.y) * image.height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const float fx = float(x - x0), fy = float(y - y0);
    auto index = [wrap](double c, int n) {
        const long long i = (long long)c;
        if (wrap == TextureWrap::Clamp) return int(std::clamp<long long>(i, 0, n - 1));
        return int(((i % n) + n) % n);  // Repeat (Mirror is not used by stage 08)
    };
    const int i = index(x0, image.width), i1 = index(x0 + 1, image.width);
    const int j = index(y0, image.height), j1 = index(y0 + 1, image.height);
    const Color top = (1 - fx) * image.stored(i, j) + fx * image.stored(i1, j);
    const Color bottom = (1 - fx) * image.stored(i, j1) + fx * image.stored(i1, j1);
    return (1 - fy) * top + fy * bottom;
}

}  // namespace rt
