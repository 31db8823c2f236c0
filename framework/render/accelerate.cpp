#include "render/accelerate.h"

#include <chrono>
#include <cstdio>

#include "accel/bvh_input.h"
#include "core/not_implemented.h"

namespace rt {

AccelerationReport build_acceleration(Scene& scene, const BvhBuildOptions& options) {
    AccelerationReport report;
    scene.bvh = Bvh{};
    if (scene.accelerator != Accelerator::Bvh) return report;
    report.requested = true;
    std::vector<BvhPrimitive> input = bvh_primitives(scene);
    report.primitives = input.size();
    const std::uint64_t stubs = stub_calls_total();
    const auto start = std::chrono::steady_clock::now();
    build_bvh(input, options, scene.bvh);
    report.build_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (stub_calls_total() != stubs) {
        report.problem = "build_bvh is not implemented";  // the stub already said where to read
    } else {
        report.problem = validate_bvh(scene.bvh, input);
        if (!report.problem.empty())
            std::fprintf(stderr,
                         "%s: the BVH from build_bvh is invalid: %s; rendering without it (read "
                         "stages/06-bvh/README.md#checking-your-tree)\n",
                         scene.source.c_str(), report.problem.c_str());
    }
    if (!report.problem.empty()) {
        scene.bvh = Bvh{};
        return report;
    }
    report.built = true;
    report.nodes = scene.bvh.nodes.size();
    report.depth = bvh_depth(scene.bvh);
    return report;
}

bool nearest_hit(const Scene& scene, const Ray& ray, Interval t_range, Hit& hit) {
    if (uses_bvh(scene)) return bvh_intersect_nearest(scene, ray, t_range, hit);
    return intersect_nearest(ray, scene, t_range, hit);
}

}  // namespace rt
