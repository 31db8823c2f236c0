// Stage 06: a bounding volume hierarchy. Handout: stages/06-bvh/README.md
// The node layout is framework/accel/bvh.h; the contracts are in framework/stage_api/stage06.h.
//
// You edit only this file. Tests: ctest --test-dir build -L stage06 --output-on-failure
// Check a tree any time with validate_bvh (framework/accel/bvh.h): it names the first problem.
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "core/not_implemented.h"
#include "render/nearest_hit.h"
#include "stage_api/stage06.h"

namespace rt {

// BEGIN SOLUTION
namespace {

// One bin of one axis: the box around the primitives whose centroid falls in it, and how many.
struct Bin {
    Aabb bounds;
    std::uint32_t count = 0;

    void add(const Aabb& box, std::uint32_t n) {
        bounds.grow(box);
        count += n;
    }
};

}  // namespace
// STUB
// // Helper functions of your own may go here (an anonymous namespace keeps them in this file).
// END SOLUTION

// Try every boundary between bins on every axis; keep the cheapest by the SAH cost model.
SahSplit find_sah_split(const std::vector<BvhPrimitive>& prims, std::size_t begin, std::size_t end,
                        const BvhBuildOptions& options) {
    // BEGIN SOLUTION
    // The node's box (for A) and the box of its centroids (which the bins divide).
    Aabb bounds, centroids;
    for (std::size_t i = begin; i < end; ++i) {
        bounds.grow(prims[i].bounds);
        centroids.grow(prims[i].centroid);
    }
    const int bins = std::clamp(options.bins, 2, kMaxBins);
    const float area = bounds.surface_area();
    const float inv_area = area > 0 ? 1 / area : 0;

    SahSplit best;
    for (int axis = 0; axis < 3; ++axis) {
        if (!(centroids.max[axis] > centroids.min[axis])) continue;  // no spread on this axis
        const float lo = centroids.min[axis];
        const float scale = float(bins) / (centroids.max[axis] - lo);

        // 1. Each primitive into the bin of its centroid.
        Bin bin[kMaxBins];
        for (std::size_t i = begin; i < end; ++i)
            bin[bin_of(prims[i].centroid[axis], lo, scale, bins)].add(prims[i].bounds, 1);

        // 2. From the right: right[k] holds bins k .. bins - 1.
        Bin right[kMaxBins + 1];
        for (int k = bins - 1; k >= 1; --k) {
            right[k] = right[k + 1];
            right[k].add(bin[k].bounds, bin[k].count);
        }

        // 3. From the left, the cost of each boundary k (bins [0, k) go left). Only splits with
        // primitives on both sides count; on a tie the lower bin stays.
        Bin left;
        for (int k = 1; k < bins; ++k) {
            left.add(bin[k - 1].bounds, bin[k - 1].count);
            if (left.count == 0 || right[k].count == 0) continue;
            const float left_term = left.bounds.surface_area() * float(left.count);
            const float right_term = right[k].bounds.surface_area() * float(right[k].count);
            const float cost = options.traversal_cost + (left_term + right_term) * inv_area;
            if (!(cost < best.cost)) continue;
            best.axis = axis;
            best.bin = k;
            best.cost = cost;
            best.left_bounds = left.bounds;
            best.right_bounds = right[k].bounds;
            best.left_count = left.count;
            best.right_count = right[k].count;
            best.centroid_lo = lo;
            best.scale = scale;
        }
    }
    return best;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/06-bvh/README.md#the-surface-area-heuristic");
    // (void)prims; (void)begin; (void)end; (void)options;
    // return {};
    // END SOLUTION
}

// BEGIN SOLUTION
namespace {

// A node still to build: its index in bvh.nodes, its primitives prims[begin, end), its depth.
struct BuildTask {
    std::uint32_t node;
    std::uint32_t begin, end;
    int depth;
};

// A node whose box is the one around prims[begin, end); its links are set later.
BvhNode node_around(const std::vector<BvhPrimitive>& prims, std::uint32_t begin,
                    std::uint32_t end) {
    Aabb box;
    for (std::uint32_t i = begin; i < end; ++i) box.grow(prims[i].bounds);
    return BvhNode{box.min, 0, box.max, 0};
}

// Where the task's primitives split: they are partitioned so that [begin, mid) go left and
// [mid, end) right, and mid is returned; or the task's begin, when the node stays a leaf.
std::uint32_t split_point(std::vector<BvhPrimitive>& prims, const BuildTask& task,
                          const BvhBuildOptions& options) {
    const std::uint32_t count = task.end - task.begin;
    if (count <= std::uint32_t(options.max_leaf_size) || task.depth >= kBvhMaxDepth)
        return task.begin;
    const SahSplit split = find_sah_split(prims, task.begin, task.end, options);
    if (split.axis < 0 || !(split.cost < float(count))) return task.begin;  // a leaf is cheaper
    // The very bin computation the split was chosen with.
    const int bins = std::clamp(options.bins, 2, kMaxBins);
    const auto goes_left = [&](const BvhPrimitive& p) {
        return bin_of(p.centroid[split.axis], split.centroid_lo, split.scale, bins) < split.bin;
    };
    const auto first = prims.begin() + task.begin;
    const auto mid = std::partition(first, prims.begin() + task.end, goes_left);
    const std::uint32_t index = task.begin + std::uint32_t(mid - first);
    return index == task.end ? task.begin : index;  // an empty side: a leaf after all
}

}  // namespace
// STUB
// // Helper functions of your own may go here (an anonymous namespace keeps them in this file).
// END SOLUTION

// Top-down: split while the SAH says splitting pays, children stored next to each other.
void build_bvh(std::vector<BvhPrimitive> prims, const BvhBuildOptions& options, Bvh& bvh) {
    // BEGIN SOLUTION
    bvh = Bvh{};
    if (prims.empty()) return;
    const std::uint32_t n = std::uint32_t(prims.size());
    bvh.primitives.resize(n);
    bvh.nodes.reserve(2 * std::size_t(n));  // a tree over n primitives has at most 2n - 1 nodes
    bvh.nodes.push_back(node_around(prims, 0, n));

    // A list of work instead of recursion: a badly shaped mesh can make the tree deep.
    std::vector<BuildTask> tasks{{0, 0, n, 1}};
    while (!tasks.empty()) {
        const BuildTask task = tasks.back();
        tasks.pop_back();
        const std::uint32_t mid = split_point(prims, task, options);
        if (mid == task.begin) {  // a leaf: its primitives' ids, at the same positions
            bvh.nodes[task.node].first = task.begin;
            bvh.nodes[task.node].count = task.end - task.begin;
            for (std::uint32_t i = task.begin; i < task.end; ++i) bvh.primitives[i] = prims[i].id;
            continue;
        }
        // Two children, side by side; the left one is built first.
        const std::uint32_t left = std::uint32_t(bvh.nodes.size());
        bvh.nodes.push_back(node_around(prims, task.begin, mid));
        bvh.nodes.push_back(node_around(prims, mid, task.end));
        bvh.nodes[task.node].first = left;
        tasks.push_back({left + 1, mid, task.end, task.depth + 1});
        tasks.push_back({left, task.begin, mid, task.depth + 1});
    }
    // STUB
    // RT_NOT_IMPLEMENTED("stages/06-bvh/README.md#building-the-tree");
    // (void)prims; (void)options; (void)bvh;
    // END SOLUTION
}

// Slab test: the ray is inside the box where it is inside all three slabs at once.
bool intersect_node(const BvhNode& node, const Ray& ray, const Vec3& inv_direction,
                    Interval t_range, Real& t_entry) {
    // BEGIN SOLUTION
    // gamma(3) of Higham and pbrt: a bound on the relative rounding error of the distances.
    constexpr Real eps = std::numeric_limits<Real>::epsilon() / 2;
    constexpr Real growth = 1 + 2 * (3 * eps) / (1 - 3 * eps);
    Real t0 = t_range.min;
    Real t1 = t_range.max;
    for (int axis = 0; axis < 3; ++axis) {
        // A positive direction meets the slab's min plane first, a negative one its max plane.
        const bool negative = inv_direction[axis] < 0;
        const Real near_plane = negative ? node.max[axis] : node.min[axis];
        const Real far_plane = negative ? node.min[axis] : node.max[axis];
        const Real near = (near_plane - ray.origin[axis]) * inv_direction[axis];
        const Real far = (far_plane - ray.origin[axis]) * inv_direction[axis] * growth;
        // Written so that a NaN (0 * inf: the origin on the plane) leaves the interval as it is.
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
    }
    t_entry = t0;
    return t0 <= t1;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/06-bvh/README.md#ray-box-slab-test");
    // (void)node; (void)ray; (void)inv_direction; (void)t_range; (void)t_entry;
    // return false;
    // END SOLUTION
}

// Depth-first, nearer child first, skipping whatever starts beyond the nearest hit so far.
bool bvh_intersect_nearest(const PreparedScene& scene, const Ray& ray, Interval t_range, Hit& hit,
                           BvhStats* stats) {
    // BEGIN SOLUTION
    bool found = false;
    for (std::size_t i = 0; i < scene.planes.size(); ++i) {
        if (intersect_primitive(scene, Scene::primitive_id(Scene::Kind::Plane, i), ray, t_range,
                                hit)) {
            found = true;
            t_range.max = hit.t;  // what follows must be nearer
        }
    }
    if (!scene.bvh.built()) return found;

    const std::vector<BvhNode>& nodes = scene.bvh.nodes;
    const Vec3 inv_direction = Real(1) / ray.direction;
    std::uint32_t visited = 1;
    std::uint32_t tested = 0;
    struct Pending {
        std::uint32_t node;
        Real t_entry;
    };
    Pending stack[kBvhMaxDepth];  // the far children waiting, and the near one about to be taken
    int top = 0;
    Real t_root;
    if (intersect_node(nodes[0], ray, inv_direction, t_range, t_root)) stack[top++] = {0, t_root};
    while (top > 0) {
        const Pending pending = stack[--top];
        if (pending.t_entry > t_range.max) continue;  // a nearer hit was found after the push
        const BvhNode& node = nodes[pending.node];
        if (node.is_leaf()) {
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
                ++tested;
                if (intersect_primitive(scene, scene.bvh.primitives[k], ray, t_range, hit)) {
                    found = true;
                    t_range.max = hit.t;
                }
            }
            continue;
        }
        // Both children's boxes: the nearer is taken next (the left one on a tie), the other
        // waits below it.
        Pending left{node.first, 0};
        Pending right{node.first + 1, 0};
        const bool hit_left =
            intersect_node(nodes[left.node], ray, inv_direction, t_range, left.t_entry);
        const bool hit_right =
            intersect_node(nodes[right.node], ray, inv_direction, t_range, right.t_entry);
        visited += 2;
        if (hit_left && hit_right) {
            const bool right_nearer = right.t_entry < left.t_entry;
            stack[top++] = right_nearer ? left : right;
            stack[top++] = right_nearer ? right : left;
        } else if (hit_left) {
            stack[top++] = left;
        } else if (hit_right) {
            stack[top++] = right;
        }
    }
    if (stats) {
        stats->nodes_visited += visited;
        stats->primitives_tested += tested;
    }
    return found;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/06-bvh/README.md#nearest-hit-traversal");
    // (void)scene; (void)ray; (void)t_range; (void)hit; (void)stats;
    // return false;
    // END SOLUTION
}

