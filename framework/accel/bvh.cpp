#include <cmath>
#include <limits>
#include <unordered_map>

#include "accel/bvh.h"

#include <atomic>

#include "core/not_implemented.h"

namespace rt {

namespace {

std::string node_name(std::size_t i) {
    return "node " + std::to_string(i);
}

}  // namespace

std::string validate_bvh(const Bvh& bvh, const std::vector<BvhPrimitive>& input) {
    if (input.empty())
        return bvh.nodes.empty() ? "" : "the tree has nodes but there are no primitives";
    if (bvh.nodes.empty())
        return "the tree is empty but there are " + std::to_string(input.size()) + " primitives";
    const std::size_t n = bvh.nodes.size();
    if (n > 2 * input.size())
        return "the tree has " + std::to_string(n) + " nodes, more than 2 x " +
               std::to_string(input.size()) + " primitives: some nodes are empty or unreachable";

    // Bounds of each input id, and how often each id appears in a leaf.
    // Ids are sparse (the kind sits in the top bits), so a map rather than a table.
    std::unordered_map<std::uint32_t, int> index_of;
    index_of.reserve(input.size());
    for (std::size_t i = 0; i < input.size(); ++i) index_of.emplace(input[i].id, int(i));
    std::vector<int> seen(input.size(), 0);

    std::vector<std::uint32_t> parent(n, std::numeric_limits<std::uint32_t>::max());
    std::vector<char> reached(n, 0);
    reached[0] = 1;
    for (std::size_t i = 0; i < n; ++i) {
        const BvhNode& node = bvh.nodes[i];
        if (!reached[i]) return node_name(i) + " is not reachable from the root";
        const Aabb box = node.bounds();
        if (node.is_leaf()) {
            if (std::size_t(node.first) + node.count > bvh.primitives.size())
                return node_name(i) + " (a leaf) lists primitives [" + std::to_string(node.first) +
                       ", " + std::to_string(node.first + node.count) + ") but there are only " +
                       std::to_string(bvh.primitives.size());
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
                const std::uint32_t id = bvh.primitives[k];
                const auto found = index_of.find(id);
                if (found == index_of.end())
                    return node_name(i) + " holds primitive id " + std::to_string(id) +
                           ", which was not in the input";
                const BvhPrimitive& p = input[std::size_t(found->second)];
                if (++seen[std::size_t(found->second)] > 1)
                    return "primitive id " + std::to_string(id) +
                           " is in more than one leaf (again in " + node_name(i) + ")";
                if (!box.contains(p.bounds))
                    return node_name(i) + "'s box does not contain its primitive id " +
                           std::to_string(id);
            }
        } else {
            std::size_t left = node.first;
            if (left <= i || left + 1 >= n)
                return node_name(i) + " has children " + std::to_string(left) + " and " +
                       std::to_string(left + 1) +
                       ": children must come after their parent and exist (" + std::to_string(n) +
                       " nodes)";
            for (std::size_t c : {left, left + 1}) {
                if (reached[c])
                    return node_name(c) + " has two parents (" + std::to_string(parent[c]) +
                           " and " + std::to_string(i) + ")";
                reached[c] = 1;
                parent[c] = std::uint32_t(i);
                if (!box.contains(bvh.nodes[c].bounds()))
                    return node_name(c) + "'s box is not inside its parent " + node_name(i) +
                           "'s box";
            }
        }
    }
    for (std::size_t i = 0; i < input.size(); ++i)
        if (seen[i] == 0) return "primitive id " + std::to_string(input[i].id) + " is in no leaf";
    if (int depth = bvh_depth(bvh); depth > kBvhMaxDepth)
        return "the tree is " + std::to_string(depth) +
               " levels deep, more than kBvhMaxDepth = " + std::to_string(kBvhMaxDepth) +
               ": make nodes at that depth leaves";
    return "";
}

int bvh_depth(const Bvh& bvh) {
    if (bvh.nodes.empty()) return 0;
    std::vector<int> depth(bvh.nodes.size(), 0);
    depth[0] = 1;
    int deepest = 1;
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {  // children come after parents
        const BvhNode& node = bvh.nodes[i];
        deepest = std::max(deepest, depth[i]);
        if (!node.is_leaf() && node.first + 1 < bvh.nodes.size())
            depth[node.first] = depth[node.first + 1] = depth[i] + 1;
    }
    return deepest;
}

void count_missing_bvh() {
    static std::atomic<bool> reported{true};  // build_bvh's own stub already printed where to read
    report_not_implemented("build_bvh", __FILE__, __LINE__,
                           "stages/06-bvh/README.md#building-the-tree", reported);
}

}  // namespace rt
