// Stage 03 (Blinn-Phong): the functions students write in stages/03-blinn-phong/blinn_phong.cpp.
// Handout: stages/03-blinn-phong/README.md. Conventions: docs/conventions.md (Colour, Lights).
//
// All colours are linear RGB; nothing here clamps to [0, 1] (the image writer does).
#pragma once

#include <cstddef>
#include <span>

#include "scene/scene.h"

namespace rt {

// What one light delivers at a point, before any shadowing.
struct LightSample {
    Vec3 direction{0};   // unit, from the point towards the light
    Real distance = 0;   // to the light; kInfinity for a directional light
    Color intensity{0};  // I_L * A_dist: the light arriving at the point
};

// How much of each light gets through to the point: (1, 1, 1) unobstructed, (0, 0, 0) in
// shadow, a colour behind glass; read it as visibility[light_index]. The framework fills it
// before it calls direct_light (stage 04 computes the values); empty, every light gets through.
// Plain data (a pointer and a count), so a shader has the same: an array of vec3, one per light.
struct LightVisibility {
    std::span<const Color> per_light;  // one per scene light, or empty

    Color operator[](std::size_t light_index) const {
        return light_index < per_light.size() ? per_light[light_index] : Color(1);
    }
};

// The light `light` sends to `point`.
//   point light:       direction = normalize(position - point), distance = |position - point|,
//                      intensity = I_L / (c + l r + q r^2) with (c, l, q) = light.attenuation
//   directional light: direction = -light.direction, distance = kInfinity, intensity = I_L
LightSample illuminate(const Light& light, const Vec3& point);

// The Blinn-Phong reflection of one light: incident * (k_d max(0, N.L) + k_s max(0, N.H)^n_s),
// with N = normal, L = to_light, V = to_viewer (all unit) and H = normalize(L + V).
// No light from below the surface: if N.L <= 0 the result is 0, specular included.
Color blinn_phong(const Material& material, const Vec3& normal, const Vec3& to_viewer,
                  const Vec3& to_light, const Color& incident);

// I_direct = k_e + k_a I_a + sum over the scene's lights of visibility * blinn_phong(...), at a
// surface point with unit `normal` facing the viewer and unit `to_viewer`.
Color direct_light(const Scene& scene, const Material& material, const Vec3& point,
                   const Vec3& normal, const Vec3& to_viewer, LightVisibility visibility = {});

}  // namespace rt
