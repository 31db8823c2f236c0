#include <cmath>
#include <limits>
#include <unordered_map>

#include "accel/bvh.h"
#include "accel/bvh_input.h"

namespace rt {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// The largest float <= x and the smallest float >= x.
float float_down(Real x) {
    float f = float(x);
    return Real(f) > x ? std::nextafter(f, -kInf) : f;
}
float float_up(Real x) {
    float f = float(x);
    return Real(f) < x ? std::nextafter(f, kInf) : f;
}

Vec3f down(const Vec3& v) {
    return {float_down(v.x), float_down(v.y), float_down(v.z)};
}
Vec3f up(const Vec3& v) {
    return {float_up(v.x), float_up(v.y), float_up(v.z)};
}

std::string node_name(std::size_t i) {
    return "node " + std::to_string(i);
}

}  // namespace

std::vector<BvhPrimitive> bvh_primitives(const Scene& scene) {
    std::vector<BvhPrimitive> out;
    out.reserve(scene.spheres.size() + scene.triangles.size() + scene.boxes.size());
    auto add = [&](const Aabb& box, Scene::Kind kind, std::size_t i) {
        BvhPrimitive p;
        p.bounds = box;
        p.centroid = box.centre();
        p.id = std::uint32_t(scene.primitive_id(kind, i));
        out.push_back(p);
    };
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        Vec3 r(std::abs(s.radius));
        Aabb box{down(s.center - r), up(s.center + r)};
        for (int k = 0; k < 3; ++k) {  // centre +- radius was rounded once: widen by a step
            box.min[k] = std::nextafter(box.min[k], -kInf);
            box.max[k] = std::nextafter(box.max[k], kInf);
        }
        add(box, Scene::Kind::Sphere, i);
    }
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        Vec3 a, b, c;
        scene.triangle_vertices(i, a, b, c);
        Aabb box;
        for (const Vec3& p : {a, b, c}) {
            box.grow(down(p));
            box.grow(up(p));
        }
        add(box, Scene::Kind::Triangle, i);
    }
    for (std::size_t i = 0; i < scene.boxes.size(); ++i)
        add(Aabb{down(scene.boxes[i].min), up(scene.boxes[i].max)}, Scene::Kind::Box, i);
    return out;
}

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

}  // namespace rt
