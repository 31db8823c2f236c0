#include "render/render.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/not_implemented.h"
#include "core/parallel_for.h"
#include "render/accelerate.h"
#include "render/camera_ray.h"
#include "render/nearest_hit.h"
#include "render/progress.h"
#include "render/shade.h"
#include "stage_api/stage02.h"

namespace rt {
namespace {

const Color kStubColor{1, 0, 1};  // magenta: a stub was reached for this pixel

// Debug visualisations are display values: store them so that the sRGB encoding at write time
// gives back exactly the visualised value.
Color display_value(Color value) {
    return Color(srgb_to_linear(value.r), srgb_to_linear(value.g), srgb_to_linear(value.b));
}

Color unit_vector_color(const Vec3& v) {
    return Color(Real(0.5) * (v + Vec3(1)));
}

// A stable, well-spread colour per primitive id (an integer hash, not a random generator, so
// the image is identical on every machine).
Color primitive_color(int id) {
    std::uint32_t h = std::uint32_t(id + 1) * 2654435761u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    return Color(float(h & 255), float((h >> 8) & 255), float((h >> 16) & 255)) / 255.0f * 0.8f +
           0.2f;
}

// Per pixel: the visualised colour, or a number that is mapped to grey once the whole image is
// known (map_depth, map_visits): the hit distance in the depth mode, the BVH nodes visited in the
// BVH-visits mode.
struct PixelResult {
    Color color{0};
    Real measure = -1;  // < 0: nothing to map (a miss)
};

PixelResult render_pixel(const PreparedScene& scene, RenderMode mode, int x, int y) {
    PixelResult out;
    if (mode == RenderMode::Shaded) {
        out.color = shade_pixel(scene, x, y);
        return out;
    }
    const Ray ray =
        camera_ray(scene.camera, Vec2(Real(x) + Real(0.5), Real(y) + Real(0.5)), scene.image);
    if (mode == RenderMode::Directions) {
        if (all_finite(ray.direction)) out.color = display_value(unit_vector_color(ray.direction));
        return out;
    }
    Hit hit;
    if (mode == RenderMode::BvhVisits) {  // the count is mapped at the end
        if (!uses_bvh(scene)) {           // a stubbed build_bvh: magenta, like any stub
            count_missing_bvh();
            return out;
        }
        BvhStats stats;
        bvh_intersect_nearest(scene, ray, Interval{0, kInfinity}, hit, &stats);
        out.measure = Real(stats.nodes_visited);
        return out;
    }
    if (!nearest_hit(scene, ray, Interval{0, kInfinity}, hit)) return out;
    switch (mode) {
        case RenderMode::Normals:
            out.color = display_value(unit_vector_color(hit.normal));
            break;
        case RenderMode::Depth:
            out.measure = hit.t;
            break;
        case RenderMode::PrimitiveId:
            out.color = display_value(primitive_color(scene.is_primitive(hit.primitive)
                                                          ? int(scene.primitive_rank(hit.primitive))
                                                          : hit.primitive));
            break;
        default:
            break;
    }
    return out;
}

}  // namespace

// Depth: near hits white, far hits dark grey, misses black; the range is the image's own
// [nearest, farthest] hit, a deterministic reduction over all pixels.
void map_depth(const std::vector<Real>& depth, Image& image) {
    Real near = kInfinity, far = 0;
    for (Real d : depth) {
        if (d >= 0) {
            near = std::min(near, d);
            far = std::max(far, d);
        }
    }
    const Real span = far > near ? far - near : Real(1);
    for (std::size_t i = 0; i < depth.size(); ++i) {
        if (depth[i] < 0 || image.pixels[i] == kStubColor) continue;
        const float grey = float(1 - Real(0.8) * (depth[i] - near) / span);
        image.pixels[i] = display_value(Color(grey));
    }
}

namespace {

// A heat ramp from black through purple, red and orange to pale yellow (the shape of the
// "inferno" colour map, in five hand-picked stops: dark is cheap, bright is expensive).
Color heat_color(float v) {
    static const Color stops[] = {{0.0f, 0.0f, 0.02f},
                                  {0.34f, 0.06f, 0.43f},
                                  {0.73f, 0.21f, 0.33f},
                                  {0.97f, 0.56f, 0.04f},
                                  {0.99f, 1.0f, 0.64f}};
    v = std::clamp(v, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(3, int(v));
    return glm::mix(stops[i], stops[i + 1], v - float(i));
}

}  // namespace

// BVH node visits: 0 .. the image's largest count mapped onto the heat ramp (a deterministic
// reduction over all pixels, like the depth mode).
void map_visits(const std::vector<Real>& visits, Image& image) {
    Real most = 1;
    for (Real v : visits) most = std::max(most, v);
    for (std::size_t i = 0; i < visits.size(); ++i) {
        if (visits[i] < 0 || image.pixels[i] == kStubColor) continue;
        image.pixels[i] = display_value(heat_color(float(visits[i] / most)));
    }
}

int resolve_thread_count(int threads) {
    if (threads > 0) return threads;
    return default_thread_count();
}

Image render(const PreparedScene& scene, RenderMode mode, const RenderOptions& options) {
    if (mode == RenderMode::BvhVisits && scene.accelerator != Accelerator::Bvh)
        throw std::runtime_error(
            scene.source +
            ": mode \"bvh_visits\" draws the scene's BVH, and it has none; add "
            "\"accelerator\": \"bvh\" to \"render\" or pass --accelerator bvh (if it has that, the "
            "message above says why its tree was dropped)");
    const int width = scene.image.width, height = scene.image.height;
    Image image(width, height);
    std::vector<Real> measures(std::size_t(width) * height, -1);
    const int tile = std::max(1, options.tile_size);
    const int tiles_x = (width + tile - 1) / tile, tiles_y = (height + tile - 1) / tile;
    const int tile_count = tiles_x * tiles_y;
    ProgressBar progress(tile_count, options.show_progress);

    // Threads take tiles in order from a shared counter (core/parallel_for.h).
    parallel_for(std::size_t(tile_count), resolve_thread_count(options.threads),
                 [&](std::size_t i) {
                     if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return;
                     const int t = int(i);
                     const int x0 = (t % tiles_x) * tile, y0 = (t / tiles_x) * tile;
                     for (int y = y0; y < std::min(y0 + tile, height); ++y)
                         for (int x = x0; x < std::min(x0 + tile, width); ++x) {
                             const std::uint64_t stubs = stub_calls_this_thread();
                             PixelResult p = render_pixel(scene, mode, x, y);
                             const std::size_t i = std::size_t(y) * width + x;
                             if (stub_calls_this_thread() != stubs) p = {kStubColor, -1};
                             image.pixels[i] = p.color;
                             measures[i] = p.measure;
                         }
                     progress.advance();
                 });

    if (mode == RenderMode::Depth) map_depth(measures, image);
    if (mode == RenderMode::BvhVisits) map_visits(measures, image);
    return image;
}

}  // namespace rt
