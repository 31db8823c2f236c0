// Transforms and instances against hand-computed hits (docs/scene-format.md#transforms-and-
// instances): the framework's two-level query (intersect_instance in render/nearest_hit.h) over the
// stage 02 functions and, with "accelerator": "bvh", this stage's tree at both levels. Not graded
// (a binary of its own): it checks the framework, with the reference solution. Every test uses
// the tree, so that in a starter tree they fail on this stage's stubs like the others.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/source_dir.h"
#include "render/nearest_hit.h"
#include "render/prepare.h"
#include "scene/scene_loader.h"
#include "scene/surface_point.h"
#include "stage_api/stage06.h"

namespace rt {
namespace {

PreparedScene prepared(const std::string& surfaces, const std::string& before = "",
                       Accelerator accelerator = Accelerator::None) {
    SceneOverrides overrides;
    overrides.accelerator = accelerator;
    return prepare_scene(
        parse_scene("{" + before + "\"surfaces\": [" + surfaces + "]}", "test.json", "."),
        overrides);
}

void expect_near(const Vec3& a, const Vec3& b, double tolerance = 1e-5) {
    EXPECT_NEAR(a.x, b.x, tolerance) << "x";
    EXPECT_NEAR(a.y, b.y, tolerance) << "y";
    EXPECT_NEAR(a.z, b.z, tolerance) << "z";
}

// The tree first: every test needs this stage's code (a starter tree's stage06 tests all fail on
// its stubs), then stage 02's loop, which must give the same hits.
const Accelerator kBoth[] = {Accelerator::Bvh, Accelerator::None};

TEST(Instance, RotatedBox) {
    // The cube [-1, 1]^3 turned 45 degrees about +y: its +z face now faces (1, 0, 1) / sqrt 2, at
    // distance 1 from the origin, so x + z = sqrt 2 on it. The ray x = 0.3 down -z from z = 5
    // meets it at z = sqrt 2 - 0.3, t = 5.3 - sqrt 2.
    for (Accelerator a : kBoth) {
        const PreparedScene s = prepared(
            R"({"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1], "material": 0,
                "transform": {"rotate": {"axis": [0, 1, 0], "degrees": 45}}})",
            "", a);
        ASSERT_EQ(s.instances.size(), 1u);
        Hit hit;
        ASSERT_TRUE(nearest_hit(s, Ray{{0.3, 0, 5}, {0, 0, -1}}, Interval{0, kInfinity}, hit));
        EXPECT_NEAR(hit.t, 5.3 - std::sqrt(2.0), 1e-5);
        expect_near(hit.point, {0.3, 0, std::sqrt(2.0) - 0.3});
        expect_near(hit.normal, Vec3(1, 0, 1) / std::sqrt(Real(2)));
        EXPECT_TRUE(hit.front_face);
        EXPECT_EQ(hit.primitive, Scene::primitive_id(Scene::Kind::Instance, 0));
        EXPECT_EQ(hit.object_primitive, Scene::primitive_id(Scene::Kind::Box, 0));
        EXPECT_EQ(hit.material, 0);
        // The unturned cube would be met at z = 1, t = 4: the turn must be applied.
        EXPECT_FALSE(nearest_hit(s, Ray{{0.3, 0, 5}, {0, 0, -1}}, Interval{3.9, 4.1}, hit));
    }
}

