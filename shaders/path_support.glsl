// Stage 11 on the GPU: what stages/11-path-tracing/bsdf.glsl and path.glsl are given, as the C++
// stage gets it from the framework (stage_api/stage11.h's BsdfSample, geometry/onb.h's Onb,
// scene/surface_point.h's spawn_ray, scene/area_light_hit.cpp's nearest_area_light). Included by
// trace.glsl for a path-traced scene only (HAS_PATH_TRACING), after stage 10's sampling.glsl,
// whose frame_around, sample_cosine_hemisphere, sample_rectangle, sample_sphere and their pdfs
// the student files use. Random numbers: rng_next() and rng_next2() (trace.glsl), the GPU's
// SampleStream.

// sample_bsdf's result (stage_api/stage11.h's BsdfSample).
struct BsdfSample {
    vec3 wi;      // local, unit; a sample that fails (below the surface) has weight 0
    vec3 weight;  // f(wo, wi) |wi.z| / pdf; a delta lobe: what it reflects over its chance
    float pdf;    // bsdf_pdf(material, wo, wi) per unit solid angle; 0 for a delta lobe
    bool delta;   // a mirror or glass direction: no light sampling, no MIS weight
};
BsdfSample no_bsdf_sample() { return BsdfSample(vec3(0), vec3(0), 0.0, false); }

// The GGX roughness of a material's specular lobe (packed in emissive.w: gpu/gpu_scene.h).
float material_roughness(Material m) { return m.emissive.w; }

// A local shading frame (geometry/onb.h's Onb): n its z axis.
struct Onb {
    vec3 t, b, n;
};
Onb onb_around(vec3 n) {
    Onb f;
    f.n = n;
    frame_around(n, f.t, f.b);
    return f;
}
vec3 to_world(Onb f, vec3 local) { return local.x * f.t + local.y * f.b + local.z * f.n; }
vec3 to_local(Onb f, vec3 world) { return vec3(dot(world, f.t), dot(world, f.b), dot(world, f.n)); }

// The ray leaving `at` in `direction`, its origin offset along `normal` (scene/surface_point.h).
Ray spawn_ray(SurfacePoint at, vec3 normal, vec3 direction) {
    return Ray(offset_ray_origin(at.point, at.error, normal, direction), direction);
}

// The nearest area light along a ray (scene/area_light_hit.h): light -1 when none is closer
// than t_range.max; radiance 0 on the back of a rectangle.
struct AreaLightHit {
    int light;
    float t;
    vec3 radiance;
};

float area_rectangle_t(AreaLight light, Ray ray) {
    const vec3 n = cross(light.edge_u.xyz, light.edge_v.xyz);
    const float denominator = dot(n, ray.direction);
    if (denominator == 0.0) return kInfinity;
    const float t = dot(n, light.corner_kind.xyz - ray.origin) / denominator;
    const vec3 p = ray.origin + t * ray.direction - light.corner_kind.xyz;
    const float s = dot(p, light.edge_u.xyz) / dot(light.edge_u.xyz, light.edge_u.xyz);
    const float r = dot(p, light.edge_v.xyz) / dot(light.edge_v.xyz, light.edge_v.xyz);
    return s >= 0.0 && s <= 1.0 && r >= 0.0 && r <= 1.0 ? t : kInfinity;
}

float area_sphere_t(AreaLight light, Ray ray, Interval range) {
    const vec3 oc = ray.origin - light.center_radius.xyz;
    const float radius = light.center_radius.w;
    const float a = dot(ray.direction, ray.direction);
    const float half_b = dot(oc, ray.direction);
    const float c = dot(oc, oc) - radius * radius;
    const float discriminant = half_b * half_b - a * c;
    if (discriminant < 0.0) return kInfinity;
    const float root = sqrt(discriminant);
    const float near = (-half_b - root) / a, far = (-half_b + root) / a;
    if (near > range.min && near < range.max) return near;
    if (far > range.min && far < range.max) return far;
    return kInfinity;
}

AreaLightHit nearest_area_light(Ray ray, Interval t_range) {
    AreaLightHit hit = AreaLightHit(-1, kInfinity, vec3(0));
    for (int i = 0; i < int(sampling.seed_counts.z) && i < MAX_AREA_LIGHTS; ++i) {
        const AreaLight light = area_lights[i];
        const bool rectangle = floatBitsToInt(light.corner_kind.w) == 0;
        const float t =
            rectangle ? area_rectangle_t(light, ray) : area_sphere_t(light, ray, t_range);
        if (!(t > t_range.min && t < t_range.max && t < hit.t)) continue;
        hit.light = i;
        hit.t = t;
        const bool lit_side =
            !rectangle || dot(cross(light.edge_u.xyz, light.edge_v.xyz), ray.direction) < 0.0;
        hit.radiance = lit_side ? light.radiance.rgb : vec3(0);
    }
    return hit;
}

#include "bsdf.glsl"
#include "path.glsl"
