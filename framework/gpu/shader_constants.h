// Every number the C++ host and stage 09's GLSL share, defined once here: shader_prelude() writes
// them as GLSL constants into every assembled shader, right after #version (gpu/gl/shader_source.cpp)
// and at the top of a Shadertoy export, so the two sides cannot drift apart. What the enums of
// scene/ already number (primitive kinds, render modes, texture kinds ...) is written from them.
#pragma once

#include <string>

namespace rt::gpu {

// The scene_features uniform's bits (compute_io.glsl): what the scene uses, tested at run time by
// the --uber shader (render/gpu/gpu_render.cpp's gpu_feature_bits sets them).
enum FeatureBit : int {
    kFeatureBvh = 1 << 0,
    kFeatureShadows = 1 << 1,
    kFeatureVertexNormals = 1 << 2,
    kFeatureVertexUvs = 1 << 3,
    kFeatureRefraction = 1 << 4,
    kFeatureSampled = 1 << 5,  // stage 10: Features::sampled() and its parts below
    kFeatureAreaLights = 1 << 6,
    kFeatureDepthOfField = 1 << 7,
    kFeatureGlossy = 1 << 8,
    kFeatureOcclusion = 1 << 9,
    kFeatureIndirect = 1 << 10,
    kFeaturePathTracing = 1 << 11,  // stage 11: "integrator": "path" (path_radiance)
};

// The texture_lookup uniform: each texture's own filter, or all nearest, or all bilinear.
enum LookupCode : int { kLookupPerTexture = 0, kLookupNearest = 1, kLookupBilinear = 2 };

// rt export-web's term switches (the rt_terms_off uniform, shaders/page_terms.glsl): bit i switches
// off the term render/prepare.h's kTermNames[i] names, as rt view's panel does.
enum TermBit : int {
    kTermAmbient = 1 << 0,
    kTermDiffuse = 1 << 1,
    kTermSpecular = 1 << 2,
    kTermEmissive = 1 << 3,
    kTermReflection = 1 << 4,
    kTermRefraction = 1 << 5,
    kTermEnvironment = 1 << 6,
};
constexpr int kTermCount = 7;

// The output buffer (compute_io.glsl): stub flags, the pixels, --debug-pixel's notes. The packed
// scene's bindings are gpu_scene.h's Binding.
constexpr int kOutputBinding = 15;
// Stage 10's uniform block SampledScene (scene_layout.glsl; gpu::sampled_block fills it).
constexpr int kSampledSceneBinding = 0;

// --debug-pixel's notes (debug_pixel.glsl, render/gpu/gpu_debug_pixel.cpp) and how many are kept.
enum DebugNote : int {
    kDebugValue =
        0,      // a student's rt_debug: where is its __LINE__, type float vec2 vec3 vec4 int bool
    kDebugRay,  // where: depth; value: origin, w the branch (0 camera 1 reflected 2 refracted)
    kDebugDirection,  // where: depth
    kDebugHit,        // value: t, kind, index, material; type: 1 on the front face
    kDebugPoint,
    kDebugNormal,     // the lighting normal
    kDebugMiss,       // value: the background
    kDebugShadow,     // where: the light; value: its visibility
    kDebugLocal,      // the local light (direct light, stage 10's sampled terms)
    kDebugReflected,  // value: weight, w 1 when the ray is traced
    kDebugRefracted,
    kDebugPixel,   // value: trace_pixel's result, or the camera sample's colour
    kDebugSample,  // where: the camera sample; value: its image point
};
constexpr int kDebugCapacity = 512;

// Iterations of one student while loop, in one invocation, that the guard allows
// (rt_loop_guard, compute_io.glsl). llvmpipe ends a loop after at most 65,535 iterations, fewer
// when it is nested: the BVH traversal inside the tracer's loops was cut between 16,000 and
// 30,000 (measured). A BVH traversal of this course's scenes takes a few hundred.
constexpr int kLoopLimit = 10000;

// The GLSL text of all of the above, and of the scene enums the shaders compare with.
std::string shader_prelude();

}  // namespace rt::gpu
