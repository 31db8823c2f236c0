// Progressive rendering for the viewer: a worker thread renders the scene at 1/8, 1/4, 1/2 and
// then full resolution (a stage 10 scene then with 1, 4, 16, ... samples per pixel up to its
// own count, each pass a whole estimate at that count), each pass through rt::render itself (so the last pass is the image
// `rt render` writes, bit for bit), or through stage 09's GPU renderer (`rt render --gpu`'s
// image: a headless EGL context and its cached programs, owned by the worker), and starts again
// whenever the viewer hands it a new scene. The UI thread never waits for it.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "image/image.h"
#include "scene/prepared_scene.h"

namespace rt::view {

struct Frame {
    Image image;                   // always full size (coarse passes are blown up, nearest)
    int block = 1;                 // 8, 4, 2: a coarse pass; 1: full resolution
    int samples = 1;               // samples per pixel of this pass (stage 10 scenes refine them)
    bool last = false;             // the pass `rt render` would give: full size, every sample
    std::uint64_t generation = 0;  // which restart() it belongs to
    double seconds = 0;            // this pass's render time
    bool gpu = false;              // rendered by the GPU path
    std::string error;             // the renderer refused (e.g. bvh_visits without a BVH)
    bool refined() const { return last && error.empty(); }
};

class ProgressiveRenderer {
  public:
    explicit ProgressiveRenderer(int threads);
    ~ProgressiveRenderer();  // cancels the current pass and joins the worker

    // Drops whatever is being rendered and starts on `scene` (on the GPU path when `gpu`);
    // returns its generation.
    std::uint64_t restart(PreparedScene scene, bool gpu = false);
    // The newest pass finished since the last call, if any (older ones are dropped).
    std::optional<Frame> take();
    int threads() const { return threads_; }

  private:
    void run();

    const int threads_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<PreparedScene> pending_;
    bool pending_gpu_ = false;
    std::optional<Frame> ready_;
    std::uint64_t generation_ = 0;
    bool quit_ = false;
    std::atomic<bool> cancel_{false};
    std::thread worker_;  // last: starts after every member it uses
};

}  // namespace rt::view
