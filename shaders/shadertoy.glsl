// rt export-shadertoy's entry point: the tracer (trace.glsl) as a Shadertoy fragment shader. The
// command writes, before this file, the scene's #defines, its structs (scene_layout.glsl) and the
// whole scene as constant arrays with their accessors, name_at(i) as every shader reads them
// (scene_buffers.glsl), and the uniforms as constants (framework/render/gpu/shadertoy_export.cpp).

ivec2 image_size;  // the canvas: mainImage sets it from Shadertoy's iResolution

bool rt_stub_reached = false;
// Shadertoy has nowhere to report a stub: its pixels turn magenta. rt_first_stub says which stub
// (the export's test reads it through a wrapper; Shadertoy ignores it).
int rt_first_stub = -1;
void rt_not_implemented(int stub) {
    if (rt_first_stub < 0) rt_first_stub = stub;
    rt_stub_reached = true;
}
#include "student_checks.glsl"

#ifdef HAS_SAMPLING
// Stage 10, in rt export-web's pages only (Shadertoy's export refuses it): each frame draws camera
// samples sample_first .. sample_first + sample_count - 1 of every pixel, as one dispatch of
// trace.comp does, and the page adds the frames up and divides (framework/render/gpu/web/page_samples.js).
uniform int sample_first;
uniform int sample_count;
#endif
#ifdef HAS_MOTION_BLUR
Sphere spheres[MAX_SPHERES];  // the spheres at the camera sample's time (trace.glsl's move_spheres)
Sphere spheres_at(int i) { return spheres[i]; }
Sphere spheres_at(uint i) { return spheres[i]; }
#endif

#include "trace.glsl"

// image/image.cpp's linear_to_srgb: Shadertoy shows fragColor as sRGB-encoded bytes.
float rt_encode_srgb(float x) {
    if (!(x > 0.0)) return 0.0;
    if (x >= 1.0) return 1.0;
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

void mainImage(out vec4 fragColor, in vec2 fragCoord) {
    image_size = ivec2(iResolution.xy);
#ifdef HAS_SAMPLING
    if (render_mode == kModeShaded && scene_has(kFeatureSampled)) {
        // This frame's camera samples of the pixel, summed and linear: the page divides.
        const ivec2 pixel = ivec2(fragCoord.x, iResolution.y - fragCoord.y);
        vec3 sum = vec3(0);
        for (int s = sample_first; s < sample_first + sample_count; ++s) sum += sample_pixel(pixel, s);
        fragColor = vec4(sum, 1.0);
        return;
    }
#endif
    // Shadertoy's fragCoord has y up; the camera's image points have y down.
    vec4 result = trace_pixel(vec2(fragCoord.x, iResolution.y - fragCoord.y));
    if (render_mode == kModeDepth || render_mode == kModeBvhVisits) {
        // rt export-web's page only (Shadertoy's export refuses these modes): the hit distance
        // or node count into a float image, mapped by the image's range (framework/render/gpu/web/page_ranges.js).
        fragColor = vec4(result.a, 0.0, 0.0, 1.0);
        return;
    }
    vec3 c = result.rgb;
    if (render_mode == kModeShaded) c = vec3(rt_encode_srgb(c.r), rt_encode_srgb(c.g), rt_encode_srgb(c.b));
    fragColor = vec4(c, 1.0);  // the debug modes' values are display values already
}
