// The framework's side of the GPU stage (stage 09): the types the student functions share and
// the given geometry helpers (the GLSL twins of framework/core/hit.h and
// framework/geometry/offset.cpp). Included by trace.glsl after the scene's structs and what holds
// the scene (compute_io.glsl's uniforms, or an export's constants); everything here is float
// (GLSL has double, most GPUs run it slowly).

// A macro: uintBitsToFloat is not a constant expression for glslang.
#define kInfinity uintBitsToFloat(0x7f800000u)
const float kPi = 3.14159265358979323846;

struct Ray { vec3 origin; vec3 direction; };
// The open interval (min, max) of t a hit must lie in (core/ray.h).
struct Interval { float min; float max; };
bool contains(Interval range, float t) { return range.min < t && t < range.max; }

// What an intersection reports (core/hit.h); primitive: the global id (kind << 28 | index).
struct Hit {
    float t;
    vec3 point;
    vec3 normal;      // unit, facing the side the ray came from
    bool front_face;  // the ray arrived on the side the outward normal points to
    vec2 uv;          // triangles: barycentrics (beta, gamma)
    int primitive;
    int material;
};
Hit no_hit() { return Hit(kInfinity, vec3(0), vec3(0), true, vec2(0), -1, -1); }
void set_face_normal(inout Hit hit, Ray ray, vec3 outward_normal) {
    hit.front_face = dot(ray.direction, outward_normal) < 0.0;
    hit.normal = hit.front_face ? outward_normal : -outward_normal;
}

// kSphere, kPlane, kTriangle, kBox and kKindShift are the prelude's (framework/gpu/shader_constants.h).
int primitive_id(int kind, int index) { return (kind << kKindShift) | index; }
int primitive_kind(int id) { return id >> kKindShift; }
int primitive_index(int id) { return id & ((1 << kKindShift) - 1); }

// What the scene uses when the shader has it compiled in (scene_features: compute_io.glsl, or
// the constants of an export); the --uber shader tests these bits at run time.
// kFeatureBvh ... kFeaturePathTracing: the prelude's (framework/gpu/shader_constants.h).
bool scene_has(int feature) { return (scene_features & feature) != 0; }

// Stage 06's BvhStats::nodes_visited, without pointers: bvh_intersect_nearest adds each node whose
// box it tests (the bvh_visits view reads it).
uint bvh_nodes_visited = 0u;

// A hit made ready for shading and for spawning rays (geometry/offset.h).
struct SurfacePoint {
    vec3 point;   // on the surface, refined
    vec3 error;   // |computed - exact| <= error, per coordinate
    vec3 normal;  // unit, facing the incoming ray
    bool front_face;
    int primitive;
    int material;
};

float gamma_bound(int n) {
    const float u = 5.9604644775390625e-8;  // 2^-24: float's unit roundoff
    return float(n) * u / (1.0 - float(n) * u);
}

void triangle_vertices(int triangle, out vec3 a, out vec3 b, out vec3 c) {
    const uvec4 v = triangles_at(triangle).vertices_material;
    a = positions_at(v.x).xyz;
    b = positions_at(v.y).xyz;
    c = positions_at(v.z).xyz;
}

