// Stage 11 on the GPU (optional): path.cpp in GLSL, for `rt render --gpu` and the viewer's GPU
// mode on stage 11 scenes. Handout: stages/11-path-tracing/README.md#optional-the-gpu.
// Needs bsdf.glsl (beside it), stage 10's sampling.glsl (sample_rectangle, sample_sphere,
// rectangle_pdf, sphere_pdf) and stage 09's nearest_hit. shaders/path_support.glsl gives Onb
// (onb_around, to_local, to_world), spawn_ray and nearest_area_light. The scene is global: the
// area lights are area_lights[i] for i < int(sampling.seed_counts.z) (corner_kind.w's int bits:
// 0 rectangle, 1 sphere), max_depth is a uniform, background(direction) is the sky (stage 09's
// environment_radiance) or background_color, material_at(hit.material) is a hit's material. The random numbers are rng_next() and rng_next2(), drawn in the order of
// stage_api/stage11.h's path_radiance. The contracts are stage_api/stage11.h's, in float.

float balance_heuristic(float pdf_f, float pdf_g) {
    // BEGIN SOLUTION
    return pdf_f + pdf_g > 0.0 ? pdf_f / (pdf_f + pdf_g) : 0.0;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#4-multiple-importance-sampling
    // return 0.0;
    // END SOLUTION
}

float power_heuristic(float pdf_f, float pdf_g) {
    // BEGIN SOLUTION
    const float f2 = pdf_f * pdf_f, g2 = pdf_g * pdf_g;
    return f2 + g2 > 0.0 ? f2 / (f2 + g2) : 0.0;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#4-multiple-importance-sampling
    // return 0.0;
    // END SOLUTION
}

// BEGIN SOLUTION
int area_light_count() { return min(int(sampling.seed_counts.z), MAX_AREA_LIGHTS); }

// The solid-angle density with which light sampling picks `direction` from `from`: the light's
// own (stage 10) over the number of lights.
float light_pdf(AreaLight light, vec3 from, vec3 direction) {
    const float pdf = floatBitsToInt(light.corner_kind.w) == 0
                          ? rectangle_pdf(light, from, direction)
                          : sphere_pdf(light, from, direction);
    return pdf / float(area_light_count());
}
// STUB
// // Helper functions of your own may go here.
// END SOLUTION

// `frame`: the local shading frame (z outward); wo local.
vec3 sample_light_mis(SurfacePoint at, Onb frame, Material material, vec3 wo, float u_light,
                      vec2 u) {
    // BEGIN SOLUTION
    const int count = area_light_count();
    if (count == 0) return vec3(0);
    const AreaLight light = area_lights[min(count - 1, int(u_light * float(count)))];
    // An if, not ?: on a struct (as stage 10's sample_area_light).
    AreaSample a;
    if (floatBitsToInt(light.corner_kind.w) == 0)
        a = sample_rectangle(light, at.point, u);
    else
        a = sample_sphere(light, at.point, u);
    if (!(a.pdf > 0.0)) return vec3(0);
    const vec3 to_light = a.point - at.point;
    const float distance = length(to_light);
    const vec3 direction = to_light / distance;
    if (dot(a.normal, direction) >= 0.0) return vec3(0);  // the back of a rectangle
    const vec3 wi = to_local(frame, direction);
    const vec3 f = eval_bsdf(material, wo, wi);
    if (f == vec3(0)) return vec3(0);
    Hit blocker = no_hit();
    const vec3 side = dot(direction, at.normal) > 0.0 ? at.normal : -at.normal;
    if (nearest_hit(spawn_ray(at, side, direction), Interval(0.0, distance * 0.9999), blocker))
        return vec3(0);
    const float p_light = a.pdf / float(count);
    const float weight = power_heuristic(p_light, bsdf_pdf(material, wo, wi));
    return f * light.radiance.rgb * (abs(wi.z) * weight / p_light);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#5-next-event-estimation
    // return vec3(0);
    // END SOLUTION
}

// GLSL has no recursion: the path is a loop, at most max_depth + 1 surfaces long.
vec3 path_radiance(Ray camera_ray) {
    vec3 radiance = vec3(0);
    // BEGIN SOLUTION
    vec3 throughput = vec3(1);
    Ray ray = camera_ray;
    bool full_weight = true;  // the camera ray, or a delta bounce: no light sampling competed
    float bounce_pdf = 0.0;
    for (int depth = 0; depth <= max_depth; ++depth) {
        Hit hit = no_hit();
        const bool found = nearest_hit(ray, Interval(0.0, kInfinity), hit);
        const AreaLightHit light = nearest_area_light(ray, Interval(0.0, hit.t));
        if (light.light >= 0) {
            const vec3 d = normalize(ray.direction);
            const float weight =
                full_weight ? 1.0
                            : power_heuristic(bounce_pdf,
                                              light_pdf(area_lights[light.light], ray.origin, d));
            radiance += throughput * light.radiance * weight;
            break;
        }
        if (!found) {
            radiance += throughput * background(ray.direction);  // the sky, if any
            break;
        }
        const SurfacePoint at = surface_point(ray, hit);
        const Material material = material_at(hit.material);
        radiance += throughput * material.emissive.rgb;  // never light-sampled: full weight
        if (depth >= max_depth) break;
        const Onb frame = onb_around(at.front_face ? at.normal : -at.normal);
        const vec3 wo = to_local(frame, -normalize(ray.direction));
        const float u_light = rng_next();
        const vec2 u = rng_next2();
        radiance += throughput * sample_light_mis(at, frame, material, wo, u_light, u);
        const float u_lobe = rng_next();
        const BsdfSample s = sample_bsdf(material, wo, u_lobe, rng_next2());
        if (s.weight == vec3(0)) break;
        throughput *= s.weight;
        full_weight = s.delta;
        bounce_pdf = s.pdf;
        const vec3 direction = to_world(frame, s.wi);
        ray = spawn_ray(at, dot(direction, at.normal) > 0.0 ? at.normal : -at.normal, direction);
        if (depth >= 3) {  // Russian roulette, unbiased by the division
            const float q = min(0.95, max(throughput.r, max(throughput.g, throughput.b)));
            if (rng_next() >= q) break;
            throughput /= q;
        }
    }
    return radiance;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#6-the-path-tracer
    // return radiance;
    // END SOLUTION
}
