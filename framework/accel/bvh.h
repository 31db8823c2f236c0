// The data of a bounding volume hierarchy (stage 06), in flat arrays so that the GPU port can
// upload it as two storage buffers unchanged. The builder and the traversal are student code
// (stages/06-bvh/bvh.cpp, declared in stage_api/stage06.h); this file holds only what the
// framework needs to store, check and draw a tree.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/real.h"

namespace rt {

using Vec3f = glm::vec3;

// An axis-aligned bounding box in float, whatever Real is: bounds are conservative (rounded
// outwards), so float is enough, and it keeps a node at 32 bytes. The empty box has min = +inf,
// max = -inf, so that growing it by anything gives that thing.
struct Aabb {
    Vec3f min{std::numeric_limits<float>::infinity()};
    Vec3f max{-std::numeric_limits<float>::infinity()};

    bool empty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
    void grow(const Vec3f& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void grow(const Aabb& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    Vec3f extent() const { return max - min; }
    Vec3f center() const { return (min + max) * 0.5f; }
    // Surface area; 0 for the empty box (so empty bins cost nothing in the SAH).
    float surface_area() const {
        if (empty()) return 0;
        Vec3f e = extent();
        return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
    bool contains(const Aabb& b) const {
        return glm::all(glm::lessThanEqual(min, b.min)) && glm::all(glm::lessThanEqual(b.max, max));
    }
};

// One node, 32 bytes: two cache lines hold four nodes.
//   interior node (count == 0): children are nodes[first] and nodes[first + 1]
//   leaf (count > 0):           primitives are Bvh::primitives[first .. first + count)
struct BvhNode {
    Vec3f min;
    std::uint32_t first = 0;
    Vec3f max;
    std::uint32_t count = 0;

    bool is_leaf() const { return count > 0; }
    Aabb bounds() const { return Aabb{min, max}; }
};
static_assert(sizeof(BvhNode) == 32, "a BVH node must stay 32 bytes (docs/conventions.md)");

// The deepest a tree may be (the root has depth 1). Traversal keeps a fixed-size stack of this
// many entries (as the GPU port will), so a builder makes a node a leaf at this depth whatever
// its size.
inline constexpr int kBvhMaxDepth = 64;

struct Bvh {
    std::vector<BvhNode> nodes;             // nodes[0] is the root; empty when nothing was built
    std::vector<std::uint32_t> primitives;  // global primitive ids (Scene::primitive_id)

    bool built() const { return !nodes.empty(); }
};

// Counters of one traversal, for the heat map and the tests.
struct BvhStats {
    std::uint32_t nodes_visited = 0;      // nodes whose box was tested
    std::uint32_t primitives_tested = 0;  // primitive intersection tests
};

// What the builder is given for each primitive: its bounds, the centre of those bounds (what
// the SAH bins) and its global primitive id.
struct BvhPrimitive {
    Aabb bounds;
    Vec3f centroid{0};
    std::uint32_t id = 0;
};

// Checks a built tree against `primitive_count` primitives given as `input`: every node index
// in range and pointing forwards (so there is no cycle), every leaf range inside `primitives`,
// every input id in exactly one leaf, each child box inside its parent and each leaf box around
// its primitives, and depth at most kBvhMaxDepth. Returns "" for a valid tree, otherwise the first problem, one line.
std::string validate_bvh(const Bvh& bvh, const std::vector<BvhPrimitive>& input);

// Depth of the tree (a root-only tree has depth 1), 0 when empty.
int bvh_depth(const Bvh& bvh);

// Counts a stub call for a query that needed the BVH that a stubbed build_bvh did not make
// (nearest_hit, render/nearest_hit.h): the image comes out magenta, as for any other stub.
void count_missing_bvh();

}  // namespace rt
