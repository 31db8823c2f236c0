// Stage 09, intersections: stage 02 (stages/02-intersections/intersections.cpp) in GLSL.
// Handout: stages/09-gpu/README.md#intersections. The contract is stage 02's
// (framework/stage_api/stage02.h): accept t only in the open interval t_range; on a hit fill
// hit.t, hit.point, hit.normal and hit.front_face (set_face_normal), hit.uv, and return true; on a
// miss return false and leave `hit` alone. A zero, NaN or infinite direction hits nothing.
// `inout Hit hit` is GLSL's reference: the caller's variable is updated.

// Ray-sphere by the quadratic formula in the stable form. center_radius: xyz centre, w radius.
bool intersect_sphere(Ray ray, vec4 center_radius, Interval t_range, inout Hit hit) {
    // BEGIN SOLUTION
    const vec3 center = center_radius.xyz;
    const float radius = center_radius.w;
    const vec3 oc = ray.origin - center;
    const vec3 d = ray.direction;
    const float a = dot(d, d);
    if (!(a > 0.0) || isinf(a)) return false;
    const float half_b = dot(oc, d);
    const float c = dot(oc, oc) - radius * radius;
    const vec3 l = oc - (half_b / a) * d;
    const float discriminant = a * (radius * radius - dot(l, l));
    if (discriminant < 0.0) return false;
    // q has the sign of -half_b (GLSL's sign() is 0 at 0: C++'s copysign is not).
    const float root = sqrt(discriminant);
    const float q = -(half_b + (half_b < 0.0 ? -root : root));
    float t0 = q / a;
    float t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) {
        const float swap = t0;
        t0 = t1;
        t1 = swap;
    }
    float t = t0;
    if (!contains(t_range, t)) {
        t = t1;
        if (!contains(t_range, t)) return false;
    }
    hit.t = t;
    hit.point = ray.origin + t * ray.direction;
    const vec3 outward = (hit.point - center) / radius;
    set_face_normal(hit, ray, outward);
    hit.uv = vec2(0);  // a texture's (u, v) are sphere_texcoord's, at the shaded hit only
    return true;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#intersections
    // return false;
    // END SOLUTION
}

// Ray-plane; a ray parallel to the plane misses. The outward normal is `normal`; uv (0, 0).
bool intersect_plane(Ray ray, vec3 point, vec3 normal, Interval t_range, inout Hit hit) {
    // BEGIN SOLUTION
    const float denominator = dot(normal, ray.direction);
    if (denominator == 0.0 || isinf(denominator) || isnan(denominator)) return false;
    const float t = dot(normal, point - ray.origin) / denominator;
    if (!contains(t_range, t)) return false;
    hit.t = t;
    hit.point = ray.origin + t * ray.direction;
    set_face_normal(hit, ray, normal);
    hit.uv = vec2(0);
    return true;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#intersections
    // return false;
    // END SOLUTION
}

// Ray-triangle by Cramer's rule: solve [a-b, a-c, d] (beta, gamma, t)^T = a - o. The outward
// normal is normalize(cross(b - a, c - a)); uv = (beta, gamma).
bool intersect_triangle(Ray ray, vec3 a, vec3 b, vec3 c, Interval t_range, inout Hit hit) {
    // BEGIN SOLUTION
    const vec3 col1 = a - b;
    const vec3 col2 = a - c;
    const vec3 col3 = ray.direction;
    const vec3 rhs = a - ray.origin;
    const float det_m = dot(col1, cross(col2, col3));
    if (det_m == 0.0 || isinf(det_m) || isnan(det_m)) return false;
    const float t = dot(col1, cross(col2, rhs)) / det_m;
    if (!contains(t_range, t)) return false;
    const float gamma = dot(col1, cross(rhs, col3)) / det_m;
    if (gamma < 0.0 || gamma > 1.0) return false;
    const float beta = dot(rhs, cross(col2, col3)) / det_m;
    if (beta < 0.0 || beta > 1.0 - gamma) return false;
    hit.t = t;
    hit.point = ray.origin + t * ray.direction;
    set_face_normal(hit, ray, normalize(cross(b - a, c - a)));
    hit.uv = vec2(beta, gamma);
    return true;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#intersections
    // return false;
    // END SOLUTION
}

