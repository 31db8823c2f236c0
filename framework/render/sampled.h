// Distribution ray tracing (stage 10): several camera samples per pixel, each with its own
// random numbers, averaged. Only scenes with Features::sampled() come here (shade_pixel), so
// every other scene renders exactly as before and never calls stage 10 code.
//
// Determinism: the numbers of camera sample s of pixel (x, y) come from a PCG32 generator
// (pcg-cpp) seeded with the scene's seed and the pixel's index, on stream s. They do not depend
// on which thread renders the pixel or in which order, so images are bit-identical for any
// thread count and any run; a sample's numbers are drawn in the fixed order of the shading
// loop (docs/conventions.md#sampling).
#pragma once

#include <cstdint>

#include "core/sample_stream.h"
#include "scene/prepared_scene.h"

namespace rt {

class TraceObserver;  // render/shade.h

// Camera sample `sample` of pixel (x, y): the jittered, filtered image point, the thin-lens ray
// and the shutter time, traced (linear RGB). `observer`, if given, sees its ray tree.
Color sample_pixel(const PreparedScene& scene, int x, int y, int sample,
                   TraceObserver* observer = nullptr);

// The mean of the pixel's scene.sampling.samples_per_pixel samples, summed in sample order.
Color shade_sampled_pixel(const PreparedScene& scene, int x, int y);

}  // namespace rt
