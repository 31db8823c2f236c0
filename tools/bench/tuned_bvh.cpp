// The BVH that stage 06's reference solution was before issue 49 made it plain, kept as a
// back-end of `rt-bench` ("bvh-tuned") so that what its speed tricks buy stays measured: the bins'
// boxes as 4-wide vectors (a GCC and Clang extension), every axis binned in one pass, only the
// bins in use swept, the top levels split side by side and subtrees built as parallel jobs, the
// partition growing the children's boxes as it moves primitives, each slab's near bound chosen
// once per ray, and a descent to a leaf in an inner loop. It builds the very tree
// stages/06-bvh/bvh.cpp builds, in another node order (Bench.TunedBvh.*).
#include "bench/tuned_bvh.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <type_traits>

#include "core/parallel_for.h"
#include "render/nearest_hit.h"

namespace rt::bench::tuned {

namespace {

// A box as two 4-wide vectors (x, y, z, an unused lane; a GCC and Clang vector extension): one
// SSE min or max each, which round nothing, so the box is exactly the Aabb it stands for.
using Lanes = float __attribute__((vector_size(16)));

// No default member initialisers: an array of kMaxBins of them would be filled on every call.
struct Box4 {
    Lanes min, max;

    static Box4 empty() {
        constexpr float inf = std::numeric_limits<float>::infinity();
        return Box4{Lanes{inf, inf, inf, inf}, Lanes{-inf, -inf, -inf, -inf}};
    }
    // A primitive's box in two 4-float loads (each fourth lane, inside the primitive, unused).
    static Box4 of(const BvhPrimitive& p) {
        static_assert(offsetof(BvhPrimitive, bounds) + sizeof(Aabb) < sizeof(BvhPrimitive));
        Box4 box;
        std::memcpy(&box.min, &p.bounds.min.x, sizeof box.min);
        std::memcpy(&box.max, &p.bounds.max.x, sizeof box.max);
        return box;
    }
    static Lanes centroid(const BvhPrimitive& p) {
        return Lanes{p.centroid.x, p.centroid.y, p.centroid.z, 0};
    }
    void grow(const Lanes& lo, const Lanes& hi) {
        min = lo < min ? lo : min;
        max = hi > max ? hi : max;
    }
    void grow(const Box4& b) { grow(b.min, b.max); }
    Aabb aabb() const { return Aabb{Vec3f(min[0], min[1], min[2]), Vec3f(max[0], max[1], max[2])}; }
};

// Every axis's bins over some primitives: the box and count of those whose centroid falls in
// each. All three axes are binned in one pass over the primitives.
struct Bins {
    Box4 box[3][kMaxBins];
    std::uint32_t count[3][kMaxBins];

    // Only the bins in use are cleared: a small node should not pay for kMaxBins.
    explicit Bins(int bins) {
        for (int axis = 0; axis < 3; ++axis)
            for (int k = 0; k < bins; ++k) {
                box[axis][k] = Box4::empty();
                count[axis][k] = 0;
            }
    }
    // bin_of on three axes at once, lane by lane the same answers (clamped before converting).
    void add(const std::vector<BvhPrimitive>& prims, std::size_t begin, std::size_t end,
             const Aabb& centroids, const float (&scale)[3], int bins) {
        using Ints = std::int32_t __attribute__((vector_size(16)));
        const Lanes lo{centroids.min.x, centroids.min.y, centroids.min.z, 0};
        const Lanes scales{scale[0], scale[1], scale[2], 0};
        const Lanes zero{}, tops = zero + float(bins), lasts = zero + float(bins - 1);
        for (std::size_t i = begin; i < end; ++i) {
            const Box4 b = Box4::of(prims[i]);
            Lanes x = (Box4::centroid(prims[i]) - lo) * scales;
            x = x >= zero ? x : zero;  // and NaN
            x = x < tops ? x : lasts;
            const Ints k = __builtin_convertvector(x, Ints);
            for (int axis = 0; axis < 3; ++axis) {
                if (!(scale[axis] > 0)) continue;  // the centroids do not spread on this axis
                box[axis][k[axis]].grow(b);
                ++count[axis][k[axis]];
            }
        }
    }
};

// What the slab test needs of a ray, worked out once per traversal: for each axis, the node's
// bound it meets first (min for a positive direction), by index into the node read as eight
// floats (min: 0-2, max: 4-6). Choosing by sign, not by swapping distances, leaves a NaN (0 * inf)
// where the comparisons ignore it; choosing once per ray takes the sign out of every box test.
struct SlabRay {
    Vec3 origin, inv_direction;
    int near_side[3];  // the far side is near_side ^ 4

