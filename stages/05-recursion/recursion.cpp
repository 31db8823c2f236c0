// Stage 05: recursive reflection and refraction. Handout: stages/05-recursion/README.md
// Conventions (front_face, nested objects, ray origins): docs/conventions.md
//
// You edit only this file. Tests: ctest --test-dir build -L stage05 --output-on-failure
// The contracts are in framework/stage_api/stage05.h. The framework's shading driver
// (framework/render/shade.cpp) does the recursion: it calls secondary_rays() at each hit.
#include <algorithm>
#include <cmath>

#include "core/not_implemented.h"
#include "stage_api/stage05.h"

namespace rt {

// Mirror reflection of d about the unit normal n.
Vec3 reflect(const Vec3& d, const Vec3& n) {
    // BEGIN SOLUTION
    return d - 2 * glm::dot(d, n) * n;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/05-recursion/README.md#mirror-reflection");
    // (void)n;
    // return d;
    // END SOLUTION
}

// Snell's law, eta = n_incoming / n_outgoing; false on total internal reflection.
bool refract(const Vec3& d, const Vec3& n, Real eta, Vec3& refracted) {
    // BEGIN SOLUTION
    const Real cos_i = std::min(Real(1), -glm::dot(d, n));
    const Real sin2_t = eta * eta * (1 - cos_i * cos_i);
    if (sin2_t >= 1) return false;  // at the critical angle the ray would only graze
    const Real cos_t = std::sqrt(1 - sin2_t);
    refracted = glm::normalize(eta * d + (eta * cos_i - cos_t) * n);
    return true;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/05-recursion/README.md#refraction-snells-law");
    // (void)d; (void)n; (void)eta; (void)refracted;
    // return false;
    // END SOLUTION
}

// Schlick: R0 + (1 - R0)(1 - cos)^5 with R0 = ((n1 - n2) / (n1 + n2))^2, cos on the less dense
// side; 1 past the critical angle.
Real schlick_reflectance(Real cos_incident, Real n1, Real n2) {
    // BEGIN SOLUTION
    Real cosine = std::clamp(cos_incident, Real(0), Real(1));
    if (n1 > n2) {
        const Real sin2_t = (n1 / n2) * (n1 / n2) * (1 - cosine * cosine);
        if (sin2_t >= 1) return 1;
        cosine = std::sqrt(1 - sin2_t);
    }
    Real r0 = (n1 - n2) / (n1 + n2);
    r0 *= r0;
    const Real x = 1 - cosine;
    return r0 + (1 - r0) * x * x * x * x * x;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/05-recursion/README.md#fresnel-schlicks-approximation");
    // (void)cos_incident; (void)n1; (void)n2;
    // return 0;
    // END SOLUTION
}

// The reflected and refracted rays with their weights (see stage05.h for the full contract).
SecondaryRays secondary_rays(const Ray& incoming, const SurfacePoint& at, const Material& material,
                             bool fresnel) {
    // BEGIN SOLUTION
    SecondaryRays out;
    const Vec3 d = glm::normalize(incoming.direction);
    const Vec3& n = at.normal;  // faces the incoming ray
    Color k_r = material.reflective, k_t = material.transmissive;
    Vec3 refracted_direction(0);
    if (k_t != Color(0)) {
        // front_face: from air (1) into the material; otherwise from the material into air.
        const Real n1 = at.front_face ? 1 : Real(material.ior);
        const Real n2 = at.front_face ? Real(material.ior) : 1;
        if (!refract(d, n, n1 / n2, refracted_direction)) {
            out.total_internal_reflection = true;
            k_r += k_t;
            k_t = Color(0);
        } else if (fresnel) {
            const float f = float(schlick_reflectance(-glm::dot(d, n), n1, n2));
            k_r += f * k_t;
            k_t *= 1 - f;
        }
    }
    if (k_r != Color(0)) {
        const Vec3 r = reflect(d, n);
        out.reflected = {spawn_ray(at, n, r), k_r, true};
    }
    if (k_t != Color(0)) out.refracted = {spawn_ray(at, n, refracted_direction), k_t, true};
    return out;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/05-recursion/README.md#secondary-rays-and-their-weights");
    // (void)incoming; (void)at; (void)material; (void)fresnel;
    // return {};
    // END SOLUTION
}

}  // namespace rt
