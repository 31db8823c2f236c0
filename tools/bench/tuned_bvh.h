// Stage 06's BVH with the speed tricks its reference solution no longer has (tuned_bvh.cpp): the
// same tree, built and traversed faster. `rt-bench` races it against the plain reference and
// Embree.
#pragma once

#include <vector>

#include "accel/bvh.h"
#include "scene/prepared_scene.h"
#include "stage_api/stage06.h"

namespace rt::bench::tuned {

// build_bvh's contract (stage_api/stage06.h), and the same tree as the reference's.
void build(std::vector<BvhPrimitive> prims, const BvhBuildOptions& options, Bvh& bvh);

// bvh_intersect_nearest and bvh_intersect_any over `bvh` (built by build() from the scene's
// primitives) and the scene's planes.
bool nearest(const PreparedScene& scene, const Bvh& bvh, const Ray& ray, Interval t_range,
             Hit& hit);
bool any(const PreparedScene& scene, const Bvh& bvh, const Ray& ray, Interval t_range);

}  // namespace rt::bench::tuned
