// The texturing step of the shading loop (stage 07): at a hit on a textured material, the
// surface's texture coordinates (stage 07's mappings), the textured material (k_d, k_a, k_s, k_e
// multiplied by their maps) and the normal-mapped shading normal. The driver calls it only when
// scene.features.textures or normal_maps, so scenes without textures never run stage 07 code.
#pragma once

#include "render/oiio_textures.h"
#include "scene/prepared_scene.h"
#include "scene/surface_point.h"

namespace rt {

// The (u, v) of the surface point on its primitive (stage 07's sphere/plane/box/triangle
// mappings), before any slot's scale and offset.
Vec2 surface_texcoord(const PreparedScene& scene, const Hit& hit, const SurfacePoint& at);

// A unit tangent along +u at the surface point (for normal maps), perpendicular to at.normal
// when possible: spheres d/d(longitude), planes and boxes the frame's t, triangles dP/du from
// the vertex uvs (any perpendicular when the uvs are degenerate).
Vec3 surface_tangent(const PreparedScene& scene, const Hit& hit, const SurfacePoint& at);

// The colour of texture `slot` at texture coordinates `uv` (the slot's scale and offset applied
// here) and world point `point` (3D textures), image textures filtered as scene.texture_lookup
// says. 1 when the slot is unused. `footprint` (in uv, before the slot's scale) only matters to
// the OpenImageIO lookups, which without scene.oiio_textures fall back to bilinear.
Color evaluate_slot(const PreparedScene& scene, const TextureSlot& slot, Vec2 uv, const Vec3& point,
                    const TexcoordDerivatives& footprint = {});

// A camera ray's neighbours through pixels (x + 1, y) and (x, y + 1): its ray differentials.
struct RayDifferential {
    Ray x;
    Ray y;
};

// The texture-coordinate derivatives at `at` (pbrt-v4 section 10.1): each neighbour ray meets
// the tangent plane of the hit at p', and du = uv(p') - uv(p) with the surface's own mapping.
// Zero where a neighbour misses the plane (grazing, or the plane behind it).
TexcoordDerivatives texcoord_derivatives(const PreparedScene& scene, const Hit& hit,
                                         const SurfacePoint& at, const RayDifferential& rays);

// Applies the material's maps at `at`: fills at.texcoord, multiplies the material's colours by
// their maps and replaces `lighting_normal` by the normal-mapped one. `rays` (camera rays only,
// and only for the OpenImageIO lookups) gives the filter footprint; without them, as for
// reflected and refracted rays, the footprint is zero: bilinear in the finest mip level.
void apply_textures(const PreparedScene& scene, const Hit& hit, SurfacePoint& at,
                    const Vec3& to_viewer, Material& material, Vec3& lighting_normal,
                    const RayDifferential* rays = nullptr);

}  // namespace rt
