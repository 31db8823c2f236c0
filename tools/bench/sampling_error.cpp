// Stage 10's speed against error: see sampling_error.h. Uses the renderer as `rt` does (the
// reference solution's stage 10 code), one scene at a time, all cores.
#include "bench/sampling_error.h"

#include <chrono>
#include <cmath>

#include "core/source_dir.h"
#include "image/compare.h"
#include "render/prepare.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace rt::bench {
namespace {

const char* const kScenes[] = {"soft_shadows", "depth_of_field",    "motion_blur",
                               "glossy",       "ambient_occlusion", "indirect"};

Image8 render_with(PreparedScene& scene, int spp, std::uint64_t seed, double* ms) {
    scene.sampling.samples_per_pixel = spp;  // the scene is prepared: only its features change
    scene.sampling.seed = seed;
    refresh_features(scene);
    const auto start = std::chrono::steady_clock::now();
    Image image = render(scene, RenderMode::Shaded);
    if (ms)
        *ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                  .count();
    return to_image8(image);
}

}  // namespace

double rmse8(const Image8& a, const Image8& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.data.size(); ++i) {
        const double d = double(a.data[i]) - double(b.data[i]);
        sum += d * d;
    }
    return std::sqrt(sum / double(a.data.size()));
}

SamplingSeries measure_sampling_error(int width, int height, int reference_spp,
                                      const std::function<void(const std::string&)>& progress) {
    SamplingSeries series;
    series.width = width;
    series.height = height;
    series.reference_spp = reference_spp;
    series.threads = resolve_thread_count(0);
    CompareOptions grader;  // stage 10's grading.json
    grader.block = 8;
    grader.tolerance = 6;
    for (const char* name : kScenes) {
        PreparedScene scene = prepare_scene(load_scene(source_dir() / "stages" / "10-sampling" /
                                                       "scenes" / (std::string(name) + ".json")),
                                            {.width = width, .height = height});
        const std::uint64_t seed = scene.sampling.seed;
        // Another seed than the series', so the reference's noise is independent of theirs.
        const Image8 reference = render_with(scene, reference_spp, seed + 1000, nullptr);
        for (int spp = 1; spp <= 256; spp *= 4) {
            SamplingPoint p;
            p.scene = name;
            p.spp = spp;
            const Image8 image = render_with(scene, spp, seed, &p.ms);
            p.rmse = rmse8(image, reference);
            p.block_percent = compare_images(image, reference, grader).failing_percent;
            series.points.push_back(p);
        }
        if (progress) progress(std::string("sampling: ") + name);
    }
    return series;
}

}  // namespace rt::bench
