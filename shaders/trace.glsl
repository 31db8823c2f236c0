// The tracer both entry points share: trace.comp (the compute shader of rt render --gpu) and
// shadertoy.glsl (rt export-shadertoy). Before it come the scene's structs and what holds the
// scene: trace.comp's storage buffers and uniforms, or an export's constants. The HAS_ defines
// (listed in trace.comp) say what the scene needs; the student files (stages/09-gpu/,
// stages/10-sampling/sampling.glsl for a stage 10 scene, stages/11-path-tracing/*.glsl for a
// path-traced one) come from the include folders the host passes.
#if defined(HAS_TEXTURES) || defined(HAS_NORMAL_MAPS)
#define HAS_MAPS  // some material has a map: texture coordinates and the texturing step
#endif
#if defined(HAS_IMAGE_TEXTURES) || defined(HAS_ENVIRONMENT)
#define HAS_IMAGE_LOOKUP  // stage 07's image lookups (the environment uses sample_bilinear)
#endif

#include "framework.glsl"
#include "camera.glsl"
#include "intersect.glsl"

// Given: one primitive by its global id (stage 06's intersect_primitive), for the BVH queries.
bool intersect_primitive(int id, Ray ray, Interval t_range, inout Hit hit) {
    const int i = primitive_index(id);
    bool found = false;
    int material = -1;
    switch (primitive_kind(id)) {
#ifdef HAS_SPHERES
        case kSphere:
            found = intersect_sphere(ray, spheres_at(i).center_radius, t_range, hit);
            material = spheres_at(i).material.x;
            break;
#endif
#ifdef HAS_PLANES
        case kPlane:
            found = intersect_plane(ray, planes_at(i).point_material.xyz, planes_at(i).normal.xyz,
                                    t_range, hit);
            material = floatBitsToInt(planes_at(i).point_material.w);
            break;
#endif
#ifdef HAS_TRIANGLES
        case kTriangle: {
            vec3 a, b, c;
            triangle_vertices(i, a, b, c);
            found = intersect_triangle(ray, a, b, c, t_range, hit);
            material = int(triangles_at(i).vertices_material.w);
            break;
        }
#endif
#ifdef HAS_BOXES
        case kBox:
            found = intersect_box(ray, boxes_at(i).min_material.xyz, boxes_at(i).max.xyz, t_range, hit);
            material = floatBitsToInt(boxes_at(i).min_material.w);
            break;
#endif
    }
    if (found) {
        hit.primitive = id;
        hit.material = material;
    }
    return found;
}

#include "bvh.glsl"

// render/nearest_hit.h's nearest_hit (shade.glsl's shadow rays use it too): the BVH when the scene has one, stage 02's loop otherwise.
bool nearest_hit(Ray ray, Interval t_range, inout Hit hit) {
#ifdef HAS_BVH
    if (scene_has(kFeatureBvh)) return bvh_intersect_nearest(ray, t_range, hit);
#endif
    return intersect_nearest(ray, t_range, hit);
}

#include "shade.glsl"
#include "recursion.glsl"
#if defined(HAS_MAPS) || defined(HAS_ENVIRONMENT)
#include "texture_helpers.glsl"
#include "textures.glsl"
#endif
#ifdef HAS_ENVIRONMENT
#include "environment.glsl"
#endif
#include "texturing.glsl"

// An if, not ?: : WebGL (and so Shadertoy and rt export-web's page) rejects ?: on structs.
Ray camera_ray(vec2 pixel) {
    if (camera.projection == kProjectionPerspective) return perspective_ray(pixel);
    return orthographic_ray(pixel);
}

// One ray's own work (render/shade.cpp's Frame): start_frame fills the last three.
struct Frame {
    Ray ray;
    int depth;
    vec3 color;  // the local light
    bool recurse;
    SecondaryRays branches;
};

bool nonzero(vec3 c) { return c.r > 0.0 || c.g > 0.0 || c.b > 0.0; }

// A hit made ready for lighting (render/shade.cpp's PreparedHit): its surface point, the material
// as its maps colour it there, the normal it is lit with.
struct PreparedHit {
    SurfacePoint at;
    int material_index;  // for light linking
    Material material;
    vec3 lighting_normal;
    vec3 to_viewer;
};

