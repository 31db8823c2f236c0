#version 430
// Stage 09's GPU unit tests (framework/render/gpu_cases.h): the student's intersect_sphere, _plane,
// _triangle and _box on a batch of rays, one invocation a case, each answer written back.
layout(local_size_x = 64) in;

#include "scene_layout.glsl"
#include "scene_buffers.glsl"
#include "compute_io.glsl"
#include "framework.glsl"
#include "intersect.glsl"

// A GL 4.5 machine may stop at 16 storage blocks, which the scene's and the output's fill: the
// cases come in texels[] (6 vec4 a case: origin and kind, direction, t range, a, b, c; kind 0
// sphere (a: centre, radius), 1 plane (a: point, b: normal), 2 triangle, 3 box (a lo, b hi)), the
// answers go out in pixels[] (4 vec4 a case: hit, t, stub; normal, front face; point; uv).
uniform int case_count;

void main() {
    const int i = int(gl_GlobalInvocationID.x);
    if (i >= case_count) return;
    const vec4 origin_kind = texels_at(6 * i), direction = texels_at(6 * i + 1);
    const vec4 t_range = texels_at(6 * i + 2);
    const vec4 a = texels_at(6 * i + 3), b = texels_at(6 * i + 4), c = texels_at(6 * i + 5);
    const Ray ray = Ray(origin_kind.xyz, direction.xyz);
    const Interval range = Interval(t_range.x, t_range.y);
    Hit hit = no_hit();
    bool found = false;
    switch (floatBitsToInt(origin_kind.w)) {
        case 0: found = intersect_sphere(ray, a, range, hit); break;
        case 1: found = intersect_plane(ray, a.xyz, b.xyz, range, hit); break;
        case 2: found = intersect_triangle(ray, a.xyz, b.xyz, c.xyz, range, hit); break;
        case 3: found = intersect_box(ray, a.xyz, b.xyz, range, hit); break;
    }
    pixels[4 * i] = vec4(found ? 1.0 : 0.0, hit.t, rt_stub_reached ? 1.0 : 0.0, 0.0);
    pixels[4 * i + 1] = vec4(hit.normal, hit.front_face ? 1.0 : 0.0);
    pixels[4 * i + 2] = vec4(hit.point, 0.0);
    pixels[4 * i + 3] = vec4(hit.uv, 0.0, 0.0);
}
