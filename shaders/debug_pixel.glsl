// rt render --gpu --debug-pixel X,Y: what the shader computed for one pixel, written to the end
// of the output buffer (compute_io.glsl's pixels[], after the image) and printed on the host by
// framework/render/gpu_debug_pixel.cpp, as the CPU's ray tree is. Only trace.comp includes it,
// and only when the host defines HAS_DEBUG_PIXEL; everywhere else framework.glsl turns
// rt_debug(...) and rt_debug_note(...) into nothing, so they cost nothing.
//
// Records: two vec4 each, a tag (kind, where, type, 0) and a value. Integers go as floats, exact
// below 2^24 (bit patterns would be denormals, which llvmpipe may flush to zero).
uniform ivec2 debug_pixel_at;
// kDebugCapacity (the notes kept) and the notes' kinds kDebug*: the prelude's
// (framework/gpu/shader_constants.h).
bool rt_debugging = false;       // this invocation is the pixel's (stage 10: its first sample)
int rt_debug_count = 0;

void rt_debug_put(int kind, int where, int type, vec4 value) {
    if (!rt_debugging) return;
    const int base = image_size.x * image_size.y + 1 + 2 * rt_debug_count;
    if (rt_debug_count < kDebugCapacity) {
        pixels[base] = vec4(float(kind), float(where), float(type), 0);
        pixels[base + 1] = value;
    }
    ++rt_debug_count;
}
// The header after the image: how many records were made (some may not have been kept).
void rt_debug_finish() {
    if (rt_debugging) pixels[image_size.x * image_size.y] = vec4(float(rt_debug_count));
}

void rt_debug_value(int line, float v) { rt_debug_put(kDebugValue, line, 0, vec4(v, 0, 0, 0)); }
void rt_debug_value(int line, vec2 v) { rt_debug_put(kDebugValue, line, 1, vec4(v, 0, 0)); }
void rt_debug_value(int line, vec3 v) { rt_debug_put(kDebugValue, line, 2, vec4(v, 0)); }
void rt_debug_value(int line, vec4 v) { rt_debug_put(kDebugValue, line, 3, v); }
void rt_debug_value(int line, int v) {  // exact: the high and low 16 bits
    rt_debug_put(kDebugValue, line, 4, vec4(float(v >> 16), float(v & 0xffff), 0, 0));
}
void rt_debug_value(int line, bool v) { rt_debug_put(kDebugValue, line, 5, vec4(v ? 1 : 0)); }

// A student's printf: rt_debug(any float, vecN, int or bool) prints its file, line and value.
#define rt_debug(value) rt_debug_value(__LINE__, value)
#define rt_debug_note(kind, where, value) rt_debug_put(kind, where, 0, value)
#define rt_debug_note_typed(kind, where, type, value) rt_debug_put(kind, where, type, value)