    SlabRay(const Ray& ray, const Vec3& inv) : origin(ray.origin), inv_direction(inv) {
        static_assert(std::is_standard_layout_v<BvhNode> && offsetof(BvhNode, max) == 16);
        for (int axis = 0; axis < 3; ++axis) near_side[axis] = inv[axis] < 0 ? 4 + axis : axis;
    }
};

// intersect_node's slab test, compiled into both traversals' loops.
[[gnu::always_inline]] inline bool slab_test(const BvhNode& node, const SlabRay& ray,
                                             Interval t_range, Real& t_entry) {
    // gamma(3) of Higham and pbrt: a bound on the relative rounding error of the distances.
    constexpr Real eps = std::numeric_limits<Real>::epsilon() / 2;
    constexpr Real growth = 1 + 2 * (3 * eps) / (1 - 3 * eps);
    Real t0 = t_range.min, t1 = kInfinity;
    const float* bounds = reinterpret_cast<const float*>(&node);
    for (int axis = 0; axis < 3; ++axis) {
        const int side = ray.near_side[axis];
        const Real near = (bounds[side] - ray.origin[axis]) * ray.inv_direction[axis];
        const Real far = (bounds[side ^ 4] - ray.origin[axis]) * ray.inv_direction[axis];
        t0 = near > t0 ? near : t0;  // no early exit: straight-line min/max code is faster
        t1 = far < t1 ? far : t1;
    }
    // Widen the exit once (rounding is monotonic: the same as widening each far distance).
    t1 *= growth;
    t1 = t_range.max < t1 ? t_range.max : t1;
    t_entry = t0;
    return t0 <= t1;
}

// find_sah_split, tuned: the boundaries between the bins in use, on every axis at once.
SahSplit sah_split(const std::vector<BvhPrimitive>& prims, std::size_t begin, std::size_t end,
                   const BvhBuildOptions& options) {
    Box4 centroids4 = Box4::empty();
    for (std::size_t i = begin; i < end; ++i)
        centroids4.grow(Box4::centroid(prims[i]), Box4::centroid(prims[i]));
    const Aabb centroids = centroids4.aabb();
    const int bins = std::clamp(options.bins, 2, kMaxBins);
    bool spread[3];
    float scale[3];
    for (int axis = 0; axis < 3; ++axis) {
        spread[axis] = centroids.max[axis] > centroids.min[axis];
        scale[axis] = spread[axis] ? float(bins) / (centroids.max[axis] - centroids.min[axis]) : 0;
    }
    const int first_spread = spread[0] ? 0 : spread[1] ? 1 : spread[2] ? 2 : -1;
    if (first_spread < 0) return {};  // no split: the centroids coincide
    Bins binned(bins);
    binned.add(prims, begin, end, centroids, scale, bins);
    Box4 bounds = Box4::empty();  // the node's box: every primitive is in one bin of each axis
    for (int k = 0; k < bins; ++k) bounds.grow(binned.box[first_spread][k]);
    const float area = bounds.aabb().surface_area();
    const float inv_area = area > 0 ? 1 / area : 0;

    SahSplit best;
    for (int axis = 0; axis < 3; ++axis) {
        if (!spread[axis]) continue;
        // Only the bins in use matter: every boundary between two of them (after used[j - 1],
        // before used[j]) splits the primitives the same way, so only the lowest, used[j - 1] + 1,
        // is costed (a tie goes to the lower bin). A small node has few bins in use.
        int used[kMaxBins], m = 0;
        for (int k = 0; k < bins; ++k) {
            used[m] = k;
            m += binned.count[axis][k] > 0;  // no branch
        }
        // Right-hand sides (bins used[j] .. used[m - 1]), swept from the right.
        float right_area[kMaxBins];
        std::uint32_t right_count[kMaxBins];
        Box4 box = Box4::empty();
        std::uint32_t count = 0;
        for (int j = m - 1; j >= 1; --j) {
            box.grow(binned.box[axis][used[j]]);
            count += binned.count[axis][used[j]];
            right_area[j] = box.aabb().surface_area();
            right_count[j] = count;
        }
        box = Box4::empty();
        count = 0;
        for (int j = 1; j < m; ++j) {
            box.grow(binned.box[axis][used[j - 1]]);
            count += binned.count[axis][used[j - 1]];
            const float cost = options.traversal_cost + (box.aabb().surface_area() * float(count) +
                                                         right_area[j] * float(right_count[j])) *
                                                            inv_area;
            if (cost < best.cost) {
                best.axis = axis;
                best.bin = used[j - 1] + 1;
                best.cost = cost;
            }
        }
    }
    if (best.axis >= 0) {  // the two sides' boxes and counts, from the chosen axis's bins
        best.centroid_lo = centroids.min[best.axis];
        best.scale = scale[best.axis];
        for (int k = 0; k < bins; ++k) {
            if (binned.count[best.axis][k] == 0) continue;
            (k < best.bin ? best.left_bounds : best.right_bounds)
                .grow(binned.box[best.axis][k].aabb());
            (k < best.bin ? best.left_count : best.right_count) += binned.count[best.axis][k];
        }
    }
    return best;
}

// A node still to build: its index in the node array being built, and its primitives.
struct BuildTask {
    std::uint32_t node;
    std::uint32_t begin, end;
    int depth;
};

// What splitting a task decided: its primitives [begin, mid) go left and [mid, end) right, with
// those boxes; mid == begin means the node is a leaf.
struct Split {
    std::uint32_t mid;
    Aabb left_bounds, right_bounds;
};

// Top-down building over a work list instead of recursion: a degenerate mesh may make a deep tree.
class TreeBuilder {
  public:
    TreeBuilder(std::vector<BvhPrimitive>& prims, const BvhBuildOptions& options, Bvh& bvh)
        : prims_(prims), options_(options), bvh_(bvh) {}

