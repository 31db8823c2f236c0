// Stage 06 (BVH): the functions students write in stages/06-bvh/bvh.cpp.
// Handout: stages/06-bvh/README.md. The tree's data layout: framework/accel/bvh.h.
//
// The tree holds the bounded primitives (spheres, triangles, boxes). Planes are unbounded, so
// they stay outside it and are tested one by one, as in stage 02.
#pragma once

#include <vector>

#include "accel/bvh.h"
#include "scene/prepared_scene.h"
#include "stage_api/stage02.h"

namespace rt {

inline constexpr int kMaxBins = 64;

struct BvhBuildOptions {
    int bins = 16;                // SAH bins per axis: bins - 1 candidate split planes per axis
    int max_leaf_size = 4;        // a node with more primitives than this is split if it can be
    float traversal_cost = 1.0f;  // C_trav: the cost of visiting a node, in units of one
                                  // primitive intersection test (C_isect = 1)
};

// A split chosen by the surface area heuristic. Primitives whose centroid falls in bins
// [0, bin) of `axis` go left, the others right (bin_of below says which bin a centroid is in).
struct SahSplit {
    int axis = -1;  // -1: there is no split (all centroids coincide on every axis)
    int bin = 0;    // 1 .. bins - 1
    float cost = std::numeric_limits<float>::infinity();  // C_trav + (A_L N_L + A_R N_R) / A
    Aabb left_bounds, right_bounds;  // the boxes around the primitives of each side
    std::uint32_t left_count = 0, right_count = 0;
    float centroid_lo = 0, scale = 0;  // of `axis`: what bin_of needs to partition by this split
};

// The bin (0 .. bins - 1) of centroid coordinate `c` when the centroids of a node span
// [lo, hi] on that axis (hi > lo) and scale = bins / (hi - lo). Builder and partition must both
// use exactly this. (A NaN, from an overflowing scale, lands in bin 0.)
inline int bin_of(float c, float lo, float scale, int bins) {
    const float x = (c - lo) * scale;
    return x >= 0 ? (x < float(bins) ? int(x) : bins - 1) : 0;
}

// The cheapest binned SAH split of prims[begin, end), over all three axes (axes on which the
// centroids do not spread are skipped), considering only splits with primitives on both sides.
// A is the surface area of the box around all of them (when A = 0, use 1 / A = 0). Ties go to
// the lower axis, then the lower bin. options.bins is between 2 and kMaxBins.
SahSplit find_sah_split(const std::vector<BvhPrimitive>& prims, std::size_t begin, std::size_t end,
                        const BvhBuildOptions& options);

// Builds `bvh` over `prims` (which it may reorder) top-down: a node becomes a leaf when it holds
// at most options.max_leaf_size primitives, when no split exists, or when the best split costs
// at least as much as making a leaf (cost N), or at depth kBvhMaxDepth. Otherwise its primitives are partitioned by the split and
// both children are built. Node 0 is the root; a node's two children are adjacent.
// An empty `prims` gives an empty tree (no nodes).
void build_bvh(std::vector<BvhPrimitive> prims, const BvhBuildOptions& options, Bvh& bvh);

// Ray-box slab test for a node. `inv_direction` is 1 / ray.direction per component (may be
// +-inf). True when the ray's segment t_range meets the box; t_entry is then where it enters
// (clamped to t_range.min). Must never miss a box that a primitive inside it is hit in: see the
// handout on rounding (README.md#robust-slab-test).
bool intersect_node(const BvhNode& node, const Ray& ray, const Vec3& inv_direction,
                    Interval t_range, Real& t_entry);

// The nearest hit in t_range over the whole scene, like stage 02's intersect_nearest (same
// result), but visiting only the nodes the ray can reach: nearer child first, skipping a node
// that starts beyond the nearest hit found so far. Uses scene.bvh. Fills `stats` when given.
bool bvh_intersect_nearest(const PreparedScene& scene, const Ray& ray, Interval t_range, Hit& hit,
                           BvhStats* stats = nullptr);

// Whether anything is hit in t_range (shadow rays): stops at the first hit found.
bool bvh_intersect_any(const PreparedScene& scene, const Ray& ray, Interval t_range,
                       BvhStats* stats = nullptr);

}  // namespace rt
