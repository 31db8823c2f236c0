// Instances on the GPU (scene/scene.h's Scene::instances): the GPU port draws a copy of the scene
// in which every instance's object is placed in world space, so the shader traverses one BVH of
// world-space primitives. The CPU traverses two levels (render/nearest_hit.h's
// intersect_instance); the copy has the same surfaces, hence the same image under the stages'
// metrics. It costs memory per instance (a copy of its object), which the course's scenes afford:
// instance_field's 8 tori of 2,400 triangles become 19,200.
#pragma once

#include "render/render.h"
#include "scene/prepared_scene.h"

namespace rt {

// `scene` without instances: each instance's triangles, spheres and boxes in world space, with
// the instance's material when it names one, and a BVH built over them (stage 06's build_bvh)
// when `scene` uses one. A box turned other than by quarter turns becomes its 12 triangles.
// Throws GpuError (render/gpu/gpu_render.h) for what a copy cannot keep: a sphere scaled unevenly
// (an ellipsoid), a turned box in a textured scene (its texture coordinates), and the modes that
// show primitives or the tree (`primitive`, `bvh_visits`), whose copy differs from the CPU's.
PreparedScene flatten_instances(const PreparedScene& scene, RenderMode mode);

}  // namespace rt
