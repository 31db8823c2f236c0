// Stage 06 build tests: the SAH split (checked against the cost model evaluated independently
// here) and the invariants of whole trees (validate_bvh) over several meshes and hard inputs.
#include <cmath>
#include <cstring>

#include "bvh_test_support.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

using bvh_test::Random;
using bvh_test::scene_from_mesh;

RT_TEST_SUITE(SahSplitCost, "the-surface-area-heuristic");
RT_TEST_SUITE(BvhBuild, "building-the-tree");

BvhPrimitive box_primitive(Vec3f lo, Vec3f hi, std::uint32_t id) {
    BvhPrimitive p;
    p.bounds = Aabb{lo, hi};
    p.centroid = p.bounds.center();
    p.id = id;
    return p;
}

// The SAH cost of putting bins [0, k) of `axis` left, computed from scratch, or +inf when a
// side is empty.
float reference_cost(const std::vector<BvhPrimitive>& prims, int axis, int k,
                     const BvhBuildOptions& o) {
    Aabb all, centroids, left, right;
    for (const auto& p : prims) {
        all.grow(p.bounds);
        centroids.grow(p.centroid);
    }
    std::uint32_t n_left = 0, n_right = 0;
    const float scale = float(o.bins) / (centroids.max[axis] - centroids.min[axis]);
    for (const auto& p : prims) {
        if (bin_of(p.centroid[axis], centroids.min[axis], scale, o.bins) < k) {
            left.grow(p.bounds);
            ++n_left;
        } else {
            right.grow(p.bounds);
            ++n_right;
        }
    }
    if (n_left == 0 || n_right == 0) return std::numeric_limits<float>::infinity();
    return o.traversal_cost +
           (left.surface_area() * float(n_left) + right.surface_area() * float(n_right)) /
               all.surface_area();
}

TEST_F(SahSplitCost, TwoClustersSplitBetweenThem) {
    std::vector<BvhPrimitive> prims;
    for (std::uint32_t i = 0; i < 8; ++i) {  // four small boxes near x = 0, four near x = 10
        const float x = i < 4 ? float(i) * 0.1f : 10 + float(i) * 0.1f;
        prims.push_back(box_primitive({x, 0, 0}, {x + 0.05f, 1, 1}, i));
    }
    const SahSplit split = find_sah_split(prims, 0, prims.size(), BvhBuildOptions{});
    ASSERT_EQ(split.axis, 0) << "the clusters are apart along x";
    EXPECT_EQ(split.left_count, 4u);
    EXPECT_EQ(split.right_count, 4u);
    EXPECT_LE(split.left_bounds.max.x, 1.0f);
    EXPECT_GE(split.right_bounds.min.x, 10.0f);
}

TEST_F(SahSplitCost, CostIsTheMinimumOverAllBinBoundaries) {
    Random random(6);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<BvhPrimitive> prims;
        const int n = 5 + trial * 7;
        for (int i = 0; i < n; ++i) {
            const Vec3 c = random.vec(-1, 1) * Vec3(1, Real(0.5) + Real(trial % 3), Real(0.25));
            const Vec3 h = random.vec(Real(0.01), Real(0.2));
            prims.push_back(box_primitive(Vec3f(c - h), Vec3f(c + h), std::uint32_t(i)));
        }
        BvhBuildOptions options;
        options.bins = 4 + trial % 13;
        const SahSplit split = find_sah_split(prims, 0, prims.size(), options);
        float best = std::numeric_limits<float>::infinity();
        int best_axis = -1, best_bin = 0;
        for (int axis = 0; axis < 3; ++axis)
            for (int k = 1; k < options.bins; ++k) {
                const float cost = reference_cost(prims, axis, k, options);
                if (cost < best) {
                    best = cost;
                    best_axis = axis;
                    best_bin = k;
                }
            }
        ASSERT_EQ(split.axis, best_axis) << "trial " << trial;
        EXPECT_EQ(split.bin, best_bin) << "trial " << trial;
        EXPECT_NEAR(split.cost, best, 1e-4f * best) << "trial " << trial;
        EXPECT_EQ(split.left_count + split.right_count, std::uint32_t(n));
        // The split carries what the partition needs: it must reproduce left_count.
        std::uint32_t left = 0;
        for (const BvhPrimitive& p : prims)
            left += bin_of(p.centroid[split.axis], split.centroid_lo, split.scale, options.bins) <
                    split.bin;
        EXPECT_EQ(left, split.left_count)
            << "trial " << trial << ": centroid_lo and scale do not reproduce the split";
    }
}

TEST_F(SahSplitCost, OnlyTheGivenRangeCounts) {
    std::vector<BvhPrimitive> prims;
    for (std::uint32_t i = 0; i < 10; ++i)
        prims.push_back(box_primitive({float(i), 0, 0}, {float(i) + 0.5f, 1, 1}, i));
    const SahSplit split = find_sah_split(prims, 2, 6, BvhBuildOptions{});
    ASSERT_EQ(split.axis, 0);
    EXPECT_EQ(split.left_count + split.right_count, 4u);
    EXPECT_GE(split.left_bounds.min.x, 2.0f);
    EXPECT_LE(split.right_bounds.max.x, 5.5f);
}

