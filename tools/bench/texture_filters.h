// The accuracy lab's texture-filter rows (docs/accuracy.md, "Texture filtering"): nearest,
// bilinear and OpenImageIO's trilinear and anisotropic lookups on a grazing checkerboard floor,
// timed and compared with a 16 x 16 supersampled reference.
#pragma once

#include <string>
#include <vector>

namespace rt::bench {

struct TexturePoint {
    std::string filter;
    double ms = 0;           // lookups of the whole image, one thread
    double rmse = 0;         // 8-bit units against the supersampled reference
    double off_percent = 0;  // pixels whose red differs by more than 2/255 from it
};

// Measures every filter on a width x height view of stage 07's filtering scene. `note` says
// what was left out (OpenImageIO's module missing) or what was not timed (its mip-mapping).
std::vector<TexturePoint> measure_texture_filters(int width, int height, std::string& note);

}  // namespace rt::bench
