// Shared by the stage 06 tests: scenes made from procedural meshes, seeded rays, and the tree
// built exactly the way the renderer builds it.
#pragma once

#include <random>

#include "geometry/procedural_mesh.h"
#include "render/accelerate.h"
#include "scene/bvh_primitives.h"

namespace rt::bvh_test {

// A scene whose only surfaces are `mesh` (material 0).
inline Scene scene_from_mesh(const TriangleMesh& mesh) {
    Scene scene;
    scene.vertices = mesh.vertices;
    for (const auto& t : mesh.triangles) scene.triangles.push_back(Triangle{t, 0});
    scene.materials.emplace_back();
    scene.accelerator = Accelerator::Bvh;
    scene.update_features();
    return scene;
}

// Deterministic on every machine: std::mt19937_64's sequence is fixed by the standard, and the
// conversions below are done by hand rather than by the library's distributions.
struct Random {
    std::mt19937_64 engine;
    explicit Random(std::uint64_t seed) : engine(seed) {}
    Real uniform(Real lo, Real hi) {
        return lo + (hi - lo) * Real(double(engine() >> 11) * 0x1p-53);
    }
    Vec3 point(Real lo, Real hi) {
        const Real x = uniform(lo, hi), y = uniform(lo, hi), z = uniform(lo, hi);
        return {x, y, z};
    }
    Vec3 direction() {
        for (;;) {
            const Vec3 v = point(-1, 1);
            const Real l = glm::length(v);
            if (l > Real(0.1) && l <= 1) return v / l;
        }
    }
};

}  // namespace rt::bvh_test
