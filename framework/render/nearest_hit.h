// The renderer's nearest-hit query over a prepared scene, given to students: stage 04's shadow
// rays, stage 06's traversal (intersect_primitive), stage 10's occlusion rays and stage 11's
// paths call it, as the renderer does. It answers with the student's functions: stage 06's BVH
// traversal when the scene has a tree, else stage 02's loop. Handout: stages/06-bvh/README.md.
#pragma once

#include "render/accelerate.h"
#include "scene/prepared_scene.h"
#include "scene/transform.h"
#include "stage_api/stage02.h"
#include "stage_api/stage06.h"

namespace rt {

inline bool intersect_instance(const PreparedScene& scene, std::size_t i, const Ray& ray,
                               Interval t_range, Hit& hit);

// Given (framework): intersects the primitive with global id `id` by the stage 02 functions and,
// on a hit, also fills hit.primitive and hit.material. An instance (Scene::instances) is its
// object met by the ray mapped into the object (intersect_instance below).
inline bool intersect_primitive(const PreparedScene& scene, std::uint32_t id, const Ray& ray,
                                Interval t_range, Hit& hit) {
    std::size_t i = 0;
    bool found = false;
    int material = -1;
    switch (scene.primitive_kind(int(id), i)) {
        case Scene::Kind::Sphere: {
            const Sphere sphere = scene.sphere_at(i, ray.time);
            found = intersect_sphere(ray, sphere, t_range, hit);
            material = sphere.material;
            break;
        }
        case Scene::Kind::Plane:
            found = intersect_plane(ray, scene.planes[i], t_range, hit);
            material = scene.planes[i].material;
            break;
        case Scene::Kind::Triangle: {
            Vec3 a, b, c;
            scene.triangle_vertices(i, a, b, c);
            found = intersect_triangle(ray, a, b, c, t_range, hit);
            material = scene.triangles[i].material;
            break;
        }
        case Scene::Kind::Box:
            found = intersect_box(ray, scene.boxes[i], t_range, hit);
            material = scene.boxes[i].material;
            break;
        case Scene::Kind::Instance:
            return intersect_instance(scene, i, ray, t_range, hit);
    }
    if (found) {
        hit.primitive = int(id);
        hit.material = material;
    }
    return found;
}

// Given (framework): the scene's nearest hit, as the renderer finds it: your BVH traversal when
// the scene has a tree, else your stage 02 intersect_nearest (the same answer, faster). Stages 04
// and 10 trace their rays through it, so a scene with a BVH uses it for every ray. A scene that
// asks for a tree a stubbed build_bvh did not make counts a stub call (the image is magenta).
// Instances (Scene::instances) are in the tree; without one, they are tested here after stage
// 02's loop, one by one.
inline bool nearest_hit(const PreparedScene& scene, const Ray& ray, Interval t_range, Hit& hit) {
    if (uses_bvh(scene)) return bvh_intersect_nearest(scene, ray, t_range, hit);
    if (scene.accelerator == Accelerator::Bvh) {
        count_missing_bvh();
        return false;
    }
    bool found = intersect_nearest(ray, scene, t_range, hit);
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
        if (intersect_instance(scene, i, ray, Interval{t_range.min, found ? hit.t : t_range.max},
                               hit))
            found = true;
    return found;
}

// Given (framework): instance i of the scene, the two-level way: the ray mapped into the
// instance's object, which nearest_hit answers there (your BVH of the object when the scene uses
// one, else your stage 02 loop), and the hit mapped back: the point on the world ray (the same
// t: the map is affine, and directions need not be unit length), the normal by the inverse
// transpose, renormalised (it still faces the ray). hit.primitive is the instance's id; the
// primitive of the object that was hit is hit.object_primitive. hit.uv is the object's (a
// triangle's barycentrics).
inline bool intersect_instance(const PreparedScene& scene, std::size_t i, const Ray& ray,
                               Interval t_range, Hit& hit) {
    const Instance& instance = scene.instances[i];
    Hit local;
    const PreparedScene& object = *scene.prepared_objects[instance.object];
    if (!nearest_hit(object, object_ray(instance, ray), t_range, local)) return false;
    hit = local;
    hit.point = ray.at(local.t);
    hit.normal = world_normal(instance, local.normal);
    hit.primitive = Scene::primitive_id(Scene::Kind::Instance, i);
    hit.object_primitive = local.primitive;
    if (instance.material >= 0) hit.material = instance.material;
    return true;
}

}  // namespace rt
