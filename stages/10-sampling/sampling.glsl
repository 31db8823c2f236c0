// Stage 10 on the GPU (optional): sampling.cpp and lights.cpp in GLSL, for `rt render --gpu` and
// the viewer's GPU mode on stage 10 scenes. Handout: stages/10-sampling/README.md#optional-the-gpu.
// Needs stage 09's GLSL (stages/09-gpu/): Ray, SurfacePoint, LightSample, blinn_phong,
// light_transmittance, nearest_hit, offset_ray_origin come from there and from
// shaders/framework.glsl. As in C++, every u is uniform in [0, 1): the framework draws it
// (shaders/trace.glsl, a PCG hash of the pixel, the sample and the scene's seed); these functions
// only warp it. The contracts are framework/stage_api/stage10.h's, in float.
// Area lights are area_lights[i] (shaders/scene_layout.glsl): corner_kind.w (floatBitsToInt)
// 0 rectangle, 1 sphere.

// ---------------------------------------------------------------- as sampling.cpp

vec2 stratified_sample(int index, int count, vec2 u) {
    // BEGIN SOLUTION
    int n = max(1, int(sqrt(float(max(count, 1)))));
    if ((n + 1) * (n + 1) <= count) ++n;  // sqrt may round below a perfect square
    if (n * n > count && n > 1) --n;
    if (index < 0 || index >= n * n) return u;
    return (vec2(float(index % n), float(index / n)) + u) / float(n);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#1-pixel-samples-and-filters
    // return u;
    // END SOLUTION
}

vec2 box_filter_offset(vec2 u) {
    // BEGIN SOLUTION
    return u - 0.5;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#1-pixel-samples-and-filters
    // return vec2(0);
    // END SOLUTION
}

vec2 tent_filter_offset(vec2 u) {
    // BEGIN SOLUTION
    const bvec2 low = lessThan(u, vec2(0.5));
    const vec2 below = sqrt(2.0 * u) - 1.0, above = 1.0 - sqrt(max(vec2(0), 2.0 - 2.0 * u));
    return vec2(low.x ? below.x : above.x, low.y ? below.y : above.y);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#1-pixel-samples-and-filters
    // return vec2(0);
    // END SOLUTION
}

vec2 sample_uniform_disk(vec2 u) {
    // BEGIN SOLUTION
    const float r = sqrt(u.x), phi = 2.0 * kPi * u.y;
    return r * vec2(cos(phi), sin(phi));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#2-disk-hemisphere-and-sphere
    // return vec2(0);
    // END SOLUTION
}

vec3 sample_cosine_hemisphere(vec2 u) {
    // BEGIN SOLUTION
    const vec2 d = sample_uniform_disk(u);
    return vec3(d, sqrt(max(0.0, 1.0 - dot(d, d))));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#2-disk-hemisphere-and-sphere
    // return vec3(0, 0, 1);
    // END SOLUTION
}

float cosine_hemisphere_pdf(vec3 direction) {
    // BEGIN SOLUTION
    return direction.z > 0.0 ? direction.z / kPi : 0.0;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#2-disk-hemisphere-and-sphere
    // return 0.0;
    // END SOLUTION
}

