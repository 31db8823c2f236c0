// `rt bvh-dump` and `rt bvh-cost` (bvh_cost.h).
#include "apps/bvh_cost.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "accel/bvh.h"
#include "core/text_file.h"
#include "render/camera_ray.h"
#include "render/prepare.h"
#include "scene/bvh_primitives.h"
#include "scene/scene_loader.h"
#include "stage_api/stage06.h"

namespace rt {
namespace {

// The tree file: this magic, the node and primitive counts (uint64 each), the nodes as they are
// in memory (32 bytes each) and the primitive ids (uint32 each), in this machine's byte order.
constexpr char kMagic[8] = {'R', 'T', 'B', 'V', 'H', '1', '\n', '\0'};
constexpr std::uint64_t kMaxEntries = std::uint64_t(1) << 26;

void append_bytes(std::string& out, const void* data, std::size_t size) {
    out.append(static_cast<const char*>(data), size);
}

std::string encode_tree(const Bvh& bvh) {
    std::string out;
    const std::uint64_t nodes = bvh.nodes.size();
    const std::uint64_t primitives = bvh.primitives.size();
    append_bytes(out, kMagic, sizeof kMagic);
    append_bytes(out, &nodes, sizeof nodes);
    append_bytes(out, &primitives, sizeof primitives);
    append_bytes(out, bvh.nodes.data(), nodes * sizeof(BvhNode));
    append_bytes(out, bvh.primitives.data(), primitives * sizeof(std::uint32_t));
    return out;
}

// The tree in `bytes`, or a runtime_error naming what is wrong with the file.
Bvh decode_tree(const std::string& bytes, const std::string& file) {
    const std::size_t header = sizeof kMagic + 2 * sizeof(std::uint64_t);
    if (bytes.size() < header || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        throw std::runtime_error(file + ": not a tree written by rt bvh-dump");
    std::uint64_t nodes = 0;
    std::uint64_t primitives = 0;
    std::memcpy(&nodes, bytes.data() + sizeof kMagic, sizeof nodes);
    std::memcpy(&primitives, bytes.data() + sizeof kMagic + sizeof nodes, sizeof primitives);
    if (nodes > kMaxEntries || primitives > kMaxEntries ||
        bytes.size() != header + nodes * sizeof(BvhNode) + primitives * sizeof(std::uint32_t))
        throw std::runtime_error(file + ": its counts do not match its size");
    Bvh bvh;
    bvh.nodes.resize(nodes);
    bvh.primitives.resize(primitives);
    std::memcpy(bvh.nodes.data(), bytes.data() + header, nodes * sizeof(BvhNode));
    std::memcpy(bvh.primitives.data(), bytes.data() + header + nodes * sizeof(BvhNode),
                primitives * sizeof(std::uint32_t));
    return bvh;
}

PreparedScene prepare_with_bvh(const std::string& scene_file, int width = 0, int height = 0) {
    SceneOverrides overrides;
    overrides.accelerator = Accelerator::Bvh;
    overrides.width = width;
    overrides.height = height;
    PreparedScene scene = prepare_scene(load_scene(scene_file), overrides);
    if (!scene.bvh.built())
        throw std::runtime_error(scene_file + ": no BVH was built (is build_bvh written?)");
    return scene;
}

}  // namespace

int run_bvh_dump(const std::string& scene_file, const std::string& tree_file) {
    const PreparedScene scene = prepare_with_bvh(scene_file);
    write_text(tree_file, encode_tree(scene.bvh));
    return 0;
}

int run_bvh_cost(const std::string& scene_file, const std::string& tree_file, int width,
                 int height) {
    PreparedScene scene = prepare_with_bvh(scene_file, width, height);
    if (!tree_file.empty()) {
        Bvh tree = decode_tree(read_text(tree_file), tree_file);
        const std::string problem = validate_bvh(tree, bvh_primitives(scene));
        if (!problem.empty())
            throw std::runtime_error(tree_file + ": not a valid BVH of " + scene_file + ": " +
                                     problem);
        scene.bvh = std::move(tree);
    }
    double nodes = 0;
    double primitives = 0;
    for (int y = 0; y < scene.image.height; ++y) {
        for (int x = 0; x < scene.image.width; ++x) {
            const Vec2 pixel(Real(x) + Real(0.5), Real(y) + Real(0.5));
            const Ray ray = camera_ray(scene.camera, pixel, scene.image);
            Hit hit;
            BvhStats stats;
            bvh_intersect_nearest(scene, ray, Interval{0, kInfinity}, hit, &stats);
            nodes += stats.nodes_visited;
            primitives += stats.primitives_tested;
        }
    }
    const double rays = double(scene.image.width) * scene.image.height;
    std::printf("traversal cost %.3f per ray: %.3f node visits and %.3f primitive tests per ray\n",
                (nodes + kPrimitiveTestWeight * primitives) / rays, nodes / rays,
                primitives / rays);
    return 0;
}

}  // namespace rt
