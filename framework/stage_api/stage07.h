// Stage 07 (textures): the functions students write in stages/07-textures/textures.cpp.
// Handout: stages/07-textures/README.md. Conventions: docs/conventions.md#textures (texture
// coordinates of each primitive, image rows, colour spaces, normal maps).
//
// Texture coordinates (u, v): u grows to the right of the image, v downwards; (0, 0) is the
// top-left corner of the image and (1, 1) the bottom-right one, as image rows count from the top.
#pragma once

#include "scene/scene.h"

namespace rt {

// --- Texture coordinates of each primitive ----------------------------------------------------

// A sphere's (u, v) at the unit outward normal n = (x, y, z) (y is up):
//   u = phi / (2 pi), phi = atan2(-z, x) moved into [0, 2 pi)  (longitude: u = 0 at +x, 0.25 at
//                                                               -z, 0.5 at -x, 0.75 at +z)
//   v = theta / pi, theta = acos(y)                           (v = 0 at the north pole +y)
// y is clamped to [-1, 1] before acos. Seen from outside, u grows from left to right.
Vec2 sphere_texcoord(const Vec3& outward_normal);

// A plane's (u, v) at `point` on it: its offset from plane.point measured along the plane's
// tangent frame (plane_frame below), in world units: u = (p - p0).t, v = (p - p0).b.
Vec2 plane_texcoord(const Plane& plane, const Vec3& point);

// A box face's (u, v) at `point` on the face whose unit outward normal is `outward_normal`
// (an axis direction): the face's own frame (plane_frame(outward_normal)) with the face's centre
// at (0.5, 0.5) and each edge spanning 1, so every face shows the whole image, upright when the
// face is seen from outside.
Vec2 box_texcoord(const Box& box, const Vec3& point, const Vec3& outward_normal);

// A triangle's (u, v): its vertex texture coordinates interpolated with the barycentrics
// (beta, gamma) of stage 02: (1 - beta - gamma) uv_a + beta uv_b + gamma uv_c.
Vec2 triangle_texcoord(const Vec2& uv_a, const Vec2& uv_b, const Vec2& uv_c, Vec2 barycentric);

// --- Image lookup ---------------------------------------------------------------------------

// The sRGB decoding (IEC 61966-2-1) of one stored value e in [0, 1]:
//   e <= 0.04045: e / 12.92, else ((e + 0.055) / 1.055)^2.4
Real srgb_to_linear_value(Real encoded);

// Texel (i, j) of `image` as linear colour: image.stored(i, j), decoded channel by channel with
// srgb_to_linear_value when image.srgb (colour textures in 8- and 16-bit files), as stored
// otherwise (normal maps, float files).
Color decoded_texel(const TextureView& image, int i, int j);

// Maps a texel index i (any integer, possibly negative or >= n) into [0, n), n >= 1:
//   Repeat: i mod n (always non-negative);  Clamp: the nearest of 0 and n - 1;
//   Mirror: 0, 1, ..., n-1, n-1, ..., 1, 0, 0, 1, ... (period 2n, each edge texel twice).
int wrap_texel(int i, int n, TextureWrap wrap);

// Nearest-neighbour lookup: the texel whose square contains (u * width, v * height), i.e.
// i = floor(u * width), j = floor(v * height), then wrapped. Texel (i, j) covers
// [i / width, (i + 1) / width) x [j / height, (j + 1) / height); its centre is at
// ((i + 0.5) / width, (j + 0.5) / height).
Color sample_nearest(const TextureView& image, Vec2 uv, TextureWrap wrap);

// Bilinear lookup: the four texels whose centres surround (u, v), weighted by distance, each
// index wrapped and each texel decoded (decoded_texel) before it is weighted. At a texel centre
// the result is that texel exactly.
Color sample_bilinear(const TextureView& image, Vec2 uv, TextureWrap wrap);

// --- Procedural textures ----------------------------------------------------------------------

// Squares of side 1 in (u, v): colour a where floor(u) + floor(v) is even, b where odd.
Color checker_2d(Vec2 uv, const Color& a, const Color& b);

// Cubes of side `size` in space: a where floor(x/size) + floor(y/size) + floor(z/size) is even,
// b where odd.
Color checker_3d(const Vec3& point, const Color& a, const Color& b, Real size);

// Perlin's gradient noise at `point`, in [-1, 1]: at each of the 8 corners of the unit lattice
// cell around the point, the dot product of the corner's gradient (noise_gradient below) with
// the offset from the corner to the point; the 8 values blended with the weights
// fade(t) = t^3 (t (6 t - 15) + 10) of the point's position in the cell, axis by axis. 0 at
// every lattice point.
Real gradient_noise(const Vec3& point);

// Marble: s = 0.5 + 0.5 sin((x + 4 turbulence(p)) * pi) with p = point / scale and turbulence
// the sum over octaves k = 0..4 of |gradient_noise(2^k p)| / 2^k; the colour a (1 - s) + b s.
Color marble(const Vec3& point, const Color& a, const Color& b, Real scale);

// --- Normal mapping -------------------------------------------------------------------------

// The shading normal from a normal map's texel (as stored, each channel in [0, 1]):
//   1. m = 2 texel - 1 (the tangent-space normal; OpenGL style: +y towards the image top);
//   2. T' = normalize(tangent - (tangent.N) N) (Gram-Schmidt), B = cross(N, T');
//   3. n = normalize(m.x T' + m.y B + m.z N).
// If n faces away from the viewer (n.to_viewer <= 0), its component along to_viewer is removed
// (n - (n.to_viewer) to_viewer, normalised) so that the surface is seen edge-on rather than from
// behind; if nothing is left, or m is zero, or the tangent is parallel to N, `normal` itself.
// normal: unit, facing the viewer; tangent: any length, roughly along +u; to_viewer: unit.
Vec3 normal_from_map(const Vec3& normal, const Vec3& tangent, const Color& texel,
                     const Vec3& to_viewer);

// --- Provided by the framework (framework/render/texturing.cpp), for the functions above ---

// The tangent frame of a plane with unit normal n: t (the u axis) and b = cross(t, n) (the v
// axis), both unit and perpendicular to n. t = normalize(cross(n, r)) with r = (0, -1, 0), or
// r = (0, 0, 1) when |n.y| > 0.9. So a floor (n = +y) has u along +x and v along +z, and every
// wall (a box's four side faces too) has u to the right and v downwards as it is seen from the
// front: its picture upright.
struct PlaneFrame {
    Vec3 t{1, 0, 0};
    Vec3 b{0, 0, 1};
};
PlaneFrame plane_frame(const Vec3& normal);

// The unit gradient of lattice corner (x, y, z) for gradient_noise: one of the 12 edge
// directions of a cube, (+-1, +-1, 0) and permutations, normalised, chosen by a fixed hash of
// the corner (the same on every machine).
Vec3 noise_gradient(int x, int y, int z);

}  // namespace rt
