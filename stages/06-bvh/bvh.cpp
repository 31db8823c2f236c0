// Stage 06: a bounding volume hierarchy. Handout: stages/06-bvh/README.md
// The node layout is framework/accel/bvh.h; the contracts are in framework/stage_api/stage06.h.
//
// You edit only this file. Tests: ctest --test-dir build -L stage06 --output-on-failure
// Check a tree any time with validate_bvh (framework/accel/bvh.h): it names the first problem.
#include <algorithm>
#include <thread>

#include "core/not_implemented.h"
#include "stage_api/stage06.h"

namespace rt {

// Try every boundary between bins on every axis; keep the cheapest by the SAH cost model.
SahSplit find_sah_split(const std::vector<BvhPrimitive>& prims, std::size_t begin, std::size_t end,
                        const BvhBuildOptions& options) {
    // BEGIN SOLUTION
    Aabb bounds, centroids;
    for (std::size_t i = begin; i < end; ++i) {
        bounds.grow(prims[i].bounds);
        centroids.grow(prims[i].centroid);
    }
    const float area = bounds.surface_area();
    const float inv_area = area > 0 ? 1 / area : 0;
    const int bins = std::clamp(options.bins, 2, kMaxBins);

    // All three axes binned in one pass over the primitives. Only the bins in use are cleared
    // (no default initialisers: a node of a few primitives should not pay for kMaxBins bins).
    struct Bin {
        Vec3f min, max;
        std::uint32_t count;
    };
    Bin bin[3][kMaxBins];
    bool spread[3];
    float scale[3];
    for (int axis = 0; axis < 3; ++axis) {
        spread[axis] = centroids.max[axis] > centroids.min[axis];
        scale[axis] = spread[axis] ? float(bins) / (centroids.max[axis] - centroids.min[axis]) : 0;
        for (int k = 0; k < bins; ++k) bin[axis][k] = Bin{Aabb{}.min, Aabb{}.max, 0};
    }
    for (std::size_t i = begin; i < end; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            if (!spread[axis]) continue;
            Bin& b =
                bin[axis][bin_of(prims[i].centroid[axis], centroids.min[axis], scale[axis], bins)];
            b.min = glm::min(b.min, prims[i].bounds.min);
            b.max = glm::max(b.max, prims[i].bounds.max);
            ++b.count;
        }

    SahSplit best;
    for (int axis = 0; axis < 3; ++axis) {
        if (!spread[axis]) continue;
        // Right-hand sides of every boundary k (bins k .. bins-1), swept from the right.
        float right_area[kMaxBins];
        std::uint32_t right_count[kMaxBins];
        Aabb box;
        std::uint32_t count = 0;
        for (int k = bins - 1; k >= 1; --k) {
            box.grow(Aabb{bin[axis][k].min, bin[axis][k].max});
            count += bin[axis][k].count;
            right_area[k] = box.surface_area();
            right_count[k] = count;
        }
        box = Aabb{};
        count = 0;
        for (int k = 1; k < bins; ++k) {
            box.grow(Aabb{bin[axis][k - 1].min, bin[axis][k - 1].max});
            count += bin[axis][k - 1].count;
            if (count == 0 || right_count[k] == 0) continue;
            const float cost = options.traversal_cost + (box.surface_area() * float(count) +
                                                         right_area[k] * float(right_count[k])) *
                                                            inv_area;
            if (cost < best.cost) best.axis = axis, best.bin = k, best.cost = cost;
        }
    }
    if (best.axis >= 0) {  // the two sides' boxes and counts, from the chosen axis's bins
        best.centroid_lo = centroids.min[best.axis];
        best.scale = scale[best.axis];
        for (int k = 0; k < bins; ++k) {
            const Bin& b = bin[best.axis][k];
            if (b.count == 0) continue;
            (k < best.bin ? best.left_bounds : best.right_bounds).grow(Aabb{b.min, b.max});
            (k < best.bin ? best.left_count : best.right_count) += b.count;
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

// A node still to build: its index in the node array being built, and its primitives.
struct BuildTask {
    std::uint32_t node;
    std::uint32_t begin, end;
    int depth;
};

// Top-down building over a work list instead of recursion: a degenerate mesh may make a deep tree.
class TreeBuilder {
  public:
    TreeBuilder(std::vector<BvhPrimitive>& prims, const BvhBuildOptions& options, Bvh& bvh)
        : prims_(prims), options_(options), bvh_(bvh) {}

    // Makes task.node a leaf, or splits it: partitions its primitives, appends its two children
    // (boxes set, adjacent) to `nodes` and their tasks to `tasks`, left task last.
    void split_node(const BuildTask& task, std::vector<BvhNode>& nodes,
                    std::vector<BuildTask>& tasks) const {
        const std::uint32_t count = task.end - task.begin;
        const std::uint32_t mid = partition(task);
        if (mid == task.begin || mid == task.end) {  // a leaf (or, defensively, an empty side)
            for (std::uint32_t i = task.begin; i < task.end; ++i) bvh_.primitives[i] = prims_[i].id;
            nodes[task.node].first = task.begin;
            nodes[task.node].count = count;
            return;
        }
        // The children's boxes come from the primitives each side really got, not from the
        // split's bins: if the compiler evaluated bin_of a little differently here than in
        // find_sah_split (as -ffast-math allows), the tree must still be valid.
        Aabb left_bounds, right_bounds;
        for (std::uint32_t i = task.begin; i < mid; ++i) left_bounds.grow(prims_[i].bounds);
        for (std::uint32_t i = mid; i < task.end; ++i) right_bounds.grow(prims_[i].bounds);
        const std::uint32_t left = std::uint32_t(nodes.size());
        nodes.push_back(BvhNode{left_bounds.min, 0, left_bounds.max, 0});
        nodes.push_back(BvhNode{right_bounds.min, 0, right_bounds.max, 0});
        nodes[task.node].first = left;
        nodes[task.node].count = 0;
        tasks.push_back({left + 1, mid, task.end, task.depth + 1});
        tasks.push_back({left, task.begin, mid, task.depth + 1});
    }

    // Builds the subtree of `task` into `nodes`, its root at task.node.
    void build_subtree(BuildTask task, std::vector<BvhNode>& nodes) const {
        std::vector<BuildTask> tasks{task};
        while (!tasks.empty()) {
            const BuildTask next = tasks.back();
            tasks.pop_back();
            split_node(next, nodes, tasks);
        }
    }

  private:
    // Where the task's primitives split: the first index of the right side, or task.begin when
    // the SAH says a leaf costs less (or the node is small or deep enough to be one).
    std::uint32_t partition(const BuildTask& task) const {
        const std::uint32_t count = task.end - task.begin;
        SahSplit split;
        if (count > std::uint32_t(options_.max_leaf_size) && task.depth < kBvhMaxDepth)
            split = find_sah_split(prims_, task.begin, task.end, options_);
        if (split.axis < 0 || !(split.cost < float(count))) return task.begin;
        // Partition by the very same bin computation the split was chosen with.
        const int axis = split.axis;
        const int bins = std::clamp(options_.bins, 2, kMaxBins);
        const auto left_side = [&](const BvhPrimitive& p) {
            return bin_of(p.centroid[axis], split.centroid_lo, split.scale, bins) < split.bin;
        };
        return std::uint32_t(
            std::partition(prims_.begin() + task.begin, prims_.begin() + task.end, left_side) -
            prims_.begin());
    }

    std::vector<BvhPrimitive>& prims_;
    const BvhBuildOptions& options_;
    Bvh& bvh_;
};

// Lays the root's two subtrees (each built with its root at local index 0) out after the root:
// root, left child, right child, the rest of the left subtree, the rest of the right.
void place_subtrees(const std::vector<BvhNode> (&sub)[2], Bvh& bvh) {
    bvh.nodes.resize(1 + sub[0].size() + sub[1].size());
    std::uint32_t offset = 3;  // where the subtree's nodes after its root go
    for (std::uint32_t side = 0; side < 2; ++side) {
        const auto place = [&](std::uint32_t local) {
            return local == 0 ? 1 + side : offset + local - 1;
        };
        for (std::uint32_t local = 0; local < sub[side].size(); ++local) {
            BvhNode node = sub[side][local];
            if (!node.is_leaf()) node.first = place(node.first);
            bvh.nodes[place(local)] = node;
        }
        offset += std::uint32_t(sub[side].size()) - 1;
    }
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
    const TreeBuilder builder(prims, options, bvh);

    Aabb root_bounds;
    for (const BvhPrimitive& p : prims) root_bounds.grow(p.bounds);
    bvh.nodes.push_back(BvhNode{root_bounds.min, 0, root_bounds.max, 0});
    std::vector<BuildTask> children;
    builder.split_node({0, 0, n, 1}, bvh.nodes, children);
    if (children.empty()) return;  // the root is a leaf

    // The root's two subtrees are independent: build each into a vector of its own (its root at
    // local index 0), the right one on a second thread when the mesh is large. The layout does
    // not depend on the thread, so the tree is the same on every run.
    std::vector<BvhNode> sub[2] = {{bvh.nodes[1]}, {bvh.nodes[2]}};
    const BuildTask left_task{0, children[1].begin, children[1].end, 2};
    const BuildTask right_task{0, children[0].begin, children[0].end, 2};
    sub[0].reserve(2 * std::size_t(left_task.end - left_task.begin));
    sub[1].reserve(2 * std::size_t(right_task.end - right_task.begin));
    constexpr std::uint32_t kParallelFrom = 20000;  // below, a thread costs more than it saves
    if (n >= kParallelFrom && std::thread::hardware_concurrency() > 1) {
        std::thread right([&] { builder.build_subtree(right_task, sub[1]); });
        builder.build_subtree(left_task, sub[0]);
        right.join();
    } else {
        builder.build_subtree(left_task, sub[0]);
        builder.build_subtree(right_task, sub[1]);
    }
    place_subtrees(sub, bvh);
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
    Real t0 = t_range.min, t1 = kInfinity;
    for (int axis = 0; axis < 3; ++axis) {
        // The near side of the slab is min for a positive direction, max for a negative one.
        // Choosing by sign (instead of swapping the two distances) leaves a NaN (0 * inf: origin
        // on the slab's plane, direction parallel to it) where the comparisons below ignore it.
        const bool negative = inv_direction[axis] < 0;
        const Real near_side = negative ? node.max[axis] : node.min[axis];
        const Real far_side = negative ? node.min[axis] : node.max[axis];
        const Real near = (near_side - ray.origin[axis]) * inv_direction[axis];
        const Real far = (far_side - ray.origin[axis]) * inv_direction[axis];
        t0 = near > t0 ? near : t0;  // no early exit: straight-line min/max code is faster
        t1 = far < t1 ? far : t1;
    }
    // Widen the exit once (rounding is monotonic: the same as widening each far distance).
    t1 *= growth;
    t1 = t_range.max < t1 ? t_range.max : t1;
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
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
        if (intersect_primitive(scene, Scene::primitive_id(Scene::Kind::Plane, i), ray, t_range,
                                hit)) {
            found = true;
            t_range.max = hit.t;
        }
    if (!scene.bvh.built()) return found;

    const std::vector<BvhNode>& nodes = scene.bvh.nodes;
    const Vec3 inv_direction = Real(1) / ray.direction;
    std::uint32_t visited = 1, tested = 0;
    struct Entry {
        std::uint32_t node;
        Real t;
    };
    Entry stack[kBvhMaxDepth];
    int top = 0;
    Real t_root;
    if (intersect_node(nodes[0], ray, inv_direction, t_range, t_root)) stack[top++] = {0, t_root};
    while (top > 0) {
        const Entry entry = stack[--top];
        if (entry.t > t_range.max) continue;  // a nearer hit was found after it was pushed
        const BvhNode* node = &nodes[entry.node];
        while (!node->is_leaf()) {
            const BvhNode* near = &nodes[node->first];
            const BvhNode* far = near + 1;
            Real t_near, t_far;
            const bool hit_near = intersect_node(*near, ray, inv_direction, t_range, t_near);
            const bool hit_far = intersect_node(*far, ray, inv_direction, t_range, t_far);
            visited += 2;
            if (hit_near && hit_far) {
                if (t_far < t_near) std::swap(near, far), std::swap(t_near, t_far);
                stack[top++] = {std::uint32_t(far - nodes.data()), t_far};
                node = near;
            } else if (hit_near) {
                node = near;
            } else if (hit_far) {
                node = far;
            } else {
                node = nullptr;
                break;
            }
        }
        if (!node) continue;
        for (std::uint32_t k = node->first; k < node->first + node->count; ++k) {
            ++tested;
            if (intersect_primitive(scene, scene.bvh.primitives[k], ray, t_range, hit)) {
                found = true;
                t_range.max = hit.t;
            }
        }
    }
    if (stats) stats->nodes_visited += visited, stats->primitives_tested += tested;
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
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
        if (intersect_primitive(scene, Scene::primitive_id(Scene::Kind::Plane, i), ray, t_range,
                                scratch))
            return true;
    if (!scene.bvh.built()) return false;

    const std::vector<BvhNode>& nodes = scene.bvh.nodes;
    const Vec3 inv_direction = Real(1) / ray.direction;
    std::uint32_t visited = 1, tested = 0;
    bool found = false;
    std::uint32_t stack[kBvhMaxDepth + 1];  // depth-first: at most one pending sibling per level
    int top = 0;
    Real t;
    if (intersect_node(nodes[0], ray, inv_direction, t_range, t)) stack[top++] = 0;
    while (top > 0 && !found) {
        const BvhNode& node = nodes[stack[--top]];
        if (node.is_leaf()) {
            for (std::uint32_t k = node.first; k < node.first + node.count && !found; ++k) {
                ++tested;
                found = intersect_primitive(scene, scene.bvh.primitives[k], ray, t_range, scratch);
            }
            continue;
        }
        visited += 2;
        for (std::uint32_t child = node.first; child < node.first + 2; ++child)
            if (intersect_node(nodes[child], ray, inv_direction, t_range, t)) stack[top++] = child;
    }
    if (stats) stats->nodes_visited += visited, stats->primitives_tested += tested;
    return found;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/06-bvh/README.md#any-hit-queries");
    // (void)scene; (void)ray; (void)t_range; (void)stats;
    // return false;
    // END SOLUTION
}

}  // namespace rt
