#include "scene/bvh_primitives.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel_for.h"
#include "scene/prepared_scene.h"
#include "scene/transform.h"

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

}  // namespace

std::vector<BvhPrimitive> bvh_primitives(const Scene& scene) {
    std::vector<BvhPrimitive> out;
    out.reserve(scene.spheres.size() + scene.triangles.size() + scene.boxes.size() +
                scene.instances.size());
    auto add = [&](const Aabb& box, Scene::Kind kind, std::size_t i) {
        BvhPrimitive p;
        p.bounds = box;
        p.centroid = box.center();
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
    // Triangles, the bulk of a mesh scene, in chunks on every core (each writes its own slots).
    const std::size_t first = out.size(), triangles = scene.triangles.size();
    constexpr std::size_t kChunk = 16384;
    out.resize(first + triangles);
    parallel_for((triangles + kChunk - 1) / kChunk, default_thread_count(), [&](std::size_t c) {
        for (std::size_t i = c * kChunk; i < std::min(triangles, (c + 1) * kChunk); ++i) {
            Vec3 a, b, c;
            scene.triangle_vertices(i, a, b, c);
            Aabb box;
            for (const Vec3& p : {a, b, c}) {
                box.grow(down(p));
                box.grow(up(p));
            }
            out[first + i] = BvhPrimitive{
                box, box.center(), std::uint32_t(scene.primitive_id(Scene::Kind::Triangle, i))};
        }
    });
    for (std::size_t i = 0; i < scene.boxes.size(); ++i)
        add(Aabb{down(scene.boxes[i].min), up(scene.boxes[i].max)}, Scene::Kind::Box, i);
    // Instances: each object's box (made once), mapped to the world.
    std::vector<Aabb> object_bounds(scene.objects.size());
    std::vector<bool> known(scene.objects.size(), false);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const std::size_t o = scene.instances[i].object;
        if (!known[o]) {
            for (const BvhPrimitive& p : bvh_primitives(*scene.objects[o]))
                object_bounds[o].grow(p.bounds);
            known[o] = true;
        }
        add(instance_bounds(scene.instances[i], object_bounds[o]), Scene::Kind::Instance, i);
    }
    return out;
}

}  // namespace rt