vec3 sample_uniform_sphere(vec2 u) {
    // BEGIN SOLUTION
    const float z = 1.0 - 2.0 * u.x, r = sqrt(max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#2-disk-hemisphere-and-sphere
    // return vec3(0, 0, 1);
    // END SOLUTION
}

// The camera is the uniform `camera` (eye, u, v, w); `pinhole` starts at camera.eye.
Ray thin_lens_ray(Ray pinhole, float aperture, float focus_distance, vec2 u) {
    // BEGIN SOLUTION
    const vec3 focus =
        pinhole.origin + pinhole.direction * (focus_distance / dot(pinhole.direction, -camera.w));
    const vec2 d = sample_uniform_disk(u) * (aperture / 2.0);
    const vec3 lens = camera.eye + d.x * camera.u + d.y * camera.v;
    return Ray(lens, normalize(focus - lens));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#3-depth-of-field-and-motion-blur
    // return pinhole;
    // END SOLUTION
}

float shutter_time(float open, float close, float u) {
    // BEGIN SOLUTION
    return open + u * (close - open);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#3-depth-of-field-and-motion-blur
    // return open;
    // END SOLUTION
}

// ---------------------------------------------------------------- as lights.cpp

struct AreaSample {
    vec3 point;   // on the light
    vec3 normal;  // the light's unit outward normal there
    float pdf;    // per unit solid angle, seen from `from`
};

AreaSample sample_rectangle(AreaLight light, vec3 from, vec2 u) {
    AreaSample s = AreaSample(vec3(0), vec3(0), 0.0);
    // BEGIN SOLUTION
    s.point = light.corner_kind.xyz + u.x * light.edge_u.xyz + u.y * light.edge_v.xyz;
    const vec3 c = cross(light.edge_u.xyz, light.edge_v.xyz);
    const float area = length(c);
    s.normal = c / area;
    const vec3 d = s.point - from;
    const float distance2 = dot(d, d);
    const float cosine = abs(dot(s.normal, d)) / sqrt(distance2);
    s.pdf = cosine > 0.0 ? distance2 / (cosine * area) : 0.0;
    return s;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#4-sampling-area-lights
    // return s;
    // END SOLUTION
}

float rectangle_pdf(AreaLight light, vec3 from, vec3 direction) {
    // BEGIN SOLUTION
    const vec3 c = cross(light.edge_u.xyz, light.edge_v.xyz);
    const float area = length(c);
    const vec3 n = c / area;
    const float denominator = dot(n, direction);
    if (denominator == 0.0) return 0.0;
    const float t = dot(n, light.corner_kind.xyz - from) / denominator;
    if (!(t > 0.0)) return 0.0;
    const vec3 p = from + t * direction - light.corner_kind.xyz;
    const float s = dot(p, light.edge_u.xyz) / dot(light.edge_u.xyz, light.edge_u.xyz);
    const float r = dot(p, light.edge_v.xyz) / dot(light.edge_v.xyz, light.edge_v.xyz);
    if (s < 0.0 || s > 1.0 || r < 0.0 || r > 1.0) return 0.0;
    return t * t / (abs(denominator) * area);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#4-sampling-area-lights
    // return 0.0;
    // END SOLUTION
}

// An orthonormal frame (t, b, n) around the unit n (geometry/onb.h's onb_around).
void frame_around(vec3 n, out vec3 t, out vec3 b) {
    const float sign = n.z >= 0.0 ? 1.0 : -1.0;
    const float a = -1.0 / (sign + n.z);
    const float k = n.x * n.y * a;
    t = vec3(1.0 + sign * n.x * n.x * a, sign * k, -sign * n.x);
    b = vec3(k, sign + n.y * n.y * a, -n.y);
}

AreaSample sample_sphere(AreaLight light, vec3 from, vec2 u) {
    AreaSample s = AreaSample(vec3(0), vec3(0), 0.0);
    // BEGIN SOLUTION
    const vec3 to_center = light.center_radius.xyz - from;
    const float radius = light.center_radius.w;
    const float distance = length(to_center);
    if (!(distance > radius)) return s;
    const float sin2_max = radius * radius / (distance * distance);
    const float cos_max = sqrt(max(0.0, 1.0 - sin2_max));
    const float one_minus_cos_max = sin2_max / (1.0 + cos_max);
    const float cos_theta = 1.0 - u.x * one_minus_cos_max;
    const float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta));
    const float phi = 2.0 * kPi * u.y;
    const vec3 n = to_center / distance;
    vec3 t, b;
    frame_around(n, t, b);
    const vec3 direction = sin_theta * cos(phi) * t + sin_theta * sin(phi) * b + cos_theta * n;
    const float half_chord =
        sqrt(max(0.0, radius * radius - distance * distance * sin_theta * sin_theta));
    s.point = from + (distance * cos_theta - half_chord) * direction;
    s.normal = normalize(s.point - light.center_radius.xyz);
    s.pdf = 1.0 / (2.0 * kPi * one_minus_cos_max);
    return s;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#4-sampling-area-lights
    // return s;
    // END SOLUTION
}

