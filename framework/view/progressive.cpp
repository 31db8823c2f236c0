#include "view/progressive.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <memory>
#include <vector>

#include "render/gpu/flatten_instances.h"
#include "render/gpu/gpu_render.h"
#include "render/prepare.h"
#include "render/render.h"

namespace rt::view {
namespace {

// Each coarse pixel stands for a block of block x block full-size pixels.
Image blow_up(const Image& coarse, int block, int width, int height) {
    Image full(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            full.at(x, y) = coarse.at(std::min(x / block, coarse.width - 1),
                                      std::min(y / block, coarse.height - 1));
    return full;
}

struct Pass {
    int block = 1;
    int samples = 1;
};

// Coarse passes (1 sample: they are a preview) only while they are much cheaper than the full
// one; then full size, with the samples of a Monte Carlo scene raised fourfold a pass, each pass
// a whole render at its count (stratified samples do not nest, so they are not accumulated); the
// last pass is the scene's own count, `rt render`'s image.
std::vector<Pass> passes_for(const PreparedScene& scene) {
    const int samples = std::max(1, scene.sampling.samples_per_pixel);
    std::vector<Pass> passes;
    for (int block : {8, 4, 2})
        if (scene.image.width * scene.image.height >= 64 * 64 * block) passes.push_back({block, 1});
    for (int s = 1; s < samples; s *= 4) passes.push_back({1, s});
    passes.push_back({1, samples});
    return passes;
}

}  // namespace

ProgressiveRenderer::ProgressiveRenderer(int threads)
    : threads_(resolve_thread_count(threads)), worker_([this] { run(); }) {}

ProgressiveRenderer::~ProgressiveRenderer() {
    {
        std::lock_guard lock(mutex_);
        quit_ = true;
        cancel_ = true;
    }
    wake_.notify_all();
    worker_.join();
}

std::uint64_t ProgressiveRenderer::restart(PreparedScene scene, bool gpu) {
    std::uint64_t generation = 0;
    {
        std::lock_guard lock(mutex_);
        pending_ = std::move(scene);
        pending_gpu_ = gpu;
        generation = ++generation_;
        cancel_ = true;  // the pass in flight stops at its next tile
    }
    wake_.notify_all();
    return generation;
}

std::optional<Frame> ProgressiveRenderer::take() {
    std::lock_guard lock(mutex_);
    std::optional<Frame> frame = std::move(ready_);
    ready_.reset();
    return frame;
}

void ProgressiveRenderer::run() {
    // Made on first use, on this thread, and kept: its context is current here, and its programs
    // (one per feature mask) survive camera changes.
    std::unique_ptr<GpuRenderer> gpu_renderer;
    for (;;) {
        PreparedScene scene;
        bool gpu = false;
        std::uint64_t generation = 0;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return quit_ || pending_.has_value(); });
            if (quit_) return;
            scene = std::move(*pending_);
            pending_.reset();
            gpu = pending_gpu_;
            generation = generation_;
            cancel_ = false;
        }
        const ImageSize full = scene.image;
        RenderOptions options;
        options.threads = threads_;
        options.cancel = &cancel_;
        const std::vector<Pass> passes = passes_for(scene);
        for (std::size_t k = 0; k < passes.size(); ++k) {
            const int block = passes[k].block;
            scene.image = {(full.width + block - 1) / block, (full.height + block - 1) / block};
            if (scene.sampling.samples_per_pixel != passes[k].samples) {
                scene.sampling.samples_per_pixel = passes[k].samples;
                refresh_features(scene);
            }
            Frame frame;
            frame.block = block;
            frame.samples = passes[k].samples;
            frame.last = k + 1 == passes.size();
            frame.gpu = gpu;
            frame.generation = generation;
            const auto start = std::chrono::steady_clock::now();
            try {
                if (gpu) {
                    if (!gpu_renderer) {
                        GpuRenderOptions gpu_options;
                        gpu_options.cancel = &cancel_;  // stage 10: between sample batches
                        gpu_renderer = std::make_unique<GpuRenderer>(gpu_options);
                    }
                    // Instances: the GPU's world-space copy, made once for all the passes
                    // (they change only the image size and the samples).
                    if (!scene.instances.empty()) scene = flatten_instances(scene, scene.mode);
                    frame.image = gpu_renderer->render(scene, scene.mode);
                } else {
                    frame.image = render(scene, scene.mode, options);
                }
            } catch (const std::exception& e) {
                frame.error = e.what();
            }
            frame.seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (cancel_) break;
            if (block > 1 && frame.error.empty())
                frame.image = blow_up(frame.image, block, full.width, full.height);
            const bool failed = !frame.error.empty();
            {
                std::lock_guard lock(mutex_);
                if (generation != generation_) break;
                ready_ = std::move(frame);
            }
            if (failed) break;
        }
    }
}

}  // namespace rt::view
