#include "bench/view_latency.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "camera/camera_moves.h"
#include "core/source_dir.h"
#include "scene/scene_loader.h"
#include "view/progressive.h"
#include "view/view_settings.h"

namespace rt::bench {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Stats {
    double median, low, high;
};

Stats stats(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return {v[v.size() / 2], v.front(), v.back()};
}

std::string row(const char* what, const Stats& s) {
    char line[160];
    std::snprintf(line, sizeof line, "| %s | %.1f | %.1f | %.1f |\n", what, s.median, s.low,
                  s.high);
    return line;
}

}  // namespace

bool run_view_latency(const ViewLatencyConfig& config, std::ostream& out) {
    const std::filesystem::path file =
        config.scene.empty() ? source_dir() / "stages/05-recursion/scenes/whitted.json"
                             : config.scene;
    Scene loaded;
    try {
        loaded = load_scene(file);
    } catch (const std::exception& e) {
        out << "rt-bench: error: " << e.what() << "\n";
        return false;
    }
    loaded.image = ImageSize{config.width, config.height};
    view::SceneSource source(std::move(loaded));
    view::ViewSettings settings = source.initial();
    const Vec3 up = settings.camera.v;
    const Real pivot = glm::length(settings.camera.eye);  // any distance: only the change counts

    view::ProgressiveRenderer renderer(config.threads);
    // What the viewer does on a drag: new settings, a new scene (SceneSource::make, a copy with
    // the camera and the features), restart. The clock starts before the copy, as for a person.
    const auto change_and_wait = [&](double& first_ms, double& full_ms, int& first_block) {
        const auto start = Clock::now();
        orbit(settings.camera, pivot, up, 3, 0);
        const std::uint64_t generation = renderer.restart(source.make(settings), config.gpu);
        first_ms = -1;
        for (;;) {
            if (auto frame = renderer.take(); frame && frame->generation == generation) {
                if (!frame->error.empty()) {
                    out << "rt-bench: error: the renderer refused: " << frame->error << "\n";
                    return false;
                }
                if (first_ms < 0) {
                    first_ms = ms_since(start);
                    first_block = frame->block;
                }
                if (frame->refined()) {
                    full_ms = ms_since(start);
                    return true;
                }
            }
            std::this_thread::sleep_for(std::chrono::microseconds(200));  // a UI polls each frame
        }
    };
    double first = 0, full = 0;
    int block = 0;
    if (!change_and_wait(first, full, block)) return false;  // warm-up: caches, the BVH
    std::vector<double> firsts, fulls;
    for (int k = 0; k < config.changes; ++k) {
        if (!change_and_wait(first, full, block)) return false;
        firsts.push_back(first);
        fulls.push_back(full);
    }
    const std::string path = config.gpu ? "the GPU path (stage 09's shader, headless EGL)"
                                        : std::to_string(renderer.threads()) + " CPU threads";
    out << "Viewer latency: " << file.filename().string() << " at " << config.width << "x"
        << config.height << ", " << path << ", "
        << (settings.accelerator == Accelerator::Bvh ? "stage 06's BVH" : "no BVH") << ", "
        << config.changes << " camera changes (orbits of 3 degrees), milliseconds\n\n"
        << "| from a camera change to | median | fastest | slowest |\n|---|---|---|---|\n"
        << row(("the first frame (1/" + std::to_string(block) + " resolution)").c_str(),
               stats(firsts))
        << row("the full-resolution frame", stats(fulls));
    const Stats full_stats = stats(fulls);
    char rate[96];
    std::snprintf(rate, sizeof rate, "\nFull frames per second while orbiting: %.2f (median)\n",
                  1000 / full_stats.median);
    out << rate;
    return true;
}

}  // namespace rt::bench