float sphere_pdf(AreaLight light, vec3 from, vec3 direction) {
    // BEGIN SOLUTION
    const vec3 to_center = light.center_radius.xyz - from;
    const float radius = light.center_radius.w;
    const float distance = length(to_center);
    if (!(distance > radius)) return 0.0;
    const float sin2_max = radius * radius / (distance * distance);
    const float cos_max = sqrt(max(0.0, 1.0 - sin2_max));
    if (dot(direction, to_center) / distance < cos_max) return 0.0;
    return 1.0 / (2.0 * kPi * sin2_max / (1.0 + cos_max));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#4-sampling-area-lights
    // return 0.0;
    // END SOLUTION
}

// intensity = radiance / (pi pdf); all zero for the back of a rectangle or a zero pdf.
LightSample sample_area_light(AreaLight light, vec3 point, vec2 u) {
    LightSample out_sample = LightSample(vec3(0), 0.0, vec3(0));
    // BEGIN SOLUTION
    // An if, not ?: (WebGL rejects ?: on structs, and rt export-web runs this in a browser).
    AreaSample s;
    if (floatBitsToInt(light.corner_kind.w) == 0)
        s = sample_rectangle(light, point, u);
    else
        s = sample_sphere(light, point, u);
    if (!(s.pdf > 0.0)) return out_sample;
    const vec3 d = s.point - point;
    out_sample.distance = length(d);
    out_sample.direction = d / out_sample.distance;
    if (dot(s.normal, out_sample.direction) >= 0.0) return out_sample;
    out_sample.intensity = light.radiance.rgb / (kPi * s.pdf);
    return out_sample;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#5-soft-shadows
    // return out_sample;
    // END SOLUTION
}

// blinn_phong of one sample times light_transmittance (stage 09's shade.glsl).
vec3 area_light_estimate(Material material, SurfacePoint at, vec3 normal, vec3 to_viewer,
                         AreaLight light, vec2 u) {
    // BEGIN SOLUTION
    const LightSample s = sample_area_light(light, at.point, u);
    if (s.intensity == vec3(0)) return vec3(0);
    const vec3 reflected = blinn_phong(material, normal, to_viewer, s.direction, s.intensity);
    if (reflected == vec3(0)) return reflected;
    return reflected * light_transmittance(at, s);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#5-soft-shadows
    // return vec3(0);
    // END SOLUTION
}

vec3 glossy_direction(vec3 mirror, float fuzz, vec2 u) {
    // BEGIN SOLUTION
    return normalize(mirror + fuzz * sample_uniform_sphere(u));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#6-glossy-reflection
    // return mirror;
    // END SOLUTION
}

// A cosine-distributed ray about `normal` (frame_around above), from offset_ray_origin.
Ray cosine_ray(SurfacePoint at, vec3 normal, vec2 u) {
    // BEGIN SOLUTION
    vec3 t, b;
    frame_around(normal, t, b);
    const vec3 local = sample_cosine_hemisphere(u);
    const vec3 direction = local.x * t + local.y * b + local.z * normal;
    return Ray(offset_ray_origin(at.point, at.error, at.normal, direction), direction);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#7-ambient-occlusion-and-indirect-light
    // return Ray(at.point, normal);
    // END SOLUTION
}

// 1 when the cosine_ray meets nothing (nearest_hit: the BVH when the scene has one) closer than
// max_distance, else 0.
float ambient_occlusion(SurfacePoint at, vec3 normal, float max_distance, vec2 u) {
    // BEGIN SOLUTION
    Hit hit = no_hit();
    return nearest_hit(cosine_ray(at, normal, u), Interval(0.0, max_distance), hit) ? 0.0 : 1.0;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#7-ambient-occlusion-and-indirect-light
    // return 1.0;
    // END SOLUTION
}

// (k_d / pi) L cos / pdf for a cosine_ray; incoming_radiance(ray) is the framework's (the direct
// light where the ray lands, or the background). Do not add k_a I_a back.
vec3 indirect_diffuse(SurfacePoint at, vec3 normal, Material material, vec2 u) {
    // BEGIN SOLUTION
    return material.diffuse.rgb * incoming_radiance(cosine_ray(at, normal, u));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/10-sampling/README.md#7-ambient-occlusion-and-indirect-light
    // return vec3(0);
    // END SOLUTION
}
