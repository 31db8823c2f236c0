// The parts of `rt-bench bvh` that decide whether its figures count: the comparison of
// back-ends, the work split, and that a wrong back-end is caught. No timing is looked at.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <sstream>

#include "bench/bvh_bench.h"
#include "bench/tuned_bvh.h"
#include "geometry/procedural_mesh.h"
#include "render/prepare.h"
#include "scene/bvh_primitives.h"
#include "stage_api/stage06.h"

namespace rt::bench {
namespace {

RayResult hit_at(Real t, int primitive) {
    return RayResult{t, primitive};
}
const RayResult kMiss{};

// Equal answers, and a t difference inside the relative tolerance, are no disagreement.
TEST(BvhBench, CompareCountsNothingForEqualAnswers) {
    const std::vector<RayResult> a{hit_at(1, 3), kMiss, hit_at(100, 7)};
    const std::vector<RayResult> b{hit_at(1, 3), kMiss, hit_at(Real(100.005), 7)};
    const Disagreements d = compare_results(a, b, false, 1e-4);
    EXPECT_EQ(d.rays, 3u);
    EXPECT_EQ(d.total(), 0u);
    EXPECT_EQ(d.fraction(), 0.0);
}

// Each kind of difference lands in its own column, one column per ray.
TEST(BvhBench, CompareClassifiesEachDisagreementOnce) {
    const std::vector<RayResult> a{hit_at(1, 3), kMiss, hit_at(2, 4), hit_at(2, 5), hit_at(2, 6)};
    const std::vector<RayResult> b{kMiss, hit_at(1, 3), hit_at(2, 9), hit_at(Real(2.01), 5),
                                   hit_at(5, 8)};
    const Disagreements d = compare_results(a, b, false, 1e-4);
    EXPECT_EQ(d.hit_miss, 2u);   // rays 0 and 1
    EXPECT_EQ(d.primitive, 2u);  // ray 2, and ray 4 (other primitive and other t: counted once)
    EXPECT_EQ(d.t, 1u);          // ray 3: same primitive, t off by 0.5%
    EXPECT_EQ(d.total(), 5u);
    EXPECT_DOUBLE_EQ(d.fraction(), 1.0);
}

// Any-hit rays only say whether something is in the way.
TEST(BvhBench, CompareAnyHitLooksOnlyAtHitOrMiss) {
    const std::vector<RayResult> a{hit_at(0, -1), hit_at(0, -1), kMiss};
    const std::vector<RayResult> b{hit_at(3, 2), kMiss, kMiss};
    const Disagreements d = compare_results(a, b, true, 1e-4);
    EXPECT_EQ(d.hit_miss, 1u);
    EXPECT_EQ(d.primitive + d.t, 0u);
}

// A NaN distance never agrees, and mismatched inputs are a programming error.
TEST(BvhBench, CompareRejectsNaNAndSizeMismatch) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    EXPECT_EQ(compare_results({hit_at(nan, 1)}, {hit_at(1, 1)}, false, 1e-4).t, 1u);
    EXPECT_THROW(compare_results({kMiss}, {}, false, 1e-4), std::logic_error);
}

// The limit is a fraction of the rays, rounded down: a tiny run allows none.
TEST(BvhBench, AllowedDisagreementsRoundDown) {
    EXPECT_EQ(allowed_disagreements(786432, 1e-4), 78u);
    EXPECT_EQ(allowed_disagreements(3072, 1e-4), 0u);
    EXPECT_EQ(allowed_disagreements(1000, 0.0), 0u);
    EXPECT_EQ(allowed_disagreements(1000, 1.0), 1000u);
}

// Every item is handed out exactly once, whatever the thread count and chunk size.
TEST(BvhBench, ParallelForCoversEveryItemOnce) {
    for (int threads : {1, 2, 3, 8})
        for (std::size_t chunk : {std::size_t(1), std::size_t(7), std::size_t(1024)})
            for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(5000)}) {
                std::vector<std::atomic<int>> seen(n);
                parallel_for_chunks(n, chunk, threads, [&](std::size_t begin, std::size_t end) {
                    EXPECT_LE(end - begin, chunk);
                    for (std::size_t i = begin; i < end; ++i) seen[i].fetch_add(1);
                });
                for (std::size_t i = 0; i < n; ++i)
                    ASSERT_EQ(seen[i].load(), 1) << "item " << i << ", " << threads << " threads";
            }
}

