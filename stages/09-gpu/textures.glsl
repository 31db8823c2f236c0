// Stage 09, textures: stage 07 (stages/07-textures/textures.cpp) in GLSL.
// Handout: stages/09-gpu/README.md#textures. Conventions: docs/conventions.md#textures.
// Given (shaders/texture_helpers.glsl): TextureView and stored_texel, plane_frame,
// noise_gradient, the wrap and filter constants. The framework's texturing step
// (shaders/texturing.glsl, a port of framework/render/texturing.cpp) calls these at each hit.
// Each group is compiled only when the scene needs it (the HAS_ defines of trace.comp).

#ifdef HAS_MAPS
// Longitude and latitude of the unit outward normal (docs/conventions.md#textures).
vec2 sphere_texcoord(vec3 outward_normal) {
    // BEGIN SOLUTION
    float phi = atan(-outward_normal.z, outward_normal.x);
    if (phi < 0.0) phi += 2.0 * kPi;
    const float theta = acos(clamp(outward_normal.y, -1.0, 1.0));
    return vec2(phi / (2.0 * kPi), theta / kPi);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return vec2(0);
    // END SOLUTION
}

// The point's offset from the plane's point along the plane's frame (plane_frame).
vec2 plane_texcoord(vec3 plane_point, vec3 plane_normal, vec3 point) {
    // BEGIN SOLUTION
    const PlaneFrame f = plane_frame(plane_normal);
    const vec3 d = point - plane_point;
    return vec2(dot(d, f.t), dot(d, f.b));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return vec2(0);
    // END SOLUTION
}

// The face's frame, centred on the face, each edge spanning 1.
vec2 box_texcoord(vec3 box_min, vec3 box_max, vec3 point, vec3 outward_normal) {
    // BEGIN SOLUTION
    const PlaneFrame f = plane_frame(outward_normal);
    const vec3 center = (box_min + box_max) / 2.0;
    const vec3 size = box_max - box_min;
    const vec3 d = point - center;
    const float width = dot(abs(f.t), size), height = dot(abs(f.b), size);
    return vec2(0.5 + dot(d, f.t) / width, 0.5 + dot(d, f.b) / height);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return vec2(0);
    // END SOLUTION
}

// The vertex uvs interpolated with the barycentrics (beta, gamma).
vec2 triangle_texcoord(vec2 uv_a, vec2 uv_b, vec2 uv_c, vec2 barycentric) {
    // BEGIN SOLUTION
    const float beta = barycentric.x, gamma = barycentric.y, alpha = 1.0 - beta - gamma;
    return alpha * uv_a + beta * uv_b + gamma * uv_c;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return vec2(0);
    // END SOLUTION
}
#endif  // HAS_MAPS

#ifdef HAS_IMAGE_LOOKUP
// One stored sRGB value in [0, 1] to linear light.
float srgb_to_linear_value(float encoded) {
    // BEGIN SOLUTION
    if (encoded <= 0.04045) return encoded / 12.92;
    return pow((encoded + 0.055) / 1.055, 2.4);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return 0.0;
    // END SOLUTION
}

// Texel (i, j) as linear colour: decoded when image.srgb.
vec3 decoded_texel(TextureView image, int i, int j) {
    // BEGIN SOLUTION
    const vec3 s = stored_texel(image, i, j);
    if (!image.srgb) return s;
    return vec3(srgb_to_linear_value(s.r), srgb_to_linear_value(s.g), srgb_to_linear_value(s.b));
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return vec3(0);
    // END SOLUTION
}

// Any texel index into [0, n). GLSL's % is undefined for a negative operand: keep them positive.
int wrap_texel(int i, int n, int wrap) {
    // BEGIN SOLUTION
    if (wrap == kWrapClamp) return clamp(i, 0, n - 1);
    const int period = wrap == kWrapRepeat ? n : 2 * n;
    const int k = i >= 0 ? i % period : period - 1 - (-(i + 1)) % period;  // in [0, period)
    return k < n ? k : 2 * n - 1 - k;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return 0;
    // END SOLUTION
}

// The index, in 0 .. n - 1, of the texel at coordinate `c` (in texels along a row or column of
// n, a whole number: sample_nearest and sample_bilinear floor it first) under `wrap`
// (kWrapRepeat, kWrapMirror or kWrapClamp), as wrap_texel(int(c), n, wrap) gives for any c that
// fits an int. c may be huge (a far-away plane's uv), negative or NaN (a degenerate uv: treat it
// as 0): reduce it first, by a whole number of periods for repeat and mirror (2n keeps both
// right) or by clamping to [-1, n], so that the conversion to int cannot overflow.
int texel_index(float c, int n, int wrap) {
    // BEGIN SOLUTION
    if (isnan(c)) c = 0.0;  // a degenerate uv must not reach int()
    c = wrap == kWrapClamp ? clamp(c, -1.0, float(n)) : mod(c, 2.0 * float(n));
    return wrap_texel(int(c), n, wrap);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return 0;
    // END SOLUTION
}

// The texel whose square contains (u * width, v * height).
vec3 sample_nearest(TextureView image, vec2 uv, int wrap) {
    // BEGIN SOLUTION
    const int i = texel_index(floor(uv.x * float(image.width)), image.width, wrap);
    const int j = texel_index(floor(uv.y * float(image.height)), image.height, wrap);
    return decoded_texel(image, i, j);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return vec3(0);
    // END SOLUTION
}

