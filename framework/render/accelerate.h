// Which nearest-hit query the renderer uses, and building the stage 06 BVH of a scene.
//
// A scene file asks for a BVH with "render": {"accelerator": "bvh"}; every other scene keeps
// stage 02's loop over all primitives, so stages 01-05 never depend on stage 06.
#pragma once

#include <string>

#include "stage_api/stage06.h"

namespace rt {

struct AccelerationReport {
    bool requested = false;  // the scene asked for a BVH
    bool built = false;      // and build_bvh gave a valid tree
    std::string problem;     // why not, when requested but not built
    double build_ms = 0;
    std::size_t primitives = 0, nodes = 0;
    int depth = 0;
};

// Builds scene.bvh when scene.accelerator == Accelerator::Bvh, and checks it (validate_bvh).
// An invalid tree is reported on stderr (naming the problem and the handout) and dropped:
// scene.accelerator becomes None, and rendering uses stage 02's loop (same image, slower).
// A stubbed build_bvh leaves the scene asking for a tree it has not got: nearest_hit then counts
// every query as a stub call, so the image is magenta at once, like any other stub.
AccelerationReport build_acceleration(PreparedScene& scene, const BvhBuildOptions& options = {});

// True when the scene's queries go through a built BVH.
inline bool uses_bvh(const PreparedScene& scene) {
    return scene.accelerator == Accelerator::Bvh && scene.bvh.built();
}

// The renderer's nearest-hit query, nearest_hit, is in render/nearest_hit.h: the student code of
// stages 04, 10 and 11 traces its rays through it too.

}  // namespace rt
