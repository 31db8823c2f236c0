// Stage 11: path tracing, part 1: the BSDF. A Lambertian lobe, a GGX (Trowbridge-Reitz)
// microfacet lobe with its sampling routine and pdf, and the delta lobes of a perfect mirror and
// of glass. Handout: stages/11-path-tracing/README.md. Conventions:
// docs/conventions.md#path-tracing (the local frame, the material model).
//
// You edit only this file and path.cpp. Tests: ctest --test-dir build -L stage11
// The contracts are in framework/stage_api/stage11.h. Every direction is local: z is the outward
// normal, cos theta = v.z.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/not_implemented.h"
#include "stage_api/stage05.h"
#include "stage_api/stage10.h"
#include "stage_api/stage11.h"

namespace rt {

Real ggx_d(const Vec3& h, Real alpha) {
    // BEGIN SOLUTION
    if (h.z <= 0) return 0;
    const Real a2 = alpha * alpha;
    const Real t = h.z * h.z * (a2 - 1) + 1;
    return a2 / (std::numbers::pi_v<Real> * t * t);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#1-the-ggx-microfacet-distribution");
    // (void)h, (void)alpha;
    // return 0;
    // END SOLUTION
}

Real ggx_g1(const Vec3& v, const Vec3& h, Real alpha) {
    // BEGIN SOLUTION
    if (glm::dot(v, h) * v.z <= 0) return 0;
    const Real cos2 = v.z * v.z;
    const Real tan2 = std::max(Real(0), 1 - cos2) / cos2;
    return 2 / (1 + std::sqrt(1 + alpha * alpha * tan2));
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#1-the-ggx-microfacet-distribution");
    // (void)v, (void)h, (void)alpha;
    // return 0;
    // END SOLUTION
}

Vec3 sample_ggx_normal(Real alpha, Vec2 u) {
    // BEGIN SOLUTION
    const Real tan2 = alpha * alpha * u.x / (1 - u.x);
    const Real cos_theta = 1 / std::sqrt(1 + tan2);
    const Real sin_theta = std::sqrt(std::max(Real(0), 1 - cos_theta * cos_theta));
    const Real phi = 2 * std::numbers::pi_v<Real> * u.y;
    return Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#2-sampling-the-ggx-lobe");
    // (void)alpha, (void)u;
    // return Vec3(0, 0, 1);
    // END SOLUTION
}

Real ggx_normal_pdf(const Vec3& h, Real alpha) {
    // BEGIN SOLUTION
    return h.z > 0 ? ggx_d(h, alpha) * h.z : Real(0);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#2-sampling-the-ggx-lobe");
    // (void)h, (void)alpha;
    // return 0;
    // END SOLUTION
}

Color schlick_fresnel(const Color& f0, Real cos_theta) {
    // BEGIN SOLUTION
    const Real m = std::clamp(1 - cos_theta, Real(0), Real(1));
    const Real m5 = m * m * m * m * m;
    return f0 + (Color(1) - f0) * float(m5);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#1-the-ggx-microfacet-distribution");
    // (void)cos_theta;
    // return f0;
    // END SOLUTION
}

// BEGIN SOLUTION
namespace {

bool lit(const Color& c) {
    return c.r > 0 || c.g > 0 || c.b > 0;
}

Real mean(const Color& c) {
    return (Real(c.r) + Real(c.g) + Real(c.b)) / 3;
}

Color specular_color(const Material& m) {
    return glm::min(m.specular + m.reflective, Color(1));
}

// The chance that sample_bsdf picks the specular lobe of an opaque material.
Real specular_chance(const Material& m) {
    const Real s = mean(specular_color(m)), d = mean(m.diffuse);
    return s + d > 0 ? s / (s + d) : Real(0);
}

// The GGX BRDF for wo, wi in the upper hemisphere.
Color ggx_brdf(const Material& m, const Vec3& wo, const Vec3& wi) {
    const Real alpha = m.roughness * m.roughness;
    const Vec3 h = glm::normalize(wo + wi);
    const Real g = ggx_g1(wo, h, alpha) * ggx_g1(wi, h, alpha);
    const Real d = ggx_d(h, alpha);
    const Color f = schlick_fresnel(specular_color(m), glm::dot(wo, h));
    return f * float(d * g / (4 * wo.z * wi.z));
}

// The density of wi from the GGX lobe alone: D(h) h.z / (4 wo.h), wo and wi upper.
Real ggx_pdf(const Material& m, const Vec3& wo, const Vec3& wi) {
    const Real alpha = m.roughness * m.roughness;
    const Vec3 h = glm::normalize(wo + wi);
    return ggx_normal_pdf(h, alpha) / (4 * std::abs(glm::dot(wo, h)));
}

// Glass: reflect with probability F, refract otherwise (stage 05's refract and Schlick).
BsdfSample sample_dielectric(const Material& m, const Vec3& wo, Real u_lobe) {
    BsdfSample s;
    s.delta = true;
    const bool entering = wo.z > 0;
    const Real n1 = entering ? 1 : m.ior, n2 = entering ? m.ior : 1;
    const Real reflectance = schlick_reflectance(std::abs(wo.z), n1, n2);
    Vec3 refracted;
    const Vec3 normal(0, 0, entering ? 1 : -1);
    if (u_lobe < reflectance || !refract(-wo, normal, n1 / n2, refracted)) {
        s.wi = Vec3(-wo.x, -wo.y, wo.z);
        s.weight = Color(1);
        return s;
    }
    s.wi = refracted;
    s.weight = m.transmissive;
    return s;
}

}  // namespace
// STUB
// // Helper functions of your own may go here (an anonymous namespace keeps them in this file).
// END SOLUTION

Color eval_bsdf(const Material& material, const Vec3& wo, const Vec3& wi) {
    // BEGIN SOLUTION
    if (lit(material.transmissive) || wo.z * wi.z <= 0) return Color(0);
    const Vec3 o(wo.x, wo.y, std::abs(wo.z)), i(wi.x, wi.y, std::abs(wi.z));  // upper side
    Color f = material.diffuse * float(1 / std::numbers::pi_v<Real>);
    if (material.roughness > 0 && lit(specular_color(material))) f += ggx_brdf(material, o, i);
    return f;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#3-the-bsdf-of-a-material");
    // (void)material, (void)wo, (void)wi;
    // return Color(0);
    // END SOLUTION
}

Real bsdf_pdf(const Material& material, const Vec3& wo, const Vec3& wi) {
    // BEGIN SOLUTION
    if (lit(material.transmissive) || wo.z * wi.z <= 0) return 0;
    const Vec3 o(wo.x, wo.y, std::abs(wo.z)), i(wi.x, wi.y, std::abs(wi.z));
    const Real p_s = specular_chance(material);
    Real pdf = (1 - p_s) * i.z / std::numbers::pi_v<Real>;
    if (material.roughness > 0 && p_s > 0) pdf += p_s * ggx_pdf(material, o, i);
    return pdf;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#3-the-bsdf-of-a-material");
    // (void)material, (void)wo, (void)wi;
    // return 0;
    // END SOLUTION
}

BsdfSample sample_bsdf(const Material& material, const Vec3& wo, Real u_lobe, Vec2 u) {
    // BEGIN SOLUTION
    if (lit(material.transmissive)) return sample_dielectric(material, wo, u_lobe);
    const Real side = wo.z < 0 ? -1 : 1;  // work in wo's hemisphere, then flip back
    const Vec3 o(wo.x, wo.y, side * wo.z);
    const Real p_s = specular_chance(material);
    BsdfSample s;
    Vec3 i;
    if (u_lobe < p_s) {
        if (material.roughness == 0) {  // the mirror: a delta lobe
            s.delta = true;
            s.wi = Vec3(-wo.x, -wo.y, wo.z);
            s.weight = schlick_fresnel(specular_color(material), o.z) / float(p_s);
            return s;
        }
        const Vec3 h = sample_ggx_normal(material.roughness * material.roughness, u);
        i = 2 * glm::dot(o, h) * h - o;
        if (i.z <= 0) return s;  // below the surface: absorbed
    } else {
        i = sample_cosine_hemisphere(u);
    }
    s.wi = Vec3(i.x, i.y, side * i.z);
    s.pdf = bsdf_pdf(material, wo, s.wi);
    if (!(s.pdf > 0)) return BsdfSample{};
    s.weight = eval_bsdf(material, wo, s.wi) * float(i.z / s.pdf);
    return s;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/11-path-tracing/README.md#3-the-bsdf-of-a-material");
    // (void)material, (void)wo, (void)u_lobe, (void)u;
    // return {};
    // END SOLUTION
}

}  // namespace rt
