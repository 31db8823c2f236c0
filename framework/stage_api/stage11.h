// Stage 11 (path tracing): the functions students write in stages/11-path-tracing/bsdf.cpp (the
// BSDF: a Lambertian lobe, a GGX microfacet lobe, mirrors and glass) and path.cpp (multiple
// importance sampling and the path tracer). Handout: stages/11-path-tracing/README.md.
// Conventions: docs/conventions.md#path-tracing.
//
// As in stage 10, every function gets its random numbers (u, uniform in [0, 1)) as arguments or
// from the camera sample's SampleStream, so the tests can check distributions. The framework
// calls path_radiance for every camera sample of a scene with "integrator": "path".
#pragma once

#include "core/sample_stream.h"
#include "geometry/onb.h"
#include "scene/prepared_scene.h"
#include "scene/surface_point.h"

namespace rt {

// ---------------------------------------------------------------- bsdf.cpp
// Every direction here is a unit vector in the local shading frame: z along the surface's
// OUTWARD normal, so cos theta = v.z. wo points away from the surface towards where the light
// goes (the viewer, the previous path vertex), wi towards where it comes from. wo.z < 0 means
// the surface is seen from inside (glass) or from behind (an opaque plane's back): opaque lobes
// then work in the lower hemisphere as they would in the upper one.

// The GGX (Trowbridge-Reitz) distribution of microfacet normals, alpha = roughness^2 > 0:
// D(h) = alpha^2 / (pi (cos^2 theta_h (alpha^2 - 1) + 1)^2) for h.z > 0, else 0. Normalised so
// that the integral of D(h) cos theta_h over the hemisphere is 1.
Real ggx_d(const Vec3& h, Real alpha);

// Smith's masking function for GGX: the fraction of microfacets of normal h that a direction v
// sees, G1(v) = 2 / (1 + sqrt(1 + alpha^2 tan^2 theta_v)), 0 when v and h lie on opposite sides
// of the microsurface (dot(v, h) v.z <= 0). The shadowing-masking term is its separable form
// G(wo, wi) = G1(wo, h) G1(wi, h).
Real ggx_g1(const Vec3& v, const Vec3& h, Real alpha);

// A microfacet normal sampled from the distribution of normals: density D(h) cos theta_h per
// unit solid angle of h (tan^2 theta_h = alpha^2 u.x / (1 - u.x), phi = 2 pi u.y). Always h.z > 0.
Vec3 sample_ggx_normal(Real alpha, Vec2 u);
// That density: D(h) h.z, 0 below the horizon.
Real ggx_normal_pdf(const Vec3& h, Real alpha);

// Schlick's Fresnel approximation: f0 + (1 - f0) (1 - cos)^5, cos in [0, 1].
Color schlick_fresnel(const Color& f0, Real cos_theta);

// The BSDF of a material (docs/conventions.md#path-tracing):
// - transmissive != 0: a smooth dielectric of index `ior` (glass): reflects with probability F
//   (stage 05's schlick_reflectance, entering when wo.z > 0) and refracts otherwise, tinted by
//   `transmissive`. A delta lobe: eval_bsdf and bsdf_pdf are 0.
// - otherwise a mixture of a Lambertian lobe, f = diffuse / pi, and a specular lobe of colour
//   F0 = min(specular + reflective, 1): with roughness > 0 the GGX microfacet BRDF
//   f = D(h) G(wo, wi) F(wo.h) / (4 |wo.z| |wi.z|), h = normalize(wo + wi), alpha = roughness^2;
//   with roughness 0 a perfect mirror (a delta lobe) that reflects F(|wo.z|).
//   sample_bsdf picks the specular lobe with probability P_s = mean(F0) / (mean(diffuse) +
//   mean(F0)) (u_lobe < P_s), the diffuse lobe otherwise.
struct BsdfSample {
    Vec3 wi{0};          // local, unit; a sample that fails (below the surface) has weight 0
    Color weight{0};     // f(wo, wi) |wi.z| / pdf; a delta lobe: what it reflects over its chance
    Real pdf = 0;        // bsdf_pdf(material, wo, wi) per unit solid angle; 0 for a delta lobe
    bool delta = false;  // a mirror or glass direction: no light sampling, no MIS weight
};
BsdfSample sample_bsdf(const Material& material, const Vec3& wo, Real u_lobe, Vec2 u);
// f(wo, wi) of the non-delta lobes (1 / steradian, no cosine): diffuse / pi plus the GGX lobe.
// 0 when wo and wi lie on opposite sides of the surface.
Color eval_bsdf(const Material& material, const Vec3& wo, const Vec3& wi);
// The density with which sample_bsdf returns a non-delta wi, per unit solid angle: the mixture
// (1 - P_s) cos / pi + P_s D(h) h.z / (4 |wo.h|) (for a mirror's delta lobe only the first).
Real bsdf_pdf(const Material& material, const Vec3& wo, const Vec3& wi);

// ---------------------------------------------------------------- path.cpp

// Multiple importance sampling weights of a sample drawn by technique f, whose density is
// pdf_f, against technique g (pdf_g), one sample each: balance pdf_f / (pdf_f + pdf_g), power
// (beta = 2) pdf_f^2 / (pdf_f^2 + pdf_g^2). 0 when both are 0. w(f, g) + w(g, f) = 1.
Real balance_heuristic(Real pdf_f, Real pdf_g);
Real power_heuristic(Real pdf_f, Real pdf_g);

// Next-event estimation at `at`: one area light chosen uniformly (light floor(u_light * N) of
// the scene's N), one point on it by stage 10's sample_rectangle / sample_sphere, a shadow ray
// (nearest_hit, render/nearest_hit.h; area lights never block it) and the one-sample estimate
// f(wo, wi) L |wi.z| / p_light times the power heuristic of p_light against bsdf_pdf, where
// p_light = that point's solid-angle pdf / N. `frame`: the local shading frame (z outward);
// wo local. 0 without area lights, for the back of a rectangle, or a delta material.
Color sample_light_mis(const PreparedScene& scene, const SurfacePoint& at, const Onb& frame,
                       const Material& material, const Vec3& wo, Real u_light, Vec2 u);

// The radiance arriving along `ray` (a camera ray): a path of any length. At each surface its
// `emissive`, then (below scene.max_depth bounces) sample_light_mis, then a sample_bsdf bounce;
// an area light a bounce meets (nearest_area_light, scene/area_light_hit.h) adds its radiance
// weighted by the power heuristic of the bounce's pdf against the light's (full weight after a
// delta bounce or for the camera ray), and ends the path. Russian roulette once the bounce
// sampled at the path's 4th surface (and every later one) has multiplied the throughput: survive
// with q = min(max component of the throughput, 0.95), divide the throughput by q.
// Random numbers per bounce, in this order: u_light, u (sample_light_mis), u_lobe, u
// (sample_bsdf), then the roulette's. A ray that escapes brings back background(scene, its
// direction) (render/background.h): the scene's environment (stage 08) when it has one, else its
// background colour.
Color path_radiance(const PreparedScene& scene, const Ray& ray, SampleStream& stream);

}  // namespace rt
