// Shared by the stage 06 tests: scenes made from procedural meshes, seeded rays, and the tree
// built exactly the way the renderer builds it.
#pragma once

#include "geometry/procedural_mesh.h"
#include "render/accelerate.h"
#include "render/prepare.h"
#include "scene/bvh_primitives.h"
#include "testing/random.h"

namespace rt::bvh_test {

// A scene whose only surfaces are `mesh` (material 0).
inline PreparedScene scene_from_mesh(const TriangleMesh& mesh) {
    PreparedScene scene;
    scene.vertices = mesh.vertices;
    for (const auto& t : mesh.triangles) scene.triangles.push_back(Triangle{t, 0});
    scene.materials.emplace_back();
    scene.accelerator = Accelerator::Bvh;
    refresh_features(scene);
    return scene;
}

using testing::Random;  // seeded, the same numbers on every machine (testing/random.h)

}  // namespace rt::bvh_test