TEST_F(SahSplitCost, CoincidentCentroidsHaveNoSplit) {
    std::vector<BvhPrimitive> prims;
    for (std::uint32_t i = 0; i < 6; ++i)  // nested boxes around one centre
        prims.push_back(box_primitive(Vec3f(-float(i + 1)), Vec3f(float(i + 1)), i));
    EXPECT_EQ(find_sah_split(prims, 0, prims.size(), BvhBuildOptions{}).axis, -1);
}

TEST_F(SahSplitCost, SkipsAxesWithoutSpread) {
    std::vector<BvhPrimitive> prims;  // all centroids on a line along z
    for (std::uint32_t i = 0; i < 9; ++i)
        prims.push_back(box_primitive({-1, -1, float(i)}, {1, 1, float(i) + 0.2f}, i));
    const SahSplit split = find_sah_split(prims, 0, prims.size(), BvhBuildOptions{});
    EXPECT_EQ(split.axis, 2);
}

void expect_valid_tree(const Scene& scene, const BvhBuildOptions& options, const char* what) {
    const std::vector<BvhPrimitive> input = bvh_primitives(scene);
    Bvh bvh;
    build_bvh(input, options, bvh);
    EXPECT_EQ(validate_bvh(bvh, input), "") << what;
    // Leaves hold at most max_leaf_size primitives unless their centroids could not be split.
    for (const BvhNode& node : bvh.nodes) {
        if (!node.is_leaf() || node.count <= std::uint32_t(options.max_leaf_size)) continue;
        Aabb centroids;
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
            for (const BvhPrimitive& p : input)
                if (p.id == bvh.primitives[k]) centroids.grow(p.centroid);
        const bool splittable = glm::any(glm::lessThan(centroids.min, centroids.max));
        // A splittable oversize leaf is allowed only where the SAH says a leaf is cheaper.
        if (splittable) {
            std::vector<BvhPrimitive> leaf;
            for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
                for (const BvhPrimitive& p : input)
                    if (p.id == bvh.primitives[k]) leaf.push_back(p);
            EXPECT_GE(find_sah_split(leaf, 0, leaf.size(), options).cost, float(node.count))
                << what << ": a leaf of " << node.count
                << " primitives that a split would make cheaper";
        }
    }
}

TEST_F(BvhBuild, TreesOverProceduralMeshesAreValid) {
    expect_valid_tree(scene_from_mesh(make_icosphere(3)), {}, "icosphere");
    expect_valid_tree(scene_from_mesh(make_torus(40, 20)), {}, "torus");
    expect_valid_tree(scene_from_mesh(make_terrain(30, 30, 4)), {}, "terrain");
    expect_valid_tree(scene_from_mesh(make_triangle_soup(2000, 9)), {}, "soup");
    BvhBuildOptions options;
    options.max_leaf_size = 1;
    options.bins = 2;
    expect_valid_tree(scene_from_mesh(make_torus(30, 12)), options, "torus, 2 bins, leaves of 1");
    options.max_leaf_size = 16;
    options.bins = 64;
    options.traversal_cost = 4;
    expect_valid_tree(scene_from_mesh(make_icosphere(2)), options,
                      "icosphere, 64 bins, leaves of 16");
}

TEST_F(BvhBuild, SmallAndEmptyInputs) {
    Bvh bvh;
    build_bvh({}, BvhBuildOptions{}, bvh);
    EXPECT_TRUE(bvh.nodes.empty()) << "no primitives: no nodes";
    for (std::uint32_t n : {1u, 2u, 3u, 5u}) {
        std::vector<BvhPrimitive> prims;
        for (std::uint32_t i = 0; i < n; ++i)
            prims.push_back(
                box_primitive({10.0f * float(i), 0, 0}, {10.0f * float(i) + 1, 1, 1}, 100 + i));
        BvhBuildOptions options;  // boxes far apart: the SAH splits down to single primitives
        options.max_leaf_size = 1;
        build_bvh(prims, options, bvh);
        EXPECT_EQ(validate_bvh(bvh, prims), "") << n << " primitives";
        EXPECT_EQ(bvh.nodes.size(), 2 * n - 1) << n << " primitives, leaves of one";
    }
}

