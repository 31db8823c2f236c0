// Stage 07: textures. Handout: stages/07-textures/README.md
// Conventions (texture coordinates, image rows, sRGB, normal maps): docs/conventions.md#textures
//
// You edit only this file. Tests: ctest --test-dir build -L stage07 --output-on-failure
// The contracts are in framework/stage_api/stage07.h. The framework's texturing step
// (framework/render/texturing.cpp) calls these at each hit on a textured material.
#include <algorithm>
#include <cmath>

#include "core/not_implemented.h"
#include "stage_api/stage07.h"

namespace rt {

// --- Texture coordinates ---------------------------------------------------------------------

// Longitude and latitude of the unit outward normal (docs/conventions.md#textures).
Vec2 sphere_texcoord(const Vec3& outward_normal) {
    // BEGIN SOLUTION
    Real phi = std::atan2(-outward_normal.z, outward_normal.x);
    if (phi < 0) phi += 2 * kPi;
    const Real theta = std::acos(std::clamp(outward_normal.y, Real(-1), Real(1)));
    return Vec2(phi / (2 * kPi), theta / kPi);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#spheres");
    // (void)outward_normal;
    // return Vec2(0);
    // END SOLUTION
}

// The point's offset from plane.point along the plane's frame (plane_frame), in world units.
Vec2 plane_texcoord(const Plane& plane, const Vec3& point) {
    // BEGIN SOLUTION
    const PlaneFrame f = plane_frame(plane.normal);
    const Vec3 d = point - plane.point;
    return Vec2(glm::dot(d, f.t), glm::dot(d, f.b));
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#planes");
    // (void)plane; (void)point;
    // return Vec2(0);
    // END SOLUTION
}

// The face's frame, centred on the face, each edge spanning 1.
Vec2 box_texcoord(const Box& box, const Vec3& point, const Vec3& outward_normal) {
    // BEGIN SOLUTION
    const PlaneFrame f = plane_frame(outward_normal);
    const Vec3 center = (box.min + box.max) / Real(2);
    const Vec3 size = box.max - box.min;
    const Vec3 d = point - center;
    // t and b are axis directions (+-1 on one axis), so |t|.size is the edge along t.
    const Real width = glm::dot(glm::abs(f.t), size), height = glm::dot(glm::abs(f.b), size);
    return Vec2(Real(0.5) + glm::dot(d, f.t) / width, Real(0.5) + glm::dot(d, f.b) / height);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#boxes");
    // (void)box; (void)point; (void)outward_normal;
    // return Vec2(0);
    // END SOLUTION
}

// The vertex uvs interpolated with the barycentrics (beta, gamma).
Vec2 triangle_texcoord(const Vec2& uv_a, const Vec2& uv_b, const Vec2& uv_c, Vec2 barycentric) {
    // BEGIN SOLUTION
    const Real beta = barycentric.x, gamma = barycentric.y, alpha = 1 - beta - gamma;
    return alpha * uv_a + beta * uv_b + gamma * uv_c;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#triangles");
    // (void)uv_a; (void)uv_b; (void)uv_c; (void)barycentric;
    // return Vec2(0);
    // END SOLUTION
}

// --- Image lookup ------------------------------------------------------------------------------

// One stored sRGB value in [0, 1] to linear light.
Real srgb_to_linear_value(Real encoded) {
    // BEGIN SOLUTION
    if (encoded <= Real(0.04045)) return encoded / Real(12.92);
    return std::pow((encoded + Real(0.055)) / Real(1.055), Real(2.4));
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#colour-spaces");
    // (void)encoded;
    // return 0;
    // END SOLUTION
}

// Texel (i, j) as linear colour.
Color decoded_texel(const TextureView& image, int i, int j) {
    // BEGIN SOLUTION
    const Color& s = image.stored(i, j);
    if (!image.srgb) return s;
    return Color(float(srgb_to_linear_value(Real(s.r))), float(srgb_to_linear_value(Real(s.g))),
                 float(srgb_to_linear_value(Real(s.b))));
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#colour-spaces");
    // (void)image; (void)i; (void)j;
    // return Color(0);
    // END SOLUTION
}

// Any texel index into [0, n).
int wrap_texel(int i, int n, TextureWrap wrap) {
    // BEGIN SOLUTION
    switch (wrap) {
        case TextureWrap::Repeat:
            return ((i % n) + n) % n;
        case TextureWrap::Clamp:
            return std::clamp(i, 0, n - 1);
        case TextureWrap::Mirror: {
            const int k = ((i % (2 * n)) + 2 * n) % (2 * n);  // in [0, 2n)
            return k < n ? k : 2 * n - 1 - k;
        }
    }
    return 0;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#wrap-modes");
    // (void)i; (void)n; (void)wrap;
    // return 0;
    // END SOLUTION
}

// The texel whose square contains (u * width, v * height).
Color sample_nearest(const TextureView& image, Vec2 uv, TextureWrap wrap) {
    // BEGIN SOLUTION
    // u * width can be far beyond int's range after a big uv scale: reduce by whole periods
    // (2n covers repeat and mirror) or clamp first, so the conversion to int cannot overflow.
    auto texel_index = [wrap](double c, int n) {
        if (std::isnan(c)) c = 0;  // a degenerate uv must not reach int()
        c = wrap == TextureWrap::Clamp ? std::clamp(c, -1.0, double(n)) : std::fmod(c, 2.0 * n);
        return wrap_texel(int(c), n, wrap);
    };
    const int i = texel_index(std::floor(double(uv.x) * image.width), image.width);
    const int j = texel_index(std::floor(double(uv.y) * image.height), image.height);
    return decoded_texel(image, i, j);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#nearest-neighbour");
    // (void)image; (void)uv; (void)wrap;
    // return Color(0);
    // END SOLUTION
}

// The four texels around (u, v), weighted by distance.
Color sample_bilinear(const TextureView& image, Vec2 uv, TextureWrap wrap) {
    // BEGIN SOLUTION
    // Texel centres sit at half-integers: shift by 0.5 so that they sit at integers.
    const double x = double(uv.x) * image.width - 0.5, y = double(uv.y) * image.height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const float fx = float(x - x0), fy = float(y - y0);
    // As in sample_nearest: no int overflow for far-away coordinates.
    auto texel_index = [wrap](double c, int n) {
        if (std::isnan(c)) c = 0;  // a degenerate uv must not reach int()
        c = wrap == TextureWrap::Clamp ? std::clamp(c, -1.0, double(n)) : std::fmod(c, 2.0 * n);
        return wrap_texel(int(c), n, wrap);
    };
    const int i = texel_index(x0, image.width), i1 = texel_index(x0 + 1, image.width);
    const int j = texel_index(y0, image.height), j1 = texel_index(y0 + 1, image.height);
    const Color top = (1 - fx) * decoded_texel(image, i, j) + fx * decoded_texel(image, i1, j);
    const Color bottom = (1 - fx) * decoded_texel(image, i, j1) + fx * decoded_texel(image, i1, j1);
    return (1 - fy) * top + fy * bottom;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#bilinear-filtering");
    // (void)image; (void)uv; (void)wrap;
    // return Color(0);
    // END SOLUTION
}

// --- Procedural textures -----------------------------------------------------------------------

// Unit squares in (u, v), a on even squares.
Color checker_2d(Vec2 uv, const Color& a, const Color& b) {
    // BEGIN SOLUTION
    const long long sum = (long long)std::floor(uv.x) + (long long)std::floor(uv.y);
    return sum % 2 == 0 ? a : b;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#checkerboards");
    // (void)uv; (void)a; (void)b;
    // return Color(0);
    // END SOLUTION
}

// Cubes of side `size` in space, a on even cubes.
Color checker_3d(const Vec3& point, const Color& a, const Color& b, Real size) {
    // BEGIN SOLUTION
    const Vec3 cell = glm::floor(point / size);
    const long long sum = (long long)cell.x + (long long)cell.y + (long long)cell.z;
    return sum % 2 == 0 ? a : b;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#checkerboards");
    // (void)point; (void)a; (void)b; (void)size;
    // return Color(0);
    // END SOLUTION
}

// Perlin's gradient noise: gradients at the 8 lattice corners, blended with the fade curve.
Real gradient_noise(const Vec3& point) {
    // BEGIN SOLUTION
    const Vec3 cell = glm::floor(point);
    const Vec3 f = point - cell;
    const int x = int(cell.x), y = int(cell.y), z = int(cell.z);
    auto fade = [](Real t) { return t * t * t * (t * (t * 6 - 15) + 10); };
    const Vec3 w(fade(f.x), fade(f.y), fade(f.z));
    Real corner[2][2][2];
    for (int dx = 0; dx < 2; ++dx)
        for (int dy = 0; dy < 2; ++dy)
            for (int dz = 0; dz < 2; ++dz)
                corner[dx][dy][dz] = glm::dot(noise_gradient(x + dx, y + dy, z + dz),
                                              f - Vec3(Real(dx), Real(dy), Real(dz)));
    auto lerp = [](Real a, Real b, Real t) { return a + t * (b - a); };
    const Real x00 = lerp(corner[0][0][0], corner[1][0][0], w.x);
    const Real x10 = lerp(corner[0][1][0], corner[1][1][0], w.x);
    const Real x01 = lerp(corner[0][0][1], corner[1][0][1], w.x);
    const Real x11 = lerp(corner[0][1][1], corner[1][1][1], w.x);
    return lerp(lerp(x00, x10, w.y), lerp(x01, x11, w.y), w.z);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#gradient-noise");
    // (void)point;
    // return 0;
    // END SOLUTION
}

// Veins: a sine of x disturbed by turbulence (a sum of noise octaves).
Color marble(const Vec3& point, const Color& a, const Color& b, Real scale) {
    // BEGIN SOLUTION
    const Vec3 p = point / scale;
    Real turbulence = 0, weight = 1;
    for (int octave = 0; octave < 5; ++octave) {
        turbulence += std::abs(gradient_noise(p / weight)) * weight;
        weight /= 2;
    }
    const Real s = Real(0.5) + Real(0.5) * std::sin((p.x + 4 * turbulence) * kPi);
    return a * float(1 - s) + b * float(s);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#marble");
    // (void)point; (void)a; (void)b; (void)scale;
    // return Color(0);
    // END SOLUTION
}

// --- Normal mapping -----------------------------------------------------------------------------

// The normal map's texel turned into a shading normal in the frame (T', B, N).
Vec3 normal_from_map(const Vec3& normal, const Vec3& tangent, const Color& texel,
                     const Vec3& to_viewer) {
    // BEGIN SOLUTION
    const Vec3 m = Real(2) * Vec3(texel) - Real(1);
    const Vec3 t = tangent - glm::dot(tangent, normal) * normal;  // Gram-Schmidt
    const Real t_length = glm::length(t);
    if (t_length == 0 || m == Vec3(0)) return normal;
    const Vec3 t_unit = t / t_length;
    const Vec3 b = glm::cross(normal, t_unit);
    Vec3 n = glm::normalize(m.x * t_unit + m.y * b + m.z * normal);
    const Real facing = glm::dot(n, to_viewer);
    if (facing <= 0) {
        const Vec3 edge_on = n - facing * to_viewer;
        const Real length = glm::length(edge_on);
        if (length == 0) return normal;
        n = edge_on / length;
    }
    return n;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/07-textures/README.md#normal-mapping");
    // (void)normal; (void)tangent; (void)texel; (void)to_viewer;
    // return normal;
    // END SOLUTION
}

}  // namespace rt