// The four texels around (u, v), weighted by distance.
vec3 sample_bilinear(TextureView image, vec2 uv, int wrap) {
    // BEGIN SOLUTION
    // Texel centres sit at half-integers: shift by 0.5 so that they sit at integers.
    const float x = uv.x * float(image.width) - 0.5, y = uv.y * float(image.height) - 0.5;
    const float x0 = floor(x), y0 = floor(y);
    const float fx = x - x0, fy = y - y0;
    const int i = texel_index(x0, image.width, wrap);
    const int i1 = texel_index(x0 + 1.0, image.width, wrap);
    const int j = texel_index(y0, image.height, wrap);
    const int j1 = texel_index(y0 + 1.0, image.height, wrap);
    const vec3 top = (1.0 - fx) * decoded_texel(image, i, j) + fx * decoded_texel(image, i1, j);
    const vec3 bottom =
        (1.0 - fx) * decoded_texel(image, i, j1) + fx * decoded_texel(image, i1, j1);
    return (1.0 - fy) * top + fy * bottom;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return vec3(0);
    // END SOLUTION
}
#endif  // HAS_IMAGE_LOOKUP

#ifdef HAS_CHECKER_TEXTURES
// Unit squares in (u, v), a on even squares.
vec3 checker_2d(vec2 uv, vec3 a, vec3 b) {
    // BEGIN SOLUTION
    const int sum = int(floor(uv.x)) + int(floor(uv.y));
    return (sum & 1) == 0 ? a : b;  // & 1, not % 2: GLSL's % of a negative is undefined
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return vec3(0);
    // END SOLUTION
}

// Cubes of side `size` in space, a on even cubes.
vec3 checker_3d(vec3 point, vec3 a, vec3 b, float size) {
    // BEGIN SOLUTION
    const vec3 cell = floor(point / size);
    const int sum = int(cell.x) + int(cell.y) + int(cell.z);
    return (sum & 1) == 0 ? a : b;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return vec3(0);
    // END SOLUTION
}
#endif  // HAS_CHECKER_TEXTURES

#ifdef HAS_NOISE_TEXTURES
float fade(float t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// Perlin's gradient noise: gradients at the 8 lattice corners, blended with the fade curve.
float gradient_noise(vec3 point) {
    // BEGIN SOLUTION
    const vec3 cell = floor(point);
    const vec3 f = point - cell;
    const ivec3 c = ivec3(cell);
    const vec3 w = vec3(fade(f.x), fade(f.y), fade(f.z));
    float corner[8];  // index dx + 2 dy + 4 dz
    for (int k = 0; k < 8; ++k) {
        const ivec3 d = ivec3(k & 1, (k >> 1) & 1, k >> 2);
        corner[k] = dot(noise_gradient(c.x + d.x, c.y + d.y, c.z + d.z), f - vec3(d));
    }
    // GLSL's mix(a, b, t) is a (1 - t) + b t; stage 07 blends a + t (b - a): keep that.
    const float x00 = corner[0] + w.x * (corner[1] - corner[0]);
    const float x10 = corner[2] + w.x * (corner[3] - corner[2]);
    const float x01 = corner[4] + w.x * (corner[5] - corner[4]);
    const float x11 = corner[6] + w.x * (corner[7] - corner[6]);
    const float y0 = x00 + w.y * (x10 - x00), y1 = x01 + w.y * (x11 - x01);
    return y0 + w.z * (y1 - y0);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return 0.0;
    // END SOLUTION
}

// Veins: a sine of x disturbed by turbulence (a sum of noise octaves).
vec3 marble(vec3 point, vec3 a, vec3 b, float scale) {
    // BEGIN SOLUTION
    const vec3 p = point / scale;
    float turbulence = 0.0, weight = 1.0;
    for (int octave = 0; octave < 5; ++octave) {
        turbulence += abs(gradient_noise(p / weight)) * weight;
        weight /= 2.0;
    }
    const float s = 0.5 + 0.5 * sin((p.x + 4.0 * turbulence) * kPi);
    return a * (1.0 - s) + b * s;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return vec3(0);
    // END SOLUTION
}
#endif  // HAS_NOISE_TEXTURES

#ifdef HAS_NORMAL_MAPS
// The normal map's texel turned into a shading normal in the frame (T', B, N).
vec3 normal_from_map(vec3 normal, vec3 tangent, vec3 texel, vec3 to_viewer) {
    // BEGIN SOLUTION
    const vec3 m = 2.0 * texel - 1.0;
    const vec3 t = tangent - dot(tangent, normal) * normal;  // Gram-Schmidt
    const float t_length = length(t);
    if (t_length == 0.0 || m == vec3(0)) return normal;
    const vec3 t_unit = t / t_length;
    const vec3 b = cross(normal, t_unit);
    vec3 n = normalize(m.x * t_unit + m.y * b + m.z * normal);
    const float facing = dot(n, to_viewer);
    if (facing <= 0.0) {
        const vec3 edge_on = n - facing * to_viewer;
        const float edge_length = length(edge_on);
        if (edge_length == 0.0) return normal;
        n = edge_on / edge_length;
    }
    return n;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#textures
    // return normal;
    // END SOLUTION
}
#endif  // HAS_NORMAL_MAPS
