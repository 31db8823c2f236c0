// What the compute shader (trace.comp) takes from the host and gives back: the scene's uniforms
// (set by framework/render/gpu_render.cpp), the output buffer and the stub flags. An export for
// Shadertoy (shadertoy.glsl) declares the same names as constants instead.
uniform Camera camera;
uniform ivec2 image_size;
uniform ivec4 primitive_counts;  // spheres, planes, triangles, boxes
uniform int light_count;
uniform int material_count;
uniform vec3 background_color;
uniform vec3 ambient_light;
uniform bool fresnel;
// A specialised shader has the mode and the features as constants (RENDER_MODE, SCENE_FEATURES),
// so the compiler drops the other modes' code: llvmpipe would run every branch of an if, masked.
#ifdef RENDER_MODE
const int render_mode = RENDER_MODE;
#else
uniform int render_mode;  // RenderMode: 0 directions 1 normals 2 depth 3 primitive 4 shaded 5 bvh_visits
#endif
uniform int max_depth;    // the scene's, at most MAX_DEPTH
// What the scene uses, at run time: a specialised shader has exactly these compiled in (the
// HAS_ defines); the --uber one compiles everything and tests these bits instead.
#ifdef SCENE_FEATURES
const int scene_features = SCENE_FEATURES;
#else
uniform int scene_features;
#endif
uniform int texture_lookup;  // 0 each texture's own filter, 1 all nearest, 2 all bilinear
// Stage 10's progressive accumulation: this dispatch adds camera samples sample_first ..
// sample_first + sample_count - 1 of every pixel to the sums in `pixels` (the first dispatch
// starts them at 0); the host divides by the total.
uniform int sample_first;
uniform int sample_count;
#ifdef HAS_MOTION_BLUR
// The spheres as they are at the current camera sample's time (the storage buffer holds them at
// time 0 as spheres_at_rest): what render/sampled.cpp's per-thread scene copy is on the CPU.
Sphere spheres[MAX_SPHERES];
Sphere spheres_at(int i) { return spheres[i]; }
Sphere spheres_at(uint i) { return spheres[i]; }
#endif

// RT_BINDING_OUTPUT: the stub flags (one bit per stub, the host reports each once), then the pixels.
layout(std430, binding = RT_BINDING_OUTPUT) buffer Output {
    uint stub_flags[4];
    vec4 pixels[];  // rgb colour (stage 10: the sum of the samples so far); a: depth (-1 miss),
                    // -2 when the pixel reached a stub
};

bool rt_stub_reached = false;
// A stub's report (student_checks.glsl's RT_NOT_IMPLEMENTED): its flag for the host.
void rt_not_implemented(int stub) {
    rt_stub_reached = true;
    if (stub < 0) return;  // not in the host's table: the pixel still shows the stub colour
    atomicOr(stub_flags[stub / 32], 1u << uint(stub % 32));
}
#include "student_checks.glsl"
