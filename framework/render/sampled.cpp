#include "render/sampled.h"

#include "render/camera_ray.h"
#include "render/shade.h"
#include "stage_api/stage10.h"

namespace rt {

Color sample_pixel(const PreparedScene& scene, int x, int y, int sample, TraceObserver* observer) {
    const SamplingSettings& settings = scene.sampling;
    SampleStream stream(settings.seed, std::uint64_t(y) * std::uint64_t(scene.image.width) + x,
                        std::uint64_t(sample));
    const Vec2 jitter = stratified_sample(sample, settings.samples_per_pixel, stream.next2());
    const Vec2 offset = settings.filter == PixelFilter::Tent ? tent_filter_offset(jitter)
                                                             : box_filter_offset(jitter);
    Ray ray = camera_ray(scene.camera, Vec2(Real(x) + Real(0.5), Real(y) + Real(0.5)) + offset,
                         scene.image);
    if (scene.features.depth_of_field)
        ray = thin_lens_ray(scene.camera, ray, settings.aperture, settings.focus_distance,
                            stream.next2());
    // The ray's time moves the spheres it meets, and those of every ray spawned from it.
    if (scene.features.motion_blur)
        ray.time = shutter_time(settings.shutter_open, settings.shutter_close, stream.next());
    return trace_sample(scene, ray, stream, observer);
}

Color shade_sampled_pixel(const PreparedScene& scene, int x, int y) {
    const int count = scene.sampling.samples_per_pixel;
    Color sum(0);
    for (int s = 0; s < count; ++s) sum += sample_pixel(scene, x, y, s);
    return sum / float(count);
}

}  // namespace rt
