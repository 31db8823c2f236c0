// Stage 09, direct light and shadows: stages 03 and 04 (stages/03-blinn-phong/blinn_phong.cpp,
// stages/04-shadows/shadows.cpp) in GLSL. Colours are linear RGB, nothing clamps.
// Handout: stages/09-gpu/README.md#direct-light-and-shadows.
// Lights: lights_at(i) (position_kind.w: floatBitsToInt, kLightPoint or kLightDirectional), light_count.

// What one light delivers at a point before shadowing (framework/stage_api/stage03.h).
struct LightSample {
    vec3 direction;  // unit, towards the light
    float distance;  // kInfinity for a directional light
    vec3 intensity;  // I_L / (c + l r + q r^2), or I_L for a directional light
};

LightSample illuminate(int light, vec3 point) {
    // BEGIN SOLUTION
    const Light l = lights_at(light);
    if (floatBitsToInt(l.position_kind.w) == kLightDirectional)
        return LightSample(-l.direction.xyz, kInfinity, l.intensity.rgb);
    const vec3 to_light = l.position_kind.xyz - point;
    const float r = length(to_light);
    const vec3 a = l.attenuation.xyz;
    return LightSample(r > 0.0 ? to_light / r : vec3(0), r,
                       l.intensity.rgb / (a.x + a.y * r + a.z * r * r));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#direct-light-and-shadows
    // return LightSample(vec3(0), 0.0, vec3(0));
    // END SOLUTION
}

// incident * (k_d max(0, N.L) + k_s max(0, N.H)^n_s); 0 when N.L <= 0.
vec3 blinn_phong(Material material, vec3 normal, vec3 to_viewer, vec3 to_light, vec3 incident) {
    // BEGIN SOLUTION
    const float n_dot_l = dot(normal, to_light);
    if (!(n_dot_l > 0.0)) return vec3(0);
    vec3 reflected = material.diffuse.rgb * n_dot_l;
    const vec3 half_vector = to_light + to_viewer;
    const float half_length = length(half_vector);
    if (half_length > 0.0) {
        const float n_dot_h = max(0.0, dot(normal, half_vector / half_length));
        reflected += material.specular_shininess.rgb * pow(n_dot_h, material.specular_shininess.w);
    }
    return incident * reflected;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#direct-light-and-shadows
    // return vec3(0);
    // END SOLUTION
}

// k_e + k_a I_a + sum over the lights of visibility[i] * blinn_phong(...). GLSL arrays have a
// size fixed at compile time: MAX_LIGHTS (the framework defines it from the scene).
vec3 direct_light(Material material, vec3 point, vec3 normal, vec3 to_viewer,
                  vec3 visibility[MAX_LIGHTS]) {
    // BEGIN SOLUTION
    vec3 color = material.emissive.rgb + material.ambient.rgb * ambient_light;
    for (int i = 0; i < light_count; ++i) {
        const LightSample s = illuminate(i, point);
        color += visibility[i] * blinn_phong(material, normal, to_viewer, s.direction, s.intensity);
    }
    return color;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#direct-light-and-shadows
    // return vec3(0);
    // END SOLUTION
}

struct ShadowRay {
    Ray ray;
    Interval t_range;
};

// Stage 04's shadow_ray: from offset_ray_origin towards the light, t up to the light.
ShadowRay shadow_ray(SurfacePoint at, LightSample s) {
    // BEGIN SOLUTION
    ShadowRay shadow;
    shadow.ray = Ray(offset_ray_origin(at.point, at.error, at.normal, s.direction), s.direction);
    shadow.t_range = Interval(0.0, kInfinity);
    if (s.distance < kInfinity) {
        const vec3 light_position = at.point + s.distance * s.direction;
        shadow.t_range.max = dot(light_position - shadow.ray.origin, s.direction);
    }
    return shadow;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#direct-light-and-shadows
    // return ShadowRay(Ray(at.point, s.direction), Interval(0.0, 0.0));
    // END SOLUTION
}

// Stage 04's light_transmittance: each surface crossed multiplies by its k_t, an opaque one
// gives 0; continue past a transparent one from offset_ray_origin, at most 64 surfaces.
// nearest_hit (shaders/trace.glsl) is the BVH when the scene has one, as on the CPU.
vec3 light_transmittance(SurfacePoint at, LightSample s) {
    // BEGIN SOLUTION
    ShadowRay shadow = shadow_ray(at, s);
    vec3 transmittance = vec3(1);
    for (int crossed = 0; crossed < 64; ++crossed) {
        Hit hit = no_hit();
        if (!nearest_hit(shadow.ray, shadow.t_range, hit)) return transmittance;
        transmittance *= material_at(hit.material).transmissive_ior.rgb;
        if (transmittance == vec3(0)) return transmittance;
        const SurfacePoint through = surface_point(shadow.ray, hit);
        const vec3 origin = offset_ray_origin(through.point, through.error, through.normal,
                                              shadow.ray.direction);
        shadow.t_range.max -= dot(origin - shadow.ray.origin, shadow.ray.direction);
        shadow.ray.origin = origin;
    }
    return vec3(0);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#direct-light-and-shadows
    // return vec3(1);
    // END SOLUTION
}
