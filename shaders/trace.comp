#version 430
// The GPU stage's entry point: one invocation a pixel. Assembled on the host
// (framework/gl/shader_source.h), which puts the scene's #defines after the #version line:
//   HAS_SPHERES HAS_PLANES HAS_TRIANGLES HAS_BOXES HAS_VERTEX_NORMALS  what the scene contains
//   HAS_BVH HAS_SHADOWS HAS_REFLECTION HAS_REFRACTION                  what the render needs
//   MAX_LIGHTS (>= 1), MAX_DEPTH (0..64)                                fixed array sizes
// The student files (stages/09-gpu/) come from the include folders the host passes.
layout(local_size_x = 8, local_size_y = 8) in;

#include "scene_layout.glsl"
#include "framework.glsl"
#include "camera.glsl"
#include "intersect.glsl"

// Given: one primitive by its global id (stage 06's intersect_primitive), for the BVH queries.
bool intersect_primitive(int id, Ray ray, Interval t_range, inout Hit hit) {
    const int i = primitive_index(id);
    bool found = false;
    int material = -1;
    switch (primitive_kind(id)) {
        case kSphere:
            found = intersect_sphere(ray, spheres[i].center_radius, t_range, hit);
            material = spheres[i].material.x;
            break;
        case kPlane:
            found = intersect_plane(ray, planes[i].point_material.xyz, planes[i].normal.xyz,
                                    t_range, hit);
            material = floatBitsToInt(planes[i].point_material.w);
            break;
        case kTriangle: {
            vec3 a, b, c;
            triangle_vertices(i, a, b, c);
            found = intersect_triangle(ray, a, b, c, t_range, hit);
            material = int(triangles[i].vertices_material.w);
            break;
        }
        case kBox:
            found = intersect_box(ray, boxes[i].min_material.xyz, boxes[i].max.xyz, t_range, hit);
            material = floatBitsToInt(boxes[i].min_material.w);
            break;
    }
    if (found) hit.primitive = id, hit.material = material;
    return found;
}

#include "bvh.glsl"
#include "shade.glsl"
#include "recursion.glsl"

// render/accelerate.h's nearest_hit: the BVH when the scene has one, stage 02's loop otherwise.
bool nearest_hit(Ray ray, Interval t_range, inout Hit hit) {
#ifdef HAS_BVH
    return bvh_intersect_nearest(ray, t_range, hit);
#else
    return intersect_nearest(ray, t_range, hit);
#endif
}

Ray camera_ray(vec2 pixel) {
    return camera.projection == 0 ? perspective_ray(pixel) : orthographic_ray(pixel);
}

// One ray of the loop's stack: what recursion kept in its locals (render/shade.cpp's Frame).
struct Frame {
    Ray ray;
    int depth;
    vec3 colour;  // local light, then each branch's weighted colour as it completes
    bool recurse;
    SecondaryRays branches;
    int next;  // the branch to trace next: 0 reflected, 1 refracted, 2 done
};

bool nonzero(vec3 c) { return c.r > 0.0 || c.g > 0.0 || c.b > 0.0; }

SecondaryRay branch(Frame f, int i) { return i == 0 ? f.branches.reflected : f.branches.refracted; }

// A frame's own work, as start_frame in render/shade.cpp: nearest hit, direct light with the
// shadows, and the secondary rays when the material reflects or transmits.
void start_frame(inout Frame f) {
    Hit hit = no_hit();
    f.recurse = false;
    if (!nearest_hit(f.ray, Interval(0.0, kInfinity), hit)) {
        f.colour = background_colour;
        return;
    }
    const Material material = material_at(hit.material);
    const SurfacePoint at = surface_point(f.ray, hit);
    const vec3 to_viewer = -normalize(f.ray.direction);
    vec3 lighting_normal = at.normal;
#ifdef HAS_VERTEX_NORMALS
    if (primitive_kind(hit.primitive) == kTriangle) {
        const vec3 smooth_normal = shading_normal(primitive_index(hit.primitive), hit.uv);
        if (smooth_normal != vec3(0)) lighting_normal = hit.front_face ? smooth_normal
                                                                       : -smooth_normal;
    }
#endif
    vec3 visibility[MAX_LIGHTS];
    for (int i = 0; i < MAX_LIGHTS; ++i) visibility[i] = vec3(1);
#ifdef HAS_SHADOWS
    // Only lights whose Blinn-Phong term is not zero get a shadow ray.
    for (int i = 0; i < light_count; ++i) {
        const LightSample s = illuminate(i, at.point);
        visibility[i] = vec3(0);
        if (blinn_phong(material, lighting_normal, to_viewer, s.direction, s.intensity) == vec3(0))
            continue;
#if defined(HAS_BVH) && !defined(HAS_REFRACTION)
        const ShadowRay shadow = shadow_ray(at, s);
        visibility[i] = vec3(bvh_intersect_any(shadow.ray, shadow.t_range) ? 0.0 : 1.0);
#else
        visibility[i] = light_transmittance(at, s);
#endif
    }
#endif
    f.colour = direct_light(material, at.point, lighting_normal, to_viewer, visibility);
    bool bounces = false;
#ifdef HAS_REFLECTION
    bounces = bounces || nonzero(material.reflective.rgb);
#endif
#ifdef HAS_REFRACTION
    bounces = bounces || nonzero(material.transmissive_ior.rgb);
#endif
    f.recurse = f.depth < MAX_DEPTH && bounces;
    f.next = 0;
    if (f.recurse) f.branches = secondary_rays(f.ray, at, material, fresnel);
}

// render/shade.cpp's trace: a loop over a fixed stack instead of recursion.
vec3 trace(Ray ray) {
    Frame stack[MAX_DEPTH + 1];
    int top = 0;
    stack[0].ray = ray, stack[0].depth = 0;
    start_frame(stack[0]);
    for (;;) {
        while (stack[top].recurse && stack[top].next < 2 && !branch(stack[top], stack[top].next).valid)
            ++stack[top].next;
        if (stack[top].recurse && stack[top].next < 2 && top < MAX_DEPTH) {
            const SecondaryRay s = branch(stack[top], stack[top].next);
            ++top;
            stack[top].ray = s.ray, stack[top].depth = stack[top - 1].depth + 1;
            start_frame(stack[top]);
            continue;
        }
        if (top == 0) return stack[0].colour;
        const vec3 colour = stack[top].colour;
        --top;
        stack[top].colour += branch(stack[top], stack[top].next).weight * colour;
        ++stack[top].next;
    }
}

void main() {
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= image_size.x || pixel.y >= image_size.y) return;
    const Ray ray = camera_ray(vec2(pixel) + 0.5);
    vec4 result = vec4(0, 0, 0, -1);
    if (render_mode == 0) {
        if (!any(isinf(ray.direction)) && !any(isnan(ray.direction)))
            result.rgb = 0.5 * (ray.direction + 1.0);
    } else if (render_mode == 4) {
        result.rgb = trace(ray);
    } else {
        Hit hit = no_hit();
        if (nearest_hit(ray, Interval(0.0, kInfinity), hit)) {
            result.rgb = 0.5 * (hit.normal + 1.0);
            result.a = hit.t;
        }
    }
    if (rt_stub_reached) result = vec4(1, 0, 1, -2);
    pixels[pixel.y * image_size.x + pixel.x] = result;
}