PreparedHit prepare_hit(Ray ray, Hit hit) {
    PreparedHit p;
    p.material = material_at(hit.material);
    p.material_index = hit.material;
    p.at = surface_point(ray, hit);
    p.to_viewer = -normalize(ray.direction);
    p.lighting_normal = p.at.normal;
#ifdef HAS_VERTEX_NORMALS
    if (scene_has(kFeatureVertexNormals) && primitive_kind(hit.primitive) == kTriangle) {
        const vec3 smooth_normal = shading_normal(primitive_index(hit.primitive), hit.uv);
        if (smooth_normal != vec3(0)) p.lighting_normal = hit.front_face ? smooth_normal
                                                                         : -smooth_normal;
    }
#endif
#ifdef HAS_MAPS
    // Stage 07: the material as its maps colour it here, and the normal-mapped normal.
    apply_textures(hit, p.at, p.to_viewer, p.material, p.lighting_normal);
#endif
    return p;
}

#ifdef HAS_SAMPLING
// Stage 10's random numbers: a counter-based PCG hash (Jarzynski and Olano, "Hash Functions for
// GPU Rendering", JCGT 2020) of the scene's seed, the pixel and the camera sample starts a
// 32-bit PCG stream. The same pixel and sample give the same numbers in every run and every
// dispatch order; they are not the CPU's (render/sampled.h), only as uniform.
uint rng_state = 0u;
uint pcg_hash(uint v) {
    const uint state = v * 747796405u + 2891336453u;
    const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
void rng_start(uint pixel, uint sample_index) {
    rng_state = pcg_hash(pixel + pcg_hash(sample_index + pcg_hash(sampling.seed_counts.x +
                                                                  pcg_hash(sampling.seed_counts.y))));
}
float rng_next() {  // uniform in [0, 1): 24 random bits, exact in a float
    rng_state = rng_state * 747796405u + 2891336453u;
    uint word = ((rng_state >> ((rng_state >> 28u) + 4u)) ^ rng_state) * 277803737u;
    word = (word >> 22u) ^ word;
    return float(word >> 8u) * (1.0 / 16777216.0);
}
vec2 rng_next2() {
    const float a = rng_next();
    return vec2(a, rng_next());
}

// What a ray leaving a surface brings back (sampling.glsl's indirect_diffuse asks): defined
// below. GLSL has no recursion, so the bounce's own light never bounces again (as on the CPU).
vec3 incoming_radiance(Ray ray);
#endif
#ifdef HAS_SAMPLING
#include "sampling.glsl"
#endif
// Stage 11 (a path-traced scene): path_support.glsl, then bsdf.glsl and path.glsl.
#ifdef HAS_PATH_TRACING
#include "path_support.glsl"
#endif
#ifdef HAS_SAMPLING
// Stage 10's sampled terms at a hit, in render/shade.cpp's order: one sample per area light,
// then ambient occlusion (the indirect bounce is start_frame's).
vec3 sampled_direct(PreparedHit p) {
    vec3 sum = vec3(0);
#ifdef HAS_AREA_LIGHTS
    for (int i = 0; i < int(sampling.seed_counts.z) && i < MAX_AREA_LIGHTS; ++i)
        sum += area_light_estimate(p.material, p.at, p.lighting_normal, p.to_viewer,
                                   area_lights[i], rng_next2());
#endif
#ifdef HAS_OCCLUSION
    if (scene_has(kFeatureOcclusion))
        sum += p.material.ambient.rgb * ambient_light *
               ambient_occlusion(p.at, p.lighting_normal, sampling.occlusion.x, rng_next2());
#endif
    return sum;
}
#endif

#ifdef HAS_LIGHT_LINKS
// Light linking (scene/scene.h's light_reaches): GpuLight's direction.w holds the mask of the
// first kLinkedMaterials materials the light lights, intensity.w its flags.
bool light_reaches(int light, int material) {
    const Light l = lights_at(light);
    if (material >= kLinkedMaterials)
        return (floatBitsToInt(l.intensity.w) & kLightReachRest) != 0;
    return ((floatBitsToUint(l.direction.w) >> uint(material)) & 1u) != 0u;
}
bool light_casts_shadows(int light) {
    return (floatBitsToInt(lights_at(light).intensity.w) & kLightCastsShadows) != 0;
}
#endif

// The light a hit sends back before reflected and refracted rays (render/shade.cpp's
// local_light without the bounce): direct light with the shadows, and stage 10's area lights
// and ambient occlusion, which replaces the ambient term as the bounce does.
vec3 local_light(PreparedHit p) {
    Material material = p.material;
#ifdef HAS_SAMPLING
    if (scene_has(kFeatureOcclusion) || scene_has(kFeatureIndirect)) material.ambient = vec4(0);
#endif
    vec3 visibility[MAX_LIGHTS];
    for (int i = 0; i < MAX_LIGHTS; ++i) visibility[i] = vec3(1);
#ifdef HAS_LIGHT_LINKS
    for (int i = 0; i < light_count; ++i)
        if (!light_reaches(i, p.material_index)) visibility[i] = vec3(0);
#endif
#ifdef HAS_SHADOWS
    // Only lights whose Blinn-Phong term is not zero get a shadow ray; with light linking, not
    // an unlinked light (it stays dark) or a shadowless one (it stays lit).
    for (int i = 0; i < light_count && scene_has(kFeatureShadows); ++i) {
#ifdef HAS_LIGHT_LINKS
        if (visibility[i] == vec3(0) || !light_casts_shadows(i)) continue;
#endif
        const LightSample s = illuminate(i, p.at.point);
        visibility[i] = vec3(0);
        if (blinn_phong(material, p.lighting_normal, p.to_viewer, s.direction, s.intensity) ==
            vec3(0))
            continue;
#ifdef HAS_BVH
        if (scene_has(kFeatureBvh) && !scene_has(kFeatureRefraction)) {
            const ShadowRay shadow = shadow_ray(p.at, s);
            visibility[i] = vec3(bvh_intersect_any(shadow.ray, shadow.t_range) ? 0.0 : 1.0);
            continue;
        }
#endif
        visibility[i] = light_transmittance(p.at, s);
    }
    for (int i = 0; i < light_count && scene_has(kFeatureShadows); ++i)
        rt_debug_note(kDebugShadow, i, vec4(visibility[i], 0));
#endif
    vec3 color = direct_light(material, p.at.point, p.lighting_normal, p.to_viewer, visibility);
#ifdef HAS_SAMPLING
    color += sampled_direct(p);
#endif
    return color;
}

#ifdef HAS_SAMPLING
vec3 incoming_radiance(Ray ray) {
    Hit hit = no_hit();
    if (!nearest_hit(ray, Interval(0.0, kInfinity), hit)) return background(ray.direction);
    return local_light(prepare_hit(ray, hit));
}
#endif

// --debug-pixel's notes of a ray and of its hit (debug_pixel.glsl); nothing without it.
void note_ray(int depth, Ray ray, int branch) {
    rt_debug_note(kDebugRay, depth, vec4(ray.origin, float(branch)));
    rt_debug_note(kDebugDirection, depth, vec4(ray.direction, 0));
}
void note_hit(int depth, Hit hit, vec3 point, vec3 normal) {
    rt_debug_note_typed(kDebugHit, depth, hit.front_face ? 1 : 0,
                        vec4(hit.t, float(primitive_kind(hit.primitive)),
                             float(primitive_index(hit.primitive)), float(hit.material)));
    rt_debug_note(kDebugPoint, depth, vec4(point, 0));
    rt_debug_note(kDebugNormal, depth, vec4(normal, 0));
}

// A frame's own work, as start_frame in render/shade.cpp: nearest hit, its local light, and the
// secondary rays when the material reflects or transmits.
void start_frame(inout Frame f) {
    Hit hit = no_hit();
    f.recurse = false;
    if (!nearest_hit(f.ray, Interval(0.0, kInfinity), hit)) {
        f.color = background(f.ray.direction);
        rt_debug_note(kDebugMiss, f.depth, vec4(f.color, 0));
        return;
    }
    const PreparedHit p = prepare_hit(f.ray, hit);
    note_hit(f.depth, hit, p.at.point, p.lighting_normal);
    f.color = local_light(p);
#ifdef HAS_INDIRECT
    if (scene_has(kFeatureIndirect))
        f.color += indirect_diffuse(p.at, p.lighting_normal, p.material, rng_next2());
#endif
    bool bounces = false;
#ifdef HAS_REFLECTION
    bounces = bounces || nonzero(p.material.reflective.rgb);
#endif
#ifdef HAS_REFRACTION
    bounces = bounces || nonzero(p.material.transmissive_ior.rgb);
#endif
    f.recurse = f.depth < max_depth && bounces;
    if (!f.recurse) {
        rt_debug_note(kDebugLocal, f.depth, vec4(f.color, 0));
        return;
    }
    f.branches = secondary_rays(f.ray, p.at, p.material, fresnel);
#ifdef HAS_GLOSSY
    // Stage 10: the mirror ray turned by the material's fuzz; into the surface it is absorbed.
    SecondaryRay reflected = f.branches.reflected;
    if (scene_has(kFeatureGlossy) && p.material.reflective.w > 0.0 && reflected.valid) {
        const vec3 d =
            glossy_direction(normalize(reflected.ray.direction), p.material.reflective.w,
                             rng_next2());
        if (!(dot(d, p.at.normal) > 0.0) || any(isinf(d)) || any(isnan(d)))
            f.branches.reflected.valid = false;
        else
            f.branches.reflected.ray = Ray(offset_ray_origin(p.at.point, p.at.error, p.at.normal, d), d);
    }
#endif
    rt_debug_note(kDebugLocal, f.depth, vec4(f.color, 0));
    rt_debug_note(kDebugReflected, f.depth,
                  vec4(f.branches.reflected.weight, f.branches.reflected.valid ? 1 : 0));
    rt_debug_note(kDebugRefracted, f.depth,
                  vec4(f.branches.refracted.weight, f.branches.refracted.valid ? 1 : 0));
}

// render/shade.cpp's trace: a loop over a fixed stack instead of recursion. Level k of the stack
// keeps what recursion kept in its locals, each field in an array of its own: with an array of
// Frame structs, llvmpipe (Mesa 22) drew wrong images with the uber shader's 65 levels even on
// scenes 5 deep; this layout does not. (llvmpipe also ends all loops after 65535 iterations in
// total per 8 invocations, so a ray tree much deeper than the course's max_depth 6 comes out
// black there: stages/09-gpu/README.md.)
vec3 trace(Ray ray) {
    vec3 color[MAX_DEPTH + 1];  // local light, then each branch's weighted colour as it completes
    int next[MAX_DEPTH + 1];     // the branch to trace next: 0 reflected, 1 refracted ...
    int end[MAX_DEPTH + 1];      // ... up to (not including) end
    vec3 origin[2 * MAX_DEPTH + 2], direction[2 * MAX_DEPTH + 2];  // branch i of level k: 2k + i
    vec3 weight[2 * MAX_DEPTH + 2];
    int top = 0;
    Frame f;
    f.ray = ray;
    int branch = 0;  // what f.ray is, for --debug-pixel: 0 the camera's, 1 reflected, 2 refracted
    for (;;) {
        f.depth = top;
        note_ray(top, f.ray, branch);
        start_frame(f);
        color[top] = f.color;
        next[top] = 0;
        end[top] = 0;
        if (f.recurse) {
            const SecondaryRay a = f.branches.reflected, b = f.branches.refracted;
            origin[2 * top] = a.ray.origin;
            direction[2 * top] = a.ray.direction;
            origin[2 * top + 1] = b.ray.origin;
            direction[2 * top + 1] = b.ray.direction;
            weight[2 * top] = a.weight;
            weight[2 * top + 1] = b.weight;
            next[top] = a.valid ? 0 : 1;  // an invalid branch is skipped
            end[top] = b.valid ? 2 : 1;
        }
        // Complete levels until one has a branch left (return at the root), as returns would.
        while (!(next[top] < end[top] && top < MAX_DEPTH)) {
            if (top == 0) return color[0];
            const vec3 child = color[top];
            --top;
            color[top] += weight[2 * top + next[top]] * child;
            ++next[top];
        }
        // Descend into that branch, as a recursive call would.
        f.ray = Ray(origin[2 * top + next[top]], direction[2 * top + next[top]]);
        branch = next[top] + 1;
        ++top;
    }
}

// The primitive-id view (render/render.cpp): the surface's rank when all are listed spheres,
// planes, triangles, boxes, hashed to a colour (the same integer hash as the CPU's).
vec3 primitive_color(int id) {
    const int kind = primitive_kind(id);
    int rank = primitive_index(id);
    for (int k = 0; k < kind; ++k) rank += primitive_counts[k];
    uint h = uint(rank + 1) * 2654435761u;
    h ^= h >> 15;
    h *= 2246822519u;
    h ^= h >> 13;
    return vec3(float(h & 255u), float((h >> 8) & 255u), float((h >> 16) & 255u)) / 255.0 * 0.8 +
           0.2;
}

// One pixel's value in render_mode at image point `pixel` (pixel units, y down): rgb the colour
// (display values in the debug modes); a the hit distance (depth) or the node count
// (bvh_visits), -1 for nothing, -2 when the pixel reached a stub.
vec4 trace_pixel(vec2 pixel) {
    const Ray ray = camera_ray(pixel);
    vec4 result = vec4(0, 0, 0, -1);
    if (render_mode != kModeShaded) note_ray(0, ray, 0);
    if (render_mode == kModeDirections) {
        if (!any(isinf(ray.direction)) && !any(isnan(ray.direction)))
            result.rgb = 0.5 * (ray.direction + 1.0);
    } else if (render_mode == kModeShaded) {
        result.rgb = trace(ray);
    } else if (render_mode == kModeBvhVisits) {  // the count goes through a, mapped on the host
#ifdef HAS_BVH
        Hit hit = no_hit();
        bvh_intersect_nearest(ray, Interval(0.0, kInfinity), hit);
        result.a = float(bvh_nodes_visited);
#endif
    } else {
        Hit hit = no_hit();
        if (nearest_hit(ray, Interval(0.0, kInfinity), hit)) {
            note_hit(0, hit, hit.point, hit.normal);
            result.rgb = render_mode == kModePrimitiveId ? primitive_color(hit.primitive)
                                          : 0.5 * (hit.normal + 1.0);
            result.a = hit.t;
        } else {
            rt_debug_note(kDebugMiss, 0, vec4(0));
        }
    }
    if (rt_stub_reached) result = vec4(1, 0, 1, -2);
    rt_debug_note(kDebugPixel, 0, result);
    return result;
}

#ifdef HAS_SAMPLING
#ifdef HAS_MOTION_BLUR
// The spheres at `time`, as C++'s Scene::sphere_at sees them: the moving ones moved along their
// velocity. The C++ renderer gives each ray its time; here each invocation moves its private
// copy of the spheres once per camera sample, which every ray of that sample then meets.
void move_spheres(float time) {
    for (int i = 0; i < primitive_counts.x && i < MAX_SPHERES; ++i) spheres[i] = spheres_at_rest[i];
    for (int m = 0; m < int(sampling.seed_counts.w) && m < MAX_MOVING_SPHERES; ++m) {
        const int i = floatBitsToInt(moving_spheres[m].velocity_sphere.w);
        if (i >= 0 && i < MAX_SPHERES)
            spheres[i].center_radius.xyz =
                spheres_at_rest[i].center_radius.xyz + time * moving_spheres[m].velocity_sphere.xyz;
    }
}
#endif

// Camera sample `sample_index` of `pixel` (render/sampled.cpp's sample_pixel): the jittered and
// filtered image point, the thin-lens ray, the shutter time, traced.
vec3 sample_pixel(ivec2 pixel, int sample_index) {
    rng_start(uint(pixel.y * image_size.x + pixel.x), uint(sample_index));
    const vec2 jitter =
        stratified_sample(sample_index, sampling.spp_filter_indirect.x, rng_next2());
    const vec2 offset = sampling.spp_filter_indirect.y == kPixelFilterTent ? tent_filter_offset(jitter)
                                                            : box_filter_offset(jitter);
    Ray ray = camera_ray(vec2(pixel) + 0.5 + offset);
    rt_debug_note(kDebugSample, sample_index, vec4(vec2(pixel) + 0.5 + offset, 0, 0));
#ifdef HAS_DEPTH_OF_FIELD
    if (scene_has(kFeatureDepthOfField))
        ray = thin_lens_ray(ray, sampling.lens_shutter.x, sampling.lens_shutter.y, rng_next2());
#endif
#ifdef HAS_MOTION_BLUR
    move_spheres(shutter_time(sampling.lens_shutter.z, sampling.lens_shutter.w, rng_next()));
#endif
#ifdef HAS_PATH_TRACING
    // Stage 11: the sample's radiance is path.glsl's path_radiance (render/shade.cpp's
    // trace_sample).
    const vec3 color = scene_has(kFeaturePathTracing) ? path_radiance(ray) : trace(ray);
#else
    const vec3 color = trace(ray);
#endif
    rt_debug_note(kDebugPixel, 0, vec4(color, 0));
    return color;
}
#endif