PreparedScene mesh_scene(std::string_view shape, std::size_t triangles) {
    const TriangleMesh mesh = make_procedural_mesh(shape, triangles, 1);
    PreparedScene scene;
    scene.vertices = mesh.vertices;
    for (const auto& t : mesh.triangles) scene.triangles.push_back(Triangle{t, 0});
    scene.materials.push_back(Material{});
    refresh_features(scene);
    return scene;
}

PreparedScene small_mesh_scene() {
    return mesh_scene("icosphere", 300);
}

// Rays from outside the unit icosphere towards points near its centre: most hit.
RayBatch rays_at_sphere(std::size_t n, bool any_hit) {
    RayBatch batch;
    batch.any_hit = any_hit;
    for (std::size_t i = 0; i < n; ++i) {
        const Real a = Real(i) * Real(0.37), b = Real(i % 17) * Real(0.11) - Real(0.9);
        const Vec3 origin(3 * std::cos(a), 3 * b, 3 * std::sin(a));
        const Vec3 target(Real(0.2) * std::sin(Real(i)), 0, Real(0.2) * std::cos(Real(3 * i)));
        batch.rays.push_back(Ray{origin, glm::normalize(target - origin)});
        batch.ranges.push_back(Interval{0, kInfinity});
    }
    return batch;
}

std::vector<RayResult> trace(const Backend& backend, const RayBatch& batch) {
    std::vector<RayResult> results(batch.size());
    backend.trace(batch, 0, batch.size(), results.data());
    return results;
}

// The real back-ends agree on this mesh; a back-end that is wrong on every 5th hit is caught on
// exactly those rays, for nearest-hit and any-hit rays alike.
TEST(BvhBench, WrongBackendIsCaught) {
    PreparedScene scene = small_mesh_scene();
    std::unique_ptr<Backend> bvh = make_bvh_backend(scene);
    bvh->build();
    ASSERT_TRUE(scene.bvh.built());
    const std::unique_ptr<Backend> brute = make_brute_force_backend(scene);
    for (bool any_hit : {false, true}) {
        const RayBatch batch = rays_at_sphere(400, any_hit);
        const std::vector<RayResult> expected = trace(*brute, batch);
        const auto hits = std::count_if(expected.begin(), expected.end(),
                                        [](const RayResult& r) { return r.hit(); });
        ASSERT_GT(hits, 300) << "the test rays should mostly hit the sphere";
        EXPECT_EQ(compare_results(expected, trace(*bvh, batch), any_hit, 1e-4).total(), 0u);

        PreparedScene copy = scene;
        std::unique_ptr<Backend> faulty = make_faulty_backend(make_bvh_backend(copy), 5);
        faulty->build();
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < expected.size(); i += 5) wrong += expected[i].hit() ? 1 : 0;
        const Disagreements d = compare_results(expected, trace(*faulty, batch), any_hit, 1e-4);
        EXPECT_EQ(d.total(), wrong);
        EXPECT_EQ(any_hit ? d.hit_miss : d.primitive, wrong);
        EXPECT_GT(d.total(), allowed_disagreements(d.rays, 1e-4));
    }
}

// Node `a` of tree `x` and node `b` of tree `y` head the same subtree: the same boxes (bit for
// bit), the same leaves over the same primitives, whatever the order of the nodes in memory.
void expect_same_subtree(const Bvh& x, std::uint32_t a, const Bvh& y, std::uint32_t b,
                         const std::string& shape) {
    const BvhNode& p = x.nodes[a];
    const BvhNode& q = y.nodes[b];
    ASSERT_TRUE(p.min == q.min && p.max == q.max && p.count == q.count)
        << shape << ": node " << a << " of the reference's tree, node " << b << " of the tuned one";
    if (p.is_leaf()) {
        for (std::uint32_t k = 0; k < p.count; ++k)
            ASSERT_EQ(x.primitives[p.first + k], y.primitives[q.first + k]) << shape;
        return;
    }
    expect_same_subtree(x, p.first, y, q.first, shape);
    expect_same_subtree(x, p.first + 1, y, q.first + 1, shape);
}

