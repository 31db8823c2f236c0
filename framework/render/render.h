// The parallel render loop (docs/conventions.md#pixels-and-determinism).
//
// Pixels are independent: each is computed from the scene alone, by exactly the same arithmetic
// whatever thread computes it, so the image is bit-identical for any thread count and any run.
#pragma once

#include <atomic>
#include <vector>

#include "image/image.h"
#include "scene/prepared_scene.h"

namespace rt {

struct RenderOptions {
    int threads = 0;             // 0: all cores
    bool show_progress = false;  // a progress bar with ETA on stdout
    int tile_size = 16;
    // When set (by the viewer, restarting on a change), tiles not yet started are skipped and
    // the image returned is incomplete: the caller drops it. Pixels done are unchanged.
    const std::atomic<bool>* cancel = nullptr;
};

// Renders the scene in `mode` (scene.mode unless the caller overrides it).
// Debug modes (directions, normals, depth, primitive) store the visualised value so that the PNG
// holds it directly: 8-bit value = round(255 * value).
// A pixel whose computation reached a stub (RT_NOT_IMPLEMENTED) is painted magenta.
Image render(const PreparedScene& scene, RenderMode mode, const RenderOptions& options = {});

// The number of threads `threads` means (0 → hardware concurrency, at least 1).
int resolve_thread_count(int threads);

// The last pass of two debug views over a value per pixel, shared by render() and render_gpu()
// (render/gpu/gpu_render.h): hit distances (< 0: none) to grey, near white and far 20 % grey; BVH
// node visits to a heat ramp over 0 .. the image's most. Magenta (stub) pixels stay.
void map_depth(const std::vector<Real>& depth, Image& image);
void map_visits(const std::vector<Real>& visits, Image& image);

}  // namespace rt
