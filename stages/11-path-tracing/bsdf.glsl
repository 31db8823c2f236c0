// Stage 11 on the GPU (optional): bsdf.cpp in GLSL, for `rt render --gpu` and the viewer's GPU
// mode on stage 11 scenes. Handout: stages/11-path-tracing/README.md#optional-the-gpu.
// Needs stage 09's GLSL and stage 10's sampling.glsl (sample_cosine_hemisphere); stage 09's
// recursion.glsl gives refract_direction and schlick_reflectance. shaders/path_support.glsl
// gives BsdfSample, no_bsdf_sample() and material_roughness(m). The contracts are
// framework/stage_api/stage11.h's, in float: every direction is local, z the outward normal.
// Material colours: diffuse.rgb, specular_shininess.rgb (k_s), reflective.rgb,
// transmissive_ior.rgb and .w (the index of refraction).

float ggx_d(vec3 h, float alpha) {
    // BEGIN SOLUTION
    if (h.z <= 0.0) return 0.0;
    const float a2 = alpha * alpha;
    const float t = h.z * h.z * (a2 - 1.0) + 1.0;
    return a2 / (kPi * t * t);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#1-the-ggx-microfacet-distribution
    // return 0.0;
    // END SOLUTION
}

float ggx_g1(vec3 v, vec3 h, float alpha) {
    // BEGIN SOLUTION
    if (dot(v, h) * v.z <= 0.0) return 0.0;
    const float cos2 = v.z * v.z;
    const float tan2 = max(0.0, 1.0 - cos2) / cos2;
    return 2.0 / (1.0 + sqrt(1.0 + alpha * alpha * tan2));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#1-the-ggx-microfacet-distribution
    // return 0.0;
    // END SOLUTION
}

vec3 sample_ggx_normal(float alpha, vec2 u) {
    // BEGIN SOLUTION
    const float tan2 = alpha * alpha * u.x / (1.0 - u.x);
    const float cos_theta = 1.0 / sqrt(1.0 + tan2);
    const float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta));
    const float phi = 2.0 * kPi * u.y;
    return vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#2-sampling-the-ggx-lobe
    // return vec3(0, 0, 1);
    // END SOLUTION
}

float ggx_normal_pdf(vec3 h, float alpha) {
    // BEGIN SOLUTION
    return h.z > 0.0 ? ggx_d(h, alpha) * h.z : 0.0;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#2-sampling-the-ggx-lobe
    // return 0.0;
    // END SOLUTION
}

vec3 schlick_fresnel(vec3 f0, float cos_theta) {
    // BEGIN SOLUTION
    const float m = clamp(1.0 - cos_theta, 0.0, 1.0);
    const float m5 = m * m * m * m * m;
    return f0 + (vec3(1) - f0) * m5;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#1-the-ggx-microfacet-distribution
    // return f0;
    // END SOLUTION
}

// BEGIN SOLUTION
bool bsdf_lit(vec3 c) { return c.r > 0.0 || c.g > 0.0 || c.b > 0.0; }

float bsdf_mean(vec3 c) { return (c.r + c.g + c.b) / 3.0; }

vec3 specular_color(Material m) {
    return min(m.specular_shininess.rgb + m.reflective.rgb, vec3(1));
}

// The chance that sample_bsdf picks the specular lobe of an opaque material.
float specular_chance(Material m) {
    const float s = bsdf_mean(specular_color(m)), d = bsdf_mean(m.diffuse.rgb);
    return s + d > 0.0 ? s / (s + d) : 0.0;
}

// The GGX BRDF for wo, wi in the upper hemisphere.
vec3 ggx_brdf(Material m, vec3 wo, vec3 wi) {
    const float roughness = material_roughness(m), alpha = roughness * roughness;
    const vec3 h = normalize(wo + wi);
    const float g = ggx_g1(wo, h, alpha) * ggx_g1(wi, h, alpha);
    const float d = ggx_d(h, alpha);
    const vec3 f = schlick_fresnel(specular_color(m), dot(wo, h));
    return f * (d * g / (4.0 * wo.z * wi.z));
}