    // Decides the task's node and partitions its primitives; a leaf's ids go to bvh.primitives.
    // Touches only the task's own range, so tasks of disjoint ranges may run side by side.
    Split split(const BuildTask& task) const {
        Split s{task.begin, {}, {}};
        s.mid = partition(task, s.left_bounds, s.right_bounds);
        if (s.mid == task.end) s.mid = task.begin;  // defensively: an empty side makes a leaf
        if (s.mid == task.begin)
            for (std::uint32_t i = task.begin; i < task.end; ++i) bvh_.primitives[i] = prims_[i].id;
        return s;
    }

    // Writes the split into task.node: a leaf, or two children (boxes set, adjacent) appended to
    // `nodes`, whose tasks go to `tasks`, left task last.
    static void attach(const BuildTask& task, const Split& s, std::vector<BvhNode>& nodes,
                       std::vector<BuildTask>& tasks) {
        if (s.mid == task.begin) {
            nodes[task.node].first = task.begin;
            nodes[task.node].count = task.end - task.begin;
            return;
        }
        const std::uint32_t left = std::uint32_t(nodes.size());
        nodes.push_back(BvhNode{s.left_bounds.min, 0, s.left_bounds.max, 0});
        nodes.push_back(BvhNode{s.right_bounds.min, 0, s.right_bounds.max, 0});
        nodes[task.node].first = left;
        nodes[task.node].count = 0;
        tasks.push_back({left + 1, s.mid, task.end, task.depth + 1});
        tasks.push_back({left, task.begin, s.mid, task.depth + 1});
    }

    // Builds the subtree of `task` into `nodes`, its root at task.node.
    void build_subtree(BuildTask task, std::vector<BvhNode>& nodes) const {
        std::vector<BuildTask> tasks{task};
        while (!tasks.empty()) {
            const BuildTask next = tasks.back();
            tasks.pop_back();
            attach(next, split(next), nodes, tasks);
        }
    }

  private:
    // Where the task's primitives split: the first index of the right side, or task.begin when
    // the SAH says a leaf costs less (or the node is small or deep enough to be one).
    std::uint32_t partition(const BuildTask& task, Aabb& left_bounds, Aabb& right_bounds) const {
        const std::uint32_t count = task.end - task.begin;
        SahSplit split;
        if (count > std::uint32_t(options_.max_leaf_size) && task.depth < kBvhMaxDepth)
            split = sah_split(prims_, task.begin, task.end, options_);
        if (split.axis < 0 || !(split.cost < float(count))) return task.begin;
        // Partition by the very same bin computation the split was chosen with.
        const int axis = split.axis;
        const int bins = std::clamp(options_.bins, 2, kMaxBins);
        const auto left_side = [&](const BvhPrimitive& p) {
            return bin_of(p.centroid[axis], split.centroid_lo, split.scale, bins) < split.bin;
        };
        return partition_growing(task.begin, task.end, left_side, left_bounds, right_bounds);
    }

