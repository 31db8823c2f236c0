// The accuracy lab's stage 11 rows (docs/accuracy.md, "Multiple importance sampling"): Veach's
// scene (stages/11-path-tracing/scenes/veach_mis.json), direct light only as in Veach's own
// experiment, with next-event estimation alone, BSDF sampling alone and both combined by MIS, each
// at 1 to 256 samples per pixel, timed and compared with MIS at 2048 samples. The three differ
// only in how a light's contribution is counted; every other step is the reference solution's
// (stage 11's path tracer and bsdf.cpp, stage 10's light sampling, stage 04's shadow test), so the
// curve measures the strategy and nothing else.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/ray.h"
#include "core/real.h"
#include "scene/prepared_scene.h"

namespace rt {
class SampleStream;  // core/sample_stream.h
}  // namespace rt

namespace rt::bench {

enum class LightStrategy {
    Nee,   // lights only by next-event estimation; a BSDF bounce that meets a light adds nothing
    Bsdf,  // lights only when a BSDF bounce meets them; no shadow rays
    Mis,   // both, weighted by the power heuristic: what stage 11's path_radiance computes
};
const char* strategy_name(LightStrategy strategy);

// A scene's direct light (max_depth 1) rendered under one strategy. MIS is stage 11's
// path_radiance on the scene; BSDF sampling alone is path_radiance on the scene with its sphere
// lights made emissive spheres; next-event estimation alone is one light sample at the first
// surface (mis_strategies.cpp).
struct StrategyRenderer {
    StrategyRenderer(const PreparedScene& scene, LightStrategy strategy);
    Color radiance(const Ray& camera_ray, SampleStream& stream) const;  // one camera sample

    PreparedScene scene;  // as the strategy renders it
    LightStrategy strategy;
};

struct MisPoint {
    std::string strategy;
    int spp = 1;
    double ms = 0;    // the render, all threads
    double rmse = 0;  // 8-bit sRGB units against the reference image
};

struct MisSeries {
    std::vector<MisPoint> points;
    int width = 0, height = 0, threads = 0;
    std::string scene;      // relative to the source tree
    int reference_spp = 0;  // the reference: MIS at this many samples, at the scene's own seed
};

// The error the strategy's line would have at `ms` (log-log interpolation between its points; a
// time outside the line's range takes the nearest end's error). -1 without points. In
// rt_accuracy (report_data.cpp), with the report writers that print it; the rest of this header
// is rt_sampling_bench's, which links the reference solution.
double rmse_at_time(const std::vector<MisPoint>& points, const std::string& strategy, double ms);

constexpr int kReferenceSamples = 2048;

// Renders veach_mis at its own size with each strategy at 1, 4, 16, 64 and 256 samples per pixel
// (another seed than the reference's, so their noise is independent).
MisSeries measure_mis_strategies(const std::function<void(const std::string&)>& progress);

}  // namespace rt::bench