// The tuned back-end (tuned_bvh.h: the former reference, parallel and vectorised) builds the
// very tree of the plain reference, so its figures measure the tricks, not another tree; and its
// traversals give the same answers. 40,000 triangles: its top levels are split side by side and
// its subtrees of 16,384 or fewer primitives built as jobs.
TEST(TunedBvh, BuildsTheReferencesTreeAndAnswersAlike) {
    for (const std::string& shape : procedural_shapes()) {
        PreparedScene scene = mesh_scene(shape, 40000);
        Bvh tuned_tree;
        tuned::build(bvh_primitives(scene), BvhBuildOptions{}, tuned_tree);
        build_bvh(bvh_primitives(scene), BvhBuildOptions{}, scene.bvh);
        ASSERT_EQ(scene.bvh.nodes.size(), tuned_tree.nodes.size()) << shape;
        expect_same_subtree(scene.bvh, 0, tuned_tree, 0, shape);

        const std::unique_ptr<Backend> reference = make_bvh_backend(scene);
        const std::unique_ptr<Backend> tuned = make_tuned_bvh_backend(scene);
        tuned->build();
        for (bool any_hit : {false, true}) {
            const RayBatch batch = rays_at_sphere(2000, any_hit);
            EXPECT_EQ(
                compare_results(trace(*reference, batch), trace(*tuned, batch), any_hit, 0).total(),
                0u)
                << shape << (any_hit ? ", any-hit" : ", nearest");
        }
    }
}

// Rays are generated once and must not depend on the thread count; there is one shadow and one
// diffuse ray per primary hit, all with unit directions and non-empty ranges.
TEST(BvhBench, RaysAreDeterministicAndWellFormed) {
    BvhBenchConfig config;
    config.procedural = "torus";
    config.triangles = 800;
    config.width = 40;
    config.height = 30;
    BenchMesh mesh = load_bench_mesh(config);
    make_bvh_backend(mesh.scene)->build();
    const BenchRays one = make_bench_rays(mesh.scene, config, 1);
    const BenchRays three = make_bench_rays(mesh.scene, config, 3);
    ASSERT_EQ(one.batch[0].size(), 40u * 30u);
    EXPECT_GT(one.primary_hits, 100u) << "the camera should see the mesh";
    for (int k = 0; k < 3; ++k) {
        const RayBatch& a = one.batch[k];
        const RayBatch& b = three.batch[k];
        EXPECT_EQ(a.kind, kRayKinds[k]);
        EXPECT_EQ(a.any_hit, a.kind == RayKind::Shadow);
        if (k > 0) {
            EXPECT_EQ(a.size(), one.primary_hits);
        }
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            ASSERT_EQ(a.rays[i].origin, b.rays[i].origin) << to_string(a.kind) << " ray " << i;
            ASSERT_EQ(a.rays[i].direction, b.rays[i].direction)
                << to_string(a.kind) << " ray " << i;
            ASSERT_EQ(a.ranges[i].max, b.ranges[i].max);
            ASSERT_NEAR(double(glm::length(a.rays[i].direction)), 1.0, 1e-5);
            ASSERT_LT(a.ranges[i].min, a.ranges[i].max);
        }
    }
    // Another seed gives other diffuse directions, but the same primary and shadow rays.
    config.seed = 2;
    const BenchRays other = make_bench_rays(mesh.scene, config, 2);
    EXPECT_EQ(other.batch[1].rays[0].direction, one.batch[1].rays[0].direction);
    EXPECT_NE(other.batch[2].rays[0].direction, one.batch[2].rays[0].direction);
}

// The whole benchmark on a tiny mesh: exit code 0 and a report; with a wrong BVH, exit code 2
// and no throughput table.
TEST(BvhBench, RunFailsOnlyWhenBackEndsDisagree) {
    BvhBenchConfig config;
    config.procedural = "icosphere";
    config.triangles = 300;
    config.width = 48;
    config.height = 32;
    config.repeat = 1;
    config.threads = 2;
    std::ostringstream good;
    EXPECT_EQ(run_bvh_bench(config, good), 0) << good.str();
    EXPECT_NE(good.str().find("Mrays/s"), std::string::npos) << good.str();

    config.inject_error_period = 3;
    std::ostringstream bad;
    EXPECT_EQ(run_bvh_bench(config, bad), 2) << bad.str();
    EXPECT_NE(bad.str().find("TOO MANY"), std::string::npos) << bad.str();
    EXPECT_EQ(bad.str().find("Mrays/s"), std::string::npos) << bad.str();
}

}  // namespace
}  // namespace rt::bench
