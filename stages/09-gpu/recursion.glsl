// Stage 09, reflection and refraction: stage 05 (stages/05-recursion/recursion.cpp) in GLSL.
// The recursion itself is gone: the framework's loop in shaders/trace.glsl keeps an explicit
// stack of rays, as framework/render/shade.cpp does. GLSL has reflect() and refract() built in
// (with other conventions), so these are named *_direction.
// Handout: stages/09-gpu/README.md#reflection-and-refraction.

// d - 2 (d.n) n.
vec3 reflect_direction(vec3 d, vec3 n) {
    // BEGIN SOLUTION
    return d - 2.0 * dot(d, n) * n;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#reflection-and-refraction
    // return d;
    // END SOLUTION
}

// Snell's law, d unit, n unit on the incoming side, eta = n_in / n_out. False on total internal
// reflection (refracted left alone).
bool refract_direction(vec3 d, vec3 n, float eta, inout vec3 refracted) {
    // BEGIN SOLUTION
    const float cos_i = min(1.0, -dot(d, n));
    const float sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t >= 1.0) return false;
    const float cos_t = sqrt(1.0 - sin2_t);
    refracted = normalize(eta * d + (eta * cos_i - cos_t) * n);
    return true;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#reflection-and-refraction
    // return false;
    // END SOLUTION
}

// Schlick's approximation, in [0, 1]; 1 past the critical angle.
float schlick_reflectance(float cos_incident, float n1, float n2) {
    // BEGIN SOLUTION
    float cosine = clamp(cos_incident, 0.0, 1.0);
    if (n1 > n2) {
        const float sin2_t = (n1 / n2) * (n1 / n2) * (1.0 - cosine * cosine);
        if (sin2_t >= 1.0) return 1.0;
        cosine = sqrt(1.0 - sin2_t);
    }
    float r0 = (n1 - n2) / (n1 + n2);
    r0 *= r0;
    const float x = 1.0 - cosine;
    return r0 + (1.0 - r0) * x * x * x * x * x;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#reflection-and-refraction
    // return 0.0;
    // END SOLUTION
}

struct SecondaryRay {
    Ray ray;
    vec3 weight;
    bool valid;
};
struct SecondaryRays {
    SecondaryRay reflected, refracted;
    bool total_internal_reflection;
};

// Stage 05's secondary_rays: weights k_r and k_t (Fresnel and total internal reflection move
// weight from refraction to reflection), origins from offset_ray_origin; zero weight: not valid.
SecondaryRays secondary_rays(Ray incoming, SurfacePoint at, Material material, bool use_fresnel) {
    SecondaryRays result;
    result.reflected.valid = false;
    result.refracted.valid = false;
    result.total_internal_reflection = false;
    // BEGIN SOLUTION
    const vec3 d = normalize(incoming.direction);
    const vec3 n = at.normal;
    vec3 k_r = material.reflective.rgb, k_t = material.transmissive_ior.rgb;
    vec3 refracted = vec3(0);
    if (k_t != vec3(0)) {
        const float ior = material.transmissive_ior.w;
        const float n1 = at.front_face ? 1.0 : ior;
        const float n2 = at.front_face ? ior : 1.0;
        if (!refract_direction(d, n, n1 / n2, refracted)) {
            result.total_internal_reflection = true;
            k_r += k_t;
            k_t = vec3(0);
        } else if (use_fresnel) {
            const float f = schlick_reflectance(-dot(d, n), n1, n2);
            k_r += f * k_t;
            k_t *= 1.0 - f;
        }
    }
    if (k_r != vec3(0)) {
        const vec3 r = reflect_direction(d, n);
        result.reflected = SecondaryRay(Ray(offset_ray_origin(at.point, at.error, n, r), r), k_r, true);
    }
    if (k_t != vec3(0))
        result.refracted = SecondaryRay(
            Ray(offset_ray_origin(at.point, at.error, n, refracted), refracted), k_t, true);
    return result;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#reflection-and-refraction
    // return result;
    // END SOLUTION
}