// Any order will do: the first hit ends the search.
bool bvh_intersect_any(const PreparedScene& scene, const Ray& ray, Interval t_range,
                       BvhStats* stats) {
    // BEGIN SOLUTION
    Hit scratch;
    for (std::size_t i = 0; i < scene.planes.size(); ++i) {
        if (intersect_primitive(scene, Scene::primitive_id(Scene::Kind::Plane, i), ray, t_range,
                                scratch))
            return true;
    }
    if (!scene.bvh.built()) return false;

    const std::vector<BvhNode>& nodes = scene.bvh.nodes;
    const Vec3 inv_direction = Real(1) / ray.direction;
    std::uint32_t visited = 1;
    std::uint32_t tested = 0;
    bool found = false;
    std::uint32_t stack[kBvhMaxDepth + 1];  // nodes whose box the ray enters, still to open
    int top = 0;
    Real t_entry;
    if (intersect_node(nodes[0], ray, inv_direction, t_range, t_entry)) stack[top++] = 0;
    while (top > 0 && !found) {
        const BvhNode& node = nodes[stack[--top]];
        if (node.is_leaf()) {
            for (std::uint32_t k = node.first; k < node.first + node.count && !found; ++k) {
                ++tested;
                found = intersect_primitive(scene, scene.bvh.primitives[k], ray, t_range, scratch);
            }
            continue;
        }
        // Any order will do; the right child is opened first.
        const std::uint32_t left = node.first;
        const std::uint32_t right = node.first + 1;
        visited += 2;
        if (intersect_node(nodes[left], ray, inv_direction, t_range, t_entry)) stack[top++] = left;
        if (intersect_node(nodes[right], ray, inv_direction, t_range, t_entry))
            stack[top++] = right;
    }
    if (stats) {
        stats->nodes_visited += visited;
        stats->primitives_tested += tested;
    }
    return found;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/06-bvh/README.md#any-hit-queries");
    // (void)scene; (void)ray; (void)t_range; (void)stats;
    // return false;
    // END SOLUTION
}

}  // namespace rt
