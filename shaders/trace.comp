#version 430
// The GPU stage's entry point: one invocation a pixel. Assembled on the host
// (framework/gl/shader_source.h), which puts the scene's #defines after the #version line:
//   HAS_SPHERES HAS_PLANES HAS_TRIANGLES HAS_BOXES HAS_VERTEX_NORMALS  what the scene contains
//   HAS_BVH HAS_SHADOWS HAS_REFLECTION HAS_REFRACTION                  what the render needs
//   HAS_VERTEX_UVS HAS_TEXTURES HAS_NORMAL_MAPS                         stage 07's maps ...
//   HAS_IMAGE_TEXTURES HAS_CHECKER_TEXTURES HAS_NOISE_TEXTURES          ... and their kinds
//   HAS_ENVIRONMENT                                                     stage 08
//   HAS_SAMPLING: stage 10 (several camera samples per pixel, stages/10-sampling/sampling.glsl);
//   with it HAS_AREA_LIGHTS HAS_DEPTH_OF_FIELD HAS_MOTION_BLUR HAS_GLOSSY HAS_OCCLUSION
//   HAS_INDIRECT, as the scene's Features say; HAS_PATH_TRACING: stage 11 (path_support.glsl,
//   stages/11-path-tracing/bsdf.glsl and path.glsl), with HAS_SAMPLING
//   MAX_LIGHTS (>= 1), MAX_DEPTH (0..64)                                fixed array sizes
//   MAX_AREA_LIGHTS, MAX_MOVING_SPHERES (>= 1), MAX_SPHERES (motion blur) stage 10's array sizes
// rt render --gpu --uber defines them all (scene_has() then decides at run time).
// HAS_DEBUG_PIXEL: rt render --gpu --debug-pixel X,Y (debug_pixel.glsl).
// The tracer itself is trace.glsl (rt export-shadertoy shares it); this file binds it to the
// storage buffers and uniforms of framework/render/gpu_render.cpp.
layout(local_size_x = 8, local_size_y = 8) in;

#include "scene_layout.glsl"
#include "texel_arrays.glsl"
#include "compute_io.glsl"
#ifdef HAS_DEBUG_PIXEL
#include "debug_pixel.glsl"
#endif
#include "trace.glsl"

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= image_size.x || pixel.y >= image_size.y) return;
    const int i = pixel.y * image_size.x + pixel.x;
#ifdef HAS_DEBUG_PIXEL
    const bool debug_pixel = pixel == debug_pixel_at;
#endif
#ifdef HAS_SAMPLING
    if (render_mode == kModeShaded && scene_has(kFeatureSampled)) {
        // Stage 10: add this dispatch's camera samples to the pixel's sum.
        vec4 sum = sample_first == 0 ? vec4(0) : pixels[i];
        for (int s = sample_first; s < sample_first + sample_count; ++s) {
#ifdef HAS_DEBUG_PIXEL
            rt_debugging = debug_pixel && s == 0;  // the first camera sample's values
#endif
            sum.rgb += sample_pixel(pixel, s);
        }
        if (rt_stub_reached) sum.a = -2.0;
        pixels[i] = sum;
#ifdef HAS_DEBUG_PIXEL
        rt_debugging = debug_pixel && sample_first == 0;
        rt_debug_finish();
#endif
        return;
    }
#endif
#ifdef HAS_MOTION_BLUR
    for (int k = 0; k < primitive_counts.x && k < MAX_SPHERES; ++k) spheres[k] = spheres_at_rest[k];
#endif
#ifdef HAS_DEBUG_PIXEL
    rt_debugging = debug_pixel;
#endif
    pixels[i] = trace_pixel(vec2(pixel) + 0.5);
#ifdef HAS_DEBUG_PIXEL
    rt_debug_finish();
#endif
}