TEST(Instance, NonUniformlyScaledSphere) {
    // The unit sphere stretched to x^2 / 4 + y^2 + z^2 = 1. Down -y at x = 1: y = sqrt(3) / 2.
    // The normal is the gradient (x / 4, y, z) = (0.25, 0.866, 0), normalised: by the inverse
    // transpose, not the stretched normal (2 x, y, z).
    for (Accelerator a : kBoth) {
        const PreparedScene s = prepared(
            R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
                "transform": {"scale": [2, 1, 1]}})",
            "", a);
        const double y = std::sqrt(0.75);
        const Vec3 normal = glm::normalize(Vec3(0.25, Real(y), 0));
        Hit hit;
        ASSERT_TRUE(nearest_hit(s, Ray{{1, 5, 0}, {0, -1, 0}}, Interval{0, kInfinity}, hit));
        EXPECT_NEAR(hit.t, 5 - y, 1e-5);
        expect_near(hit.point, {1, Real(y), 0});
        expect_near(hit.normal, normal);
        // A direction of length 2 halves t (directions need not be unit length).
        Hit twice;
        ASSERT_TRUE(nearest_hit(s, Ray{{1, 5, 0}, {0, -2, 0}}, Interval{0, kInfinity}, twice));
        EXPECT_NEAR(twice.t, (5 - y) / 2, 1e-5);
        expect_near(twice.normal, normal);
        // Along x the stretched sphere reaches x = 2; from inside, the normal faces the ray.
        ASSERT_TRUE(nearest_hit(s, Ray{{0, 0, 0}, {1, 0, 0}}, Interval{0, kInfinity}, hit));
        EXPECT_NEAR(hit.t, 2, 1e-5);
        expect_near(hit.normal, {-1, 0, 0});
        EXPECT_FALSE(hit.front_face);
    }
}

// One triangle (facing +z) as an object, placed twice: turned about +y by 90 degrees (facing +x)
// and moved to x = 3; turned about +x by -90 degrees (facing +y) and moved down to y = -3.
const char* const kTwoPlacements =
    R"("objects": [{"name": "tri", "surfaces": [{"type": "triangle",
        "vertices": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], "material": 1}]}],)";
const char* const kTwoInstances =
    R"({"type": "instance", "object": "tri", "transform": [{"rotate": {"axis": [0, 1, 0], "degrees": 90}}, {"translate": [3, 0, 0]}]},
       {"type": "instance", "object": "tri", "material": 0, "transform": [{"rotate": {"axis": [1, 0, 0], "degrees": -90}}, {"translate": [0, -3, 0]}]})";

TEST(Instance, InstancedMeshNormals) {
    for (Accelerator a : kBoth) {
        const PreparedScene s = prepared(
            kTwoInstances,
            std::string(R"("materials": [{"name": "a"}, {"name": "b"}],)") + kTwoPlacements, a);
        Hit hit;
        ASSERT_TRUE(nearest_hit(s, Ray{{10, 0, 0}, {-1, 0, 0}}, Interval{0, kInfinity}, hit));
        EXPECT_NEAR(hit.t, 7, 1e-5);
        expect_near(hit.normal, {1, 0, 0});
        EXPECT_TRUE(hit.front_face);
        EXPECT_EQ(hit.primitive, Scene::primitive_id(Scene::Kind::Instance, 0));
        EXPECT_EQ(hit.material, 1) << "the object's material";
        ASSERT_TRUE(nearest_hit(s, Ray{{0, 5, 0}, {0, -1, 0}}, Interval{0, kInfinity}, hit));
        EXPECT_NEAR(hit.t, 8, 1e-5);
        expect_near(hit.normal, {0, 1, 0});
        EXPECT_TRUE(hit.front_face);
        EXPECT_EQ(hit.primitive, Scene::primitive_id(Scene::Kind::Instance, 1));
        EXPECT_EQ(hit.material, 0) << "the instance's override";
        // From below, the second one is hit on its back.
        ASSERT_TRUE(nearest_hit(s, Ray{{0, -5, 0}, {0, 1, 0}}, Interval{0, kInfinity}, hit));
        expect_near(hit.normal, {0, -1, 0});
        EXPECT_FALSE(hit.front_face);
        // The surface point refines onto the object's triangle and maps back to the world.
        const Ray ray{{0.2, 5, 0.1}, {0, -1, 0}};
        ASSERT_TRUE(nearest_hit(s, ray, Interval{0, kInfinity}, hit));
        const SurfacePoint at = surface_point(s, ray, hit);
        expect_near(at.point, {0.2, -3, 0.1});
        EXPECT_GT(at.error.y, 0);
        EXPECT_LT(at.error.y, 1e-5);
    }
}

