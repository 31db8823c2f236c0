// Stage 09, environment maps: stage 08 (stages/08-environment/environment.cpp) in GLSL.
// Handout: stages/09-gpu/README.md#environment-maps. Conventions:
// docs/conventions.md#environment-maps. The environment is environment_at(0) (scene_buffers.glsl);
// the image lookup is your sample_bilinear (textures.glsl). Compiled only for scenes with an
// environment (HAS_ENVIRONMENT); the framework's background() calls environment_radiance.

// Longitude and latitude of the direction, seen from inside (OpenImageIO's y-up lat-long).
vec2 latlong_uv(vec3 direction) {
    // BEGIN SOLUTION
    const vec3 d = normalize(direction);
    float u = atan(-d.x, d.z) / (2.0 * kPi) + 0.5;
    if (u >= 1.0) u = 0.0;  // atan(+0, negative) is +pi: u = 1 is the seam, u = 0
    return vec2(u, acos(clamp(d.y, -1.0, 1.0)) / kPi);
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#environment-maps
    // return vec2(0);
    // END SOLUTION
}

struct CubeFaceUv {
    int face;  // 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z (OpenGL's order)
    vec2 uv;
};

// The OpenGL cube-map table: the major axis picks the face, the other two give (u, v).
CubeFaceUv cube_face_uv(vec3 direction) {
    // BEGIN SOLUTION
    const vec3 a = abs(direction);
    CubeFaceUv r;
    float sc, tc, ma;
    if (a.x >= a.y && a.x >= a.z) {  // ties: x before y before z
        const bool positive = direction.x > 0.0;
        r.face = positive ? 0 : 1;
        sc = positive ? -direction.z : direction.z;
        tc = -direction.y;
        ma = a.x;
    } else if (a.y >= a.z) {
        const bool positive = direction.y > 0.0;
        r.face = positive ? 2 : 3;
        sc = direction.x;
        tc = positive ? direction.z : -direction.z;
        ma = a.y;
    } else {
        const bool positive = direction.z > 0.0;
        r.face = positive ? 4 : 5;
        sc = positive ? direction.x : -direction.x;
        tc = -direction.y;
        ma = a.z;
    }
    r.uv = clamp((vec2(sc, tc) / ma + 1.0) / 2.0, 0.0, 1.0);
    return r;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#environment-maps
    // return CubeFaceUv(0, vec2(0.5));
    // END SOLUTION
}

// Rotate, map to an image position, filter, scale. background_color when there is none.
vec3 environment_radiance(vec3 direction) {
    // BEGIN SOLUTION
    const Environment env = environment_at(0);
    if (env.kind_image.x == kEnvironmentNone) return background_color;
    // The environment turned by +rotate_y: look up the direction turned back by -rotate_y.
    const float angle = env.intensity_rotate_y.y * kPi / 180.0;
    const float c = cos(angle), s = sin(angle);
    const vec3 d = vec3(c * direction.x - s * direction.z, direction.y,
                        s * direction.x + c * direction.z);
    vec3 radiance;
    if (env.kind_image.x == kEnvironmentLatLong) {
        const TextureView image = texture_view(env.kind_image.y, false);
        vec2 uv = latlong_uv(d);
        // Rows never wrap: v stays between the centres of the top and bottom rows.
        const float half_row = 0.5 / float(image.height);
        uv.y = clamp(uv.y, half_row, 1.0 - half_row);
        radiance = sample_bilinear(image, uv, kWrapRepeat);
    } else {
        const CubeFaceUv at = cube_face_uv(d);
        const int face = at.face < 4 ? env.faces_px_nx_py_ny[at.face] : env.faces_pz_nz[at.face - 4];
        radiance = sample_bilinear(texture_view(face, false), at.uv, kWrapClamp);
    }
    return radiance * env.intensity_rotate_y.x;
    // STUB
    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#environment-maps
    // return vec3(0);
    // END SOLUTION
}