// geometry/offset.cpp's surface_point, line for line.
SurfacePoint surface_point(Ray ray, Hit hit) {
    SurfacePoint sp = SurfacePoint(hit.point, vec3(0), hit.normal, hit.front_face, hit.primitive,
                                   hit.material);
    const int i = primitive_index(hit.primitive);
    switch (primitive_kind(hit.primitive)) {  // only the scene's kinds: each case costs every lane
#ifdef HAS_SPHERES
        case kSphere: {
            const vec3 c = spheres_at(i).center_radius.xyz;
            const vec3 from_center = hit.point - c;
            const float len = length(from_center);
            if (len > 0.0) sp.point = c + from_center * (spheres_at(i).center_radius.w / len);
            sp.error = gamma_bound(8) * (abs(c) + abs(sp.point - c));
            break;
        }
#endif
#ifdef HAS_PLANES
        case kPlane: {
            const vec3 p0 = planes_at(i).point_material.xyz, n = planes_at(i).normal.xyz;
            sp.point = hit.point - n * dot(n, hit.point - p0);
            const float distance_error = gamma_bound(5) * dot(abs(n), abs(hit.point) + abs(p0));
            sp.error = abs(n) * distance_error + gamma_bound(2) * abs(sp.point);
            break;
        }
#endif
#ifdef HAS_TRIANGLES
        case kTriangle: {
            vec3 a, b, c;
            triangle_vertices(i, a, b, c);
            const float b1 = hit.uv.x, b2 = hit.uv.y, b0 = 1.0 - b1 - b2;
            sp.point = b0 * a + b1 * b + b2 * c;
            sp.error = gamma_bound(7) * (abs(b0 * a) + abs(b1 * b) + abs(b2 * c));
            break;
        }
#endif
#ifdef HAS_BOXES
        case kBox: {
            const vec3 lo = boxes_at(i).min_material.xyz, hi = boxes_at(i).max.xyz;
            const vec3 outward = hit.front_face ? hit.normal : -hit.normal;
            // The face's axis (the first of the largest |outward|), by selects: a vector indexed
            // by a run-time axis costs llvmpipe a trip through memory for each of its 8 lanes.
            const vec3 m = abs(outward);
            const int first = m.y > m.x ? 1 : 0;
            const int axis = m.z > (first == 1 ? m.y : m.x) ? 2 : first;
            const bvec3 on_axis = equal(ivec3(axis), ivec3(0, 1, 2));
            sp.point = mix(clamp(hit.point, lo, hi), mix(lo, hi, greaterThan(outward, vec3(0))),
                           on_axis);
            sp.error = mix(gamma_bound(3) * abs(sp.point), vec3(0), on_axis);
            break;
        }
#endif
    }
    return sp;
}

// The next float towards +inf (up) or -inf (down); x finite.
float next_float_up(float x) {
    if (x == 0.0) return uintBitsToFloat(1u);
    const uint bits = floatBitsToUint(x);
    return uintBitsToFloat(x > 0.0 ? bits + 1u : bits - 1u);
}
float next_float_down(float x) { return -next_float_up(-x); }

// geometry/offset.cpp's offset_ray_origin: just past the error box, on the side of `direction`.
vec3 offset_ray_origin(vec3 point, vec3 error, vec3 normal, vec3 direction) {
    const float d = dot(abs(normal), error);
    vec3 offset = d * normal;
    if (dot(direction, normal) < 0.0) offset = -offset;
    vec3 origin = point + offset;
    for (int k = 0; k < 3; ++k) {
        if (offset[k] > 0.0)
            origin[k] = next_float_up(origin[k]);
        else if (offset[k] < 0.0)
            origin[k] = next_float_down(origin[k]);
    }
    return origin;
}

// The material of index `m` (a scene built in code may lack one: the default material then).
Material material_at(int m) {
    if (m >= 0 && m < material_count) return materials_at(m);
    return Material(vec4(0), vec4(0.8), vec4(0, 0, 0, 32), vec4(0), vec4(0), vec4(0, 0, 0, 1.5),
                    ivec4(-1), vec4[4](vec4(1, 1, 0, 0), vec4(1, 1, 0, 0), vec4(1, 1, 0, 0),
                                       vec4(1, 1, 0, 0)));
}

// scene.cpp's shading_normal: vertex normals interpolated, facing like the geometric normal.
vec3 shading_normal(int triangle, vec2 uv) {
    vec3 a, b, c;
    triangle_vertices(triangle, a, b, c);
    vec3 geometric = cross(b - a, c - a);
    const float geometric_length = length(geometric);
    geometric = geometric_length > 0.0 && !isinf(geometric_length) ? geometric / geometric_length
                                                                    : vec3(0);
    const uvec4 v = triangles_at(triangle).vertices_material;
    const vec3 n0 = normals_at(v.x).xyz, n1 = normals_at(v.y).xyz, n2 = normals_at(v.z).xyz;
    if (n0 == vec3(0) || n1 == vec3(0) || n2 == vec3(0)) return geometric;
    vec3 n = (1.0 - uv.x - uv.y) * n0 + uv.x * n1 + uv.y * n2;
    const float len = length(n);
    if (!(len > 0.0) || isinf(len)) return geometric;
    n /= len;
    return dot(n, geometric) < 0.0 ? -n : n;
}

#ifndef HAS_DEBUG_PIXEL
// rt_debug(value) prints a value of the --debug-pixel pixel (shaders/debug_pixel.glsl); without
// --debug-pixel it and the framework's notes are nothing.
#define rt_debug(value)
#define rt_debug_note(kind, where, value)
#define rt_debug_note_typed(kind, where, type, value)
#endif