    // std::partition's own steps (so the order, and the tree, are the same), growing each side's
    // box from the primitives it really gets as they are placed: one pass instead of two. The
    // boxes do not come from the split's bins, so the tree stays valid even if the compiler
    // evaluated bin_of a little differently here than in sah_split (as -ffast-math allows).
    template <typename LeftSide>
    std::uint32_t partition_growing(std::uint32_t first, std::uint32_t last, LeftSide left_side,
                                    Aabb& left_bounds, Aabb& right_bounds) const {
        for (;;) {
            while (first != last && left_side(prims_[first]))
                left_bounds.grow(prims_[first++].bounds);
            if (first == last) return first;
            --last;  // prims_[first] goes right: find a left one from the end to swap it with
            while (first != last && !left_side(prims_[last]))
                right_bounds.grow(prims_[last--].bounds);
            if (first == last) {
                right_bounds.grow(prims_[first].bounds);
                return first;
            }
            std::swap(prims_[first], prims_[last]);
            left_bounds.grow(prims_[first++].bounds);
            right_bounds.grow(prims_[last].bounds);
        }
    }

    std::vector<BvhPrimitive>& prims_;
    const BvhBuildOptions& options_;
    Bvh& bvh_;
};

// Copies a subtree built with its root at local index 0 into `nodes`: its root to `root` (a
// node already there), the others from `offset` on, child links moved along.
void place_subtree(const std::vector<BvhNode>& sub, std::uint32_t root, std::uint32_t offset,
                   std::vector<BvhNode>& nodes) {
    const auto place = [&](std::uint32_t local) { return local == 0 ? root : offset + local - 1; };
    for (std::uint32_t local = 0; local < sub.size(); ++local) {
        BvhNode node = sub[local];
        if (!node.is_leaf()) node.first = place(node.first);
        nodes[place(local)] = node;
    }
}

}  // namespace

// Top-down: split while the SAH says splitting pays, children stored next to each other.
void build(std::vector<BvhPrimitive> prims, const BvhBuildOptions& options, Bvh& bvh) {
    bvh = Bvh{};
    if (prims.empty()) return;
    const std::uint32_t n = std::uint32_t(prims.size());
    bvh.primitives.resize(n);
    const TreeBuilder builder(prims, options, bvh);
    const int threads = default_thread_count();

    bvh.nodes.push_back(BvhNode{});  // the root; its box is set once it is split (below)

    // Nodes of many primitives are split a level at a time, the nodes of a level side by side;
    // below kSubtree primitives a node's whole subtree is one job. Neither depends on the
    // number of threads, so the tree and its layout are the same on every run.
    constexpr std::uint32_t kSubtree = 16384;  // on the bunny, 1024-8192 and 32768 were slower
    std::vector<BuildTask> level{{0, 0, n, 1}}, jobs;
    while (!level.empty()) {
        std::vector<Split> splits(level.size());
        parallel_for(level.size(), threads,
                     [&](std::size_t i) { splits[i] = builder.split(level[i]); });
        std::vector<BuildTask> next;
        for (std::size_t i = 0; i < level.size(); ++i)
            TreeBuilder::attach(level[i], splits[i], bvh.nodes, next);
        level.clear();
        for (const BuildTask& task : next)
            (task.end - task.begin > kSubtree ? level : jobs).push_back(task);
    }

    // The root's box is its children's (a pass over every primitive only for it would cost
    // as much as a level), or its primitives' when it is a leaf.
    BvhNode& root = bvh.nodes[0];
    Aabb root_bounds;
    if (root.is_leaf()) {
        for (const BvhPrimitive& p : prims) root_bounds.grow(p.bounds);
    } else {
        root_bounds = bvh.nodes[root.first].bounds();
        root_bounds.grow(bvh.nodes[root.first + 1].bounds());
    }
    root.min = root_bounds.min;
    root.max = root_bounds.max;

    // The jobs, largest first, each into a vector of its own (its root at local index 0).
    std::vector<std::size_t> order(jobs.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return jobs[a].end - jobs[a].begin > jobs[b].end - jobs[b].begin;
    });
    std::vector<std::vector<BvhNode>> sub(jobs.size());
    parallel_for(order.size(), threads, [&](std::size_t k) {
        const BuildTask& job = jobs[order[k]];
        std::vector<BvhNode>& nodes = sub[order[k]];
        nodes.reserve(2 * std::size_t(job.end - job.begin));
        nodes.push_back(bvh.nodes[job.node]);
        builder.build_subtree({0, job.begin, job.end, job.depth}, nodes);
    });
    // Each subtree after the nodes above them, in the order the jobs were found.
    std::vector<std::uint32_t> offset(jobs.size());
    std::size_t total = bvh.nodes.size();
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        offset[i] = std::uint32_t(total);
        total += sub[i].size() - 1;
    }
    bvh.nodes.resize(total);
    parallel_for(jobs.size(), threads,
                 [&](std::size_t i) { place_subtree(sub[i], jobs[i].node, offset[i], bvh.nodes); });
}

