// What stages 07-08's GLSL (stages/09-gpu/textures.glsl, environment.glsl) is given, as the C++
// stages are given framework/scene/texture.h and framework/render/texturing.cpp: the image view,
// the plane frame, the noise gradients, and the numbers of the scene's enums.

// scene/texture.h's TextureWrap, TextureFilter, TextureKind; scene/environment.h's kinds.
// kWrap*, kFilter*, kTexture* and kEnvironment* are the prelude's (framework/gpu/shader_constants.h).

// One image of the texture table (scene/texture.h's TextureView): texels_at(first ...), row 0 at
// the top; srgb: the stored values are sRGB-encoded (decode before filtering).
struct TextureView {
    int first;
    int width;
    int height;
    bool srgb;
};

TextureView texture_view(int image, bool srgb) {
    const ivec4 t = texture_images_at(image).width_height_first;
    return TextureView(t.z, t.x, t.y, srgb);
}

// The stored (not decoded) value of texel (i, j): column i from the left, row j from the top.
vec3 stored_texel(TextureView image, int i, int j) {
    return texels_at(image.first + j * image.width + i).rgb;
}

#ifdef HAS_MAPS
// render/texturing.cpp's plane_frame: t the u axis, b = cross(t, n) the v axis.
struct PlaneFrame {
    vec3 t;
    vec3 b;
};
PlaneFrame plane_frame(vec3 normal) {
    const vec3 r = abs(normal.y) > 0.9 ? vec3(0, 0, 1) : vec3(0, -1, 0);
    const vec3 t = normalize(cross(normal, r));
    return PlaneFrame(t, cross(t, normal));
}
#endif

#ifdef HAS_NOISE_TEXTURES
// render/texturing.cpp's noise_gradient: the same integer hash, so the same noise as the CPU.
vec3 noise_gradient(int x, int y, int z) {
    uint h = uint(x) * 73856093u ^ uint(y) * 19349663u ^ uint(z) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    const float k = 0.70710678118654752;  // 1 / sqrt(2)
    const vec3 directions[12] = vec3[12](vec3(1, 1, 0), vec3(-1, 1, 0), vec3(1, -1, 0),
                                         vec3(-1, -1, 0), vec3(1, 0, 1), vec3(-1, 0, 1),
                                         vec3(1, 0, -1), vec3(-1, 0, -1), vec3(0, 1, 1),
                                         vec3(0, -1, 1), vec3(0, 1, -1), vec3(0, -1, -1));
    return directions[h % 12u] * k;
}
#endif