// The density of wi from the GGX lobe alone: D(h) h.z / (4 wo.h), wo and wi upper.
float ggx_pdf(Material m, vec3 wo, vec3 wi) {
    const float roughness = material_roughness(m);
    const vec3 h = normalize(wo + wi);
    return ggx_normal_pdf(h, roughness * roughness) / (4.0 * abs(dot(wo, h)));
}

// Glass: reflect with probability F, refract otherwise (stage 05's refract and Schlick).
BsdfSample sample_dielectric(Material m, vec3 wo, float u_lobe) {
    BsdfSample s = no_bsdf_sample();
    s.delta = true;
    const bool entering = wo.z > 0.0;
    const float ior = m.transmissive_ior.w;
    const float n1 = entering ? 1.0 : ior, n2 = entering ? ior : 1.0;
    const float reflectance = schlick_reflectance(abs(wo.z), n1, n2);
    vec3 refracted = vec3(0);
    const vec3 normal = vec3(0, 0, entering ? 1.0 : -1.0);
    if (u_lobe < reflectance || !refract_direction(-wo, normal, n1 / n2, refracted)) {
        s.wi = vec3(-wo.x, -wo.y, wo.z);
        s.weight = vec3(1);
        return s;
    }
    s.wi = refracted;
    s.weight = m.transmissive_ior.rgb;
    return s;
}
// STUB
// // Helper functions of your own may go here.
// END SOLUTION

vec3 eval_bsdf(Material material, vec3 wo, vec3 wi) {
    // BEGIN SOLUTION
    if (bsdf_lit(material.transmissive_ior.rgb) || wo.z * wi.z <= 0.0) return vec3(0);
    const vec3 o = vec3(wo.xy, abs(wo.z)), i = vec3(wi.xy, abs(wi.z));  // upper side
    vec3 f = material.diffuse.rgb * (1.0 / kPi);
    if (material_roughness(material) > 0.0 && bsdf_lit(specular_color(material)))
        f += ggx_brdf(material, o, i);
    return f;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#3-the-bsdf-of-a-material
    // return vec3(0);
    // END SOLUTION
}

float bsdf_pdf(Material material, vec3 wo, vec3 wi) {
    // BEGIN SOLUTION
    if (bsdf_lit(material.transmissive_ior.rgb) || wo.z * wi.z <= 0.0) return 0.0;
    const vec3 o = vec3(wo.xy, abs(wo.z)), i = vec3(wi.xy, abs(wi.z));
    const float p_s = specular_chance(material);
    float pdf = (1.0 - p_s) * i.z / kPi;
    if (material_roughness(material) > 0.0 && p_s > 0.0) pdf += p_s * ggx_pdf(material, o, i);
    return pdf;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#3-the-bsdf-of-a-material
    // return 0.0;
    // END SOLUTION
}

BsdfSample sample_bsdf(Material material, vec3 wo, float u_lobe, vec2 u) {
    BsdfSample s = no_bsdf_sample();
    // BEGIN SOLUTION
    if (bsdf_lit(material.transmissive_ior.rgb)) return sample_dielectric(material, wo, u_lobe);
    const float side = wo.z < 0.0 ? -1.0 : 1.0;  // work in wo's hemisphere, then flip back
    const vec3 o = vec3(wo.xy, side * wo.z);
    const float p_s = specular_chance(material), roughness = material_roughness(material);
    vec3 i;
    if (u_lobe < p_s) {
        if (roughness == 0.0) {  // the mirror: a delta lobe
            s.delta = true;
            s.wi = vec3(-wo.x, -wo.y, wo.z);
            s.weight = schlick_fresnel(specular_color(material), o.z) / p_s;
            return s;
        }
        const vec3 h = sample_ggx_normal(roughness * roughness, u);
        i = 2.0 * dot(o, h) * h - o;
        if (i.z <= 0.0) return s;  // below the surface: absorbed
    } else {
        i = sample_cosine_hemisphere(u);
    }
    s.wi = vec3(i.xy, side * i.z);
    s.pdf = bsdf_pdf(material, wo, s.wi);
    if (!(s.pdf > 0.0)) return no_bsdf_sample();
    s.weight = eval_bsdf(material, wo, s.wi) * (i.z / s.pdf);
    return s;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/11-path-tracing/README.md#3-the-bsdf-of-a-material
    // return s;
    // END SOLUTION
}