// Depth-first, nearer child first, skipping whatever starts beyond the nearest hit so far.
bool nearest(const PreparedScene& scene, const Bvh& bvh, const Ray& ray, Interval t_range,
             Hit& hit) {
    bool found = false;
    const auto test = [&](auto id) {  // a hit shrinks the range: what follows must be nearer
        if (intersect_primitive(scene, id, ray, t_range, hit)) {
            found = true;
            t_range.max = hit.t;
        }
    };
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
        test(Scene::primitive_id(Scene::Kind::Plane, i));
    if (!bvh.built()) return found;

    const std::vector<BvhNode>& nodes = bvh.nodes;
    const SlabRay slab_ray(ray, Real(1) / ray.direction);
    struct Entry {
        std::uint32_t node;
        Real t;
    };
    Entry stack[kBvhMaxDepth];
    int top = 0;
    Real t_root;
    if (slab_test(nodes[0], slab_ray, t_range, t_root)) stack[top++] = {0, t_root};
    while (top > 0) {
        const Entry entry = stack[--top];
        if (entry.t > t_range.max) continue;  // a nearer hit was found after it was pushed
        const BvhNode* node = &nodes[entry.node];
        while (node && !node->is_leaf()) {
            const BvhNode* near = &nodes[node->first];
            const BvhNode* far = near + 1;
            Real t_near, t_far;
            const bool hit_near = slab_test(*near, slab_ray, t_range, t_near);
            const bool hit_far = slab_test(*far, slab_ray, t_range, t_far);
            if (hit_near && hit_far) {  // the nearer first (the left on a tie), the other waits
                if (t_far < t_near) {
                    std::swap(near, far);
                    std::swap(t_near, t_far);
                }
                stack[top++] = {std::uint32_t(far - nodes.data()), t_far};
            }
            node = hit_near ? near : hit_far ? far : nullptr;
        }
        if (!node) continue;
        for (std::uint32_t k = node->first; k < node->first + node->count; ++k)
            test(bvh.primitives[k]);
    }
    return found;
}

// Any order will do: the first hit ends the search.
bool any(const PreparedScene& scene, const Bvh& bvh, const Ray& ray, Interval t_range) {
    Hit scratch;
    for (std::size_t i = 0; i < scene.planes.size(); ++i)
        if (intersect_primitive(scene, Scene::primitive_id(Scene::Kind::Plane, i), ray, t_range,
                                scratch))
            return true;
    if (!bvh.built()) return false;

    const std::vector<BvhNode>& nodes = bvh.nodes;
    const SlabRay slab_ray(ray, Real(1) / ray.direction);
    bool found = false;
    std::uint32_t stack[kBvhMaxDepth];  // depth-first: at most one pending sibling per level
    int top = 0;
    Real t_root;
    if (slab_test(nodes[0], slab_ray, t_range, t_root)) stack[top++] = 0;
    while (top > 0 && !found) {
        const BvhNode* node = &nodes[stack[--top]];
        while (node && !node->is_leaf()) {  // descend, the right child first (no order is needed)
            Real t_left, t_right;
            const bool hit_left = slab_test(nodes[node->first], slab_ray, t_range, t_left);
            const bool hit_right = slab_test(nodes[node->first + 1], slab_ray, t_range, t_right);
            if (hit_left && hit_right) stack[top++] = node->first;
            node = hit_right ? &nodes[node->first + 1] : hit_left ? &nodes[node->first] : nullptr;
        }
        if (!node) continue;
        for (std::uint32_t k = node->first; k < node->first + node->count && !found; ++k) {
            found = intersect_primitive(scene, bvh.primitives[k], ray, t_range, scratch);
        }
    }
    return found;
}

}  // namespace rt::bench::tuned
