// The shading driver of the "shaded" render mode: which stage function runs when.
//
//   direct light          stage 03 direct_light, always
//   shadows               stage 04 light_transmittance, only if scene.features.shadows
//   reflection/refraction stage 05 secondary_rays, only while depth < scene.max_depth and the
//                         material hit reflects or transmits
//   sampled effects       stage 10 (area lights, glossy, ambient occlusion, indirect light,
//                         lens, shutter), only if scene.features.sampled() (render/sampled.h)
//
// So a scene only runs the stages it needs, and a stage's tests pass with later stages stubbed.
// Optionally records the ray tree of the pixel (the --debug-pixel debugger).
#pragma once

#include <vector>

#include "scene/prepared_scene.h"
#include "scene/surface_point.h"
#include "stage_api/stage03.h"

namespace rt {

struct ShadowRecord {
    std::size_t light = 0;
    Ray ray;  // as shadow_ray (stage 04) builds it
    Interval t_range;
    Color transmittance{1};  // light_transmittance (stage 04)
    int blocked_by = -1;     // the first surface the shadow ray meets (primitive id), or -1
    Real blocked_t = kInfinity;
};

// One ray of a pixel's ray tree.
struct RayNode {
    enum class Kind { Camera, Reflection, Refraction };
    Kind kind = Kind::Camera;
    int depth = 0;
    Ray ray;
    Color ray_weight{1};  // k_r or k_t of this ray at its parent (1 for the camera ray)
    Color weight{1};      // product of ray_weight from the camera ray down to this ray
    bool hit = false;
    Hit hit_record;
    SurfacePoint surface;
    Color local{0};         // direct light at the hit, or the background on a miss
    Color contribution{0};  // weight * local: this node's share of the pixel
    std::vector<ShadowRecord> shadows;
    std::vector<RayNode> children;
};

// Watches the shading loop (the ray-tree debugger). The loop calls it and never depends on what
// it does, so light transport reads the same with or without it (and a shader has none).
class TraceObserver {
  public:
    virtual ~TraceObserver() = default;
    // A ray starts: its weight at its parent (1 for the camera ray) and in the pixel.
    virtual void begin_ray(RayNode::Kind kind, int depth, const Ray& ray, const Color& ray_weight,
                           const Color& weight) = 0;
    virtual void miss(const Color& background) = 0;
    // Stage 04's answer for one light at `at`, as direct light asked for it.
    virtual void shadow(const SurfacePoint& at, std::size_t light, const LightSample& sample,
                        const Color& transmittance) = 0;
    virtual void hit(const Hit& hit, const SurfacePoint& at, const Color& local) = 0;
    virtual void end_ray() = 0;
};

// The deepest bounce the loop's fixed stack holds: the scene's max_depth limit.
inline constexpr int kMaxTraceDepth = kMaxDepthLimit;

// The colour seen along `ray`, a camera ray at depth `depth` (0 for camera rays): an explicit
// loop over a fixed stack of frames {ray, depth, weight, colour so far, next branch}, which adds
// each reflected/refracted colour to its parent in the order recursion would (so images are
// bit-identical to the recursive form) and which a GLSL shader can mirror line for line.
// Fills `node` (if given) with the ray tree below this ray, `weight` being the ray's weight in
// the pixel.
Color trace_ray(const PreparedScene& scene, const Ray& ray, int depth = 0, RayNode* node = nullptr,
                const Color& weight = Color(1));
// The same loop reporting to any observer.
Color trace_ray(const PreparedScene& scene, const Ray& ray, int depth, const Color& weight,
                TraceObserver* observer);

class SampleStream;  // render/sampled.h

// One camera sample's ray with stage 10's sampled terms, drawing from `stream`
// (render/sampled.h; only for scenes with Features::sampled()).
Color trace_sample(const PreparedScene& scene, const Ray& ray, SampleStream& stream,
                   TraceObserver* observer = nullptr);

// The shaded colour of pixel (x, y), linear RGB: one ray through its centre, or for a scene
// with stage 10 features the mean of its samples (render/sampled.h).
Color shade_pixel(const PreparedScene& scene, int x, int y, RayNode* tree = nullptr);

const char* to_string(RayNode::Kind kind);

}  // namespace rt