TEST_F(BvhBuild, DegenerateInputs) {
    // Identical triangles: nothing to split, one leaf holds them all.
    Scene same;
    same.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 50; ++i) same.triangles.push_back(Triangle{{0, 1, 2}, 0});
    expect_valid_tree(same, {}, "50 identical triangles");
    // Sliver triangles all in one plane, and a mix of sizes over ten orders of magnitude.
    Scene flat;
    Random random(3);
    for (std::uint32_t i = 0; i < 300; ++i) {
        const Real s = std::pow(Real(10), Real(random.uniform(-5, 5)));
        const Vec3 c = random.vec(-100, 100);
        flat.vertices.push_back({c.x, 0, c.z});
        flat.vertices.push_back({c.x + s, 0, c.z});
        flat.vertices.push_back({c.x, 0, c.z + s * Real(1e-3)});
        flat.triangles.push_back(Triangle{{3 * i, 3 * i + 1, 3 * i + 2}, 0});
    }
    expect_valid_tree(flat, {}, "flat slivers of many scales");
}

TEST_F(BvhBuild, DepthIsBoundedOnPathologicalSpacing) {
    // Centroids at 2.2^i with 2 bins: the only boundary peels off the largest primitive, so the
    // SAH alone would go 100 levels deep (2^i with 16 bins stops at 27, below the limit).
    std::vector<BvhPrimitive> prims;
    for (std::uint32_t i = 0; i < 100; ++i) {
        const float x = float(std::pow(2.2, double(i)));
        prims.push_back(box_primitive({x, 0, 0}, {x, 1, 1}, i));
    }
    BvhBuildOptions options;
    options.max_leaf_size = 1;
    options.bins = 2;
    Bvh bvh;
    build_bvh(prims, options, bvh);
    EXPECT_EQ(validate_bvh(bvh, prims), "");
    EXPECT_EQ(bvh_depth(bvh), kBvhMaxDepth)
        << "the root has depth 1 and a node at depth kBvhMaxDepth (64) is a leaf (step 2)";
}

TEST_F(BvhBuild, LeafWhenNoSplitPays) {
    // Eight 2x2x2 boxes almost on top of each other, centroids 0.01 apart along x: every split
    // costs about 1 + 8 > N = 8, so the SAH keeps one leaf of 8 though max_leaf_size is 4.
    std::vector<BvhPrimitive> prims;
    for (std::uint32_t i = 0; i < 8; ++i) {
        const float x = 0.01f * float(i);
        prims.push_back(box_primitive({x - 1, -1, -1}, {x + 1, 1, 1}, i));
    }
    const BvhBuildOptions options;
    for (int k = 1; k < options.bins; ++k)  // the premise, from the cost model itself
        ASSERT_GE(reference_cost(prims, 0, k, options), 8.0f) << "boundary " << k;
    Bvh bvh;
    build_bvh(prims, options, bvh);
    EXPECT_EQ(validate_bvh(bvh, prims), "");
    EXPECT_EQ(bvh.nodes.size(), 1u)
        << "every split costs at least N = 8, yet the root was split: a node whose best split "
           "costs at least as much as the leaf is a leaf (step 2)";
}

TEST_F(BvhBuild, TreeIsDeterministic) {
    // A small mesh and one large enough for a builder to use threads (the reference does from
    // 20,000 primitives): the same tree, bit for bit, every time.
    for (const Scene& scene :
         {scene_from_mesh(make_terrain(40, 40, 2)), scene_from_mesh(make_icosphere(6))}) {
        Bvh a, b;
        build_bvh(bvh_primitives(scene), {}, a);
        build_bvh(bvh_primitives(scene), {}, b);
        ASSERT_EQ(a.nodes.size(), b.nodes.size());
        EXPECT_EQ(0, std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)));
        EXPECT_EQ(a.primitives, b.primitives);
        EXPECT_EQ(validate_bvh(a, bvh_primitives(scene)), "");
    }
}

TEST_F(BvhBuild, SahTreeCostIsLowAndMoreBinsDoNoWorse) {
    // The expected cost of a ray through the tree (sum over nodes of area ratio times work): far
    // below testing every primitive, and no worse with 16 bins than with 2.
    const Scene scene = scene_from_mesh(make_terrain(60, 60, 5));
    const std::vector<BvhPrimitive> input = bvh_primitives(scene);
    Bvh sah;
    build_bvh(input, {}, sah);
    ASSERT_FALSE(sah.nodes.empty()) << "build_bvh produced no nodes";
    auto expected_cost = [](const Bvh& bvh) {
        const float root = bvh.nodes[0].bounds().surface_area();
        double cost = 0;
        for (const BvhNode& node : bvh.nodes)
            cost += double(node.bounds().surface_area() / root) *
                    (node.is_leaf() ? double(node.count) : 1.0);
        return cost;
    };
    EXPECT_LT(expected_cost(sah), 0.1 * double(input.size()))
        << "the SAH tree is barely better than no tree";
    BvhBuildOptions two_bins;
    two_bins.bins = 2;
    Bvh coarse;
    build_bvh(input, two_bins, coarse);
    ASSERT_FALSE(coarse.nodes.empty()) << "build_bvh produced no nodes with 2 bins";
    EXPECT_LE(expected_cost(sah), expected_cost(coarse))
        << "16 bins should do at least as well as 2";
}

}  // namespace
}  // namespace rt