// Ray-box by slabs; the normal is that of the face hit (entry, or exit from inside); uv (0, 0).
bool intersect_box(Ray ray, vec3 lo, vec3 hi, Interval t_range, inout Hit hit) {
    // BEGIN SOLUTION
    const vec3 o = ray.origin, d = ray.direction;
    if (any(isinf(d)) || any(isnan(d)) || d == vec3(0)) return false;
    // The three slabs at once, with selects rather than branches (on llvmpipe every branch costs
    // all 8 lanes). A slab parallel to the ray (d[i] == 0) holds it for every t, or never.
    const bvec3 parallel = equal(d, vec3(0));
    const bvec3 outside = bvec3(uvec3(lessThan(o, lo)) | uvec3(greaterThan(o, hi)));
    if (any(bvec3(uvec3(parallel) & uvec3(outside)))) return false;
    const vec3 t0 = (lo - o) / d, t1 = (hi - o) / d;
    const bvec3 swapped = greaterThan(t0, t1);
    const vec3 t_in = mix(mix(t0, t1, swapped), vec3(-kInfinity), parallel);
    const vec3 t_out = mix(mix(t1, t0, swapped), vec3(kInfinity), parallel);
    const float t_near = max(max(t_in.x, t_in.y), t_in.z);
    const float t_far = min(min(t_out.x, t_out.y), t_out.z);
    if (t_near > t_far) return false;
    // The face: the first axis that reaches t_near (t_far), as a loop over the axes would find.
    const int near_axis = t_in.x == t_near ? 0 : t_in.y == t_near ? 1 : 2;
    const int far_axis = t_out.x == t_far ? 0 : t_out.y == t_far ? 1 : 2;
    const bool entering = contains(t_range, t_near);
    if (!entering && !contains(t_range, t_far)) return false;
    const float t = entering ? t_near : t_far;
    const int axis = entering ? near_axis : far_axis;
    const bool along = (axis == 0 ? d.x : axis == 1 ? d.y : d.z) > 0.0;
    const float sign = along == entering ? -1.0 : 1.0;  // entered against d, or left along it
    const vec3 outward = mix(vec3(0), vec3(sign), equal(ivec3(axis), ivec3(0, 1, 2)));
    hit.t = t;
    hit.point = ray.origin + t * ray.direction;
    set_face_normal(hit, ray, outward);
    hit.uv = vec2(0);
    return true;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#intersections
    // return false;
    // END SOLUTION
}

// The nearest hit over every primitive (no BVH), filling hit.primitive (primitive_id) and
// hit.material. The HAS_* macros say which arrays the scene has: skip the others, so the
// compiled shader holds only the loops this scene needs.
bool intersect_nearest(Ray ray, Interval t_range, inout Hit hit) {
    // BEGIN SOLUTION
    bool found = false;
#ifdef HAS_SPHERES
    for (int i = 0; i < primitive_counts.x; ++i)
        if (intersect_sphere(ray, spheres_at(i).center_radius, t_range, hit)) {
            found = true;
            t_range.max = hit.t;
            hit.primitive = primitive_id(kSphere, i);
            hit.material = spheres_at(i).material.x;
        }
#endif
#ifdef HAS_PLANES
    for (int i = 0; i < primitive_counts.y; ++i)
        if (intersect_plane(ray, planes_at(i).point_material.xyz, planes_at(i).normal.xyz, t_range,
                            hit)) {
            found = true;
            t_range.max = hit.t;
            hit.primitive = primitive_id(kPlane, i);
            hit.material = floatBitsToInt(planes_at(i).point_material.w);
        }
#endif
#ifdef HAS_TRIANGLES
    for (int i = 0; i < primitive_counts.z; ++i) {
        vec3 a, b, c;
        triangle_vertices(i, a, b, c);
        if (intersect_triangle(ray, a, b, c, t_range, hit)) {
            found = true;
            t_range.max = hit.t;
            hit.primitive = primitive_id(kTriangle, i);
            hit.material = int(triangles_at(i).vertices_material.w);
        }
    }
#endif
#ifdef HAS_BOXES
    for (int i = 0; i < primitive_counts.w; ++i)
        if (intersect_box(ray, boxes_at(i).min_material.xyz, boxes_at(i).max.xyz, t_range, hit)) {
            found = true;
            t_range.max = hit.t;
            hit.primitive = primitive_id(kBox, i);
            hit.material = floatBitsToInt(boxes_at(i).min_material.w);
        }
#endif
    return found;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#intersections
    // return false;
    // END SOLUTION
}