TEST(Instance, MirroredMeshFacesOutward) {
    // A mirrored icosphere, baked: hit from outside along every axis, it shows its front.
    const PreparedScene s = prepared(
        R"({"type": "mesh", "procedural": "icosphere", "triangles": 320,
            "transform": {"scale": [-1, 1, 1]}})",
        "", Accelerator::Bvh);
    for (const Vec3 d : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(-1, 0, 0)}) {
        Hit hit;
        ASSERT_TRUE(nearest_hit(s, Ray{d * Real(5), -d}, Interval{0, kInfinity}, hit));
        EXPECT_TRUE(hit.front_face) << d.x << " " << d.y << " " << d.z;
        EXPECT_GT(glm::dot(hit.normal, d), 0.9);
    }
}

TEST(Instance, InstanceEqualsBakedMesh) {
    // The same torus baked by a transform and instanced by it: the same hits.
    const std::string transform =
        R"([{"scale": [1, 0.5, 2]}, {"euler_degrees": [10, 20, 30]}, {"translate": [0.5, 0, 0]}])";
    const PreparedScene baked =
        prepared(R"({"type": "mesh", "procedural": "torus", "triangles": 500, "transform": )" +
                     transform + "}",
                 "", Accelerator::Bvh);
    const PreparedScene instanced =
        prepared(R"({"type": "instance", "object": "t", "transform": )" + transform + "}",
                 R"("objects": [{"name": "t", "surfaces": [{"type": "mesh", "procedural": "torus",
                    "triangles": 500}]}],)",
                 Accelerator::Bvh);
    int hits = 0;
    for (int i = 0; i < 21; ++i)
        for (int j = 0; j < 21; ++j) {
            const Ray ray{{-2 + 0.2 * i, -2 + 0.2 * j, 5}, {0.05, 0.02, -1}};
            Hit a, b;
            const bool found = nearest_hit(baked, ray, Interval{0, kInfinity}, a);
            ASSERT_EQ(found, nearest_hit(instanced, ray, Interval{0, kInfinity}, b))
                << i << " " << j;
            if (!found) continue;
            ++hits;
            EXPECT_NEAR(a.t, b.t, 1e-4);
            expect_near(a.normal, b.normal, 1e-4);
            EXPECT_EQ(a.front_face, b.front_face);
        }
    EXPECT_GT(hits, 40);
}

TEST(Instance, DemoSceneSameWithAndWithoutBvh) {
    const Scene scene =
        load_scene(source_dir() / "framework" / "tests" / "scenes" / "instance_field.json");
    SceneOverrides none, bvh;
    none.accelerator = Accelerator::None;
    bvh.accelerator = Accelerator::Bvh;
    const PreparedScene a = prepare_scene(scene, none), b = prepare_scene(scene, bvh);
    ASSERT_TRUE(uses_bvh(b));
    ASSERT_TRUE(uses_bvh(*b.prepared_objects[0])) << "the student's tree is the bottom level";
    EXPECT_FALSE(uses_bvh(*a.prepared_objects[0]));
    int instance_hits = 0;
    for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 30; ++j) {
            const Ray ray{{0, 2.2, 5.5}, glm::normalize(Vec3(-0.5 + i / 40.0, 0.1 - j / 30.0, -1))};
            Hit x, y;
            const bool found = nearest_hit(a, ray, Interval{0, kInfinity}, x);
            ASSERT_EQ(found, nearest_hit(b, ray, Interval{0, kInfinity}, y));
            if (!found) continue;
            EXPECT_EQ(x.primitive, y.primitive);
            EXPECT_NEAR(x.t, y.t, 1e-4);
            std::size_t index = 0;
            instance_hits += Scene::primitive_kind(y.primitive, index) == Scene::Kind::Instance;
        }
    EXPECT_GT(instance_hits, 50);
}

}  // namespace
}  // namespace rt
