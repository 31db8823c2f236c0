// The shading driver of the "shaded" render mode: which stage function runs when.
//
//   direct light          stage 03 direct_light, always
//   shadows               stage 04 light_transmittance, only if scene.features.shadows
//   reflection/refraction stage 05 secondary_rays, only while depth < scene.max_depth and the
//                         material hit reflects or transmits
//
// So a scene only runs the stages it needs, and a stage's tests pass with later stages stubbed.
// Optionally records the ray tree of the pixel (the --debug-pixel debugger).
#pragma once

#include <vector>

#include "geometry/offset.h"
#include "scene/scene.h"

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

// The colour seen along `ray` at recursion depth `depth` (0 for camera rays). Fills `node` (if
// given) with the ray tree below this ray, `weight` being the ray's weight in the pixel.
Color trace_ray(const Scene& scene, const Ray& ray, int depth, RayNode* node = nullptr,
                const Color& weight = Color(1));

// The shaded colour of pixel (x, y) (one ray through its centre), linear RGB.
Color shade_pixel(const Scene& scene, int x, int y, RayNode* tree = nullptr);

const char* to_string(RayNode::Kind kind);

}  // namespace rt
