// Stage 03: Blinn-Phong direct lighting. Handout: stages/03-blinn-phong/README.md
// Conventions (colours are linear, light directions): docs/conventions.md
//
// You edit only this file. Tests: ctest --test-dir build -L stage03 --output-on-failure
// The contracts are in framework/stage_api/stage03.h.
#include <algorithm>
#include <cmath>

#include "core/not_implemented.h"
#include "stage_api/stage03.h"

namespace rt {

// The light arriving at `point` from one light: unit direction towards the light, distance,
// and I_L times the distance attenuation 1 / (c + l r + q r^2) (point lights only).
LightSample illuminate(const Light& light, const Vec3& point) {
    // BEGIN SOLUTION
    LightSample sample;
    if (light.kind == LightKind::Directional) {
        sample.direction = -light.direction;  // light.direction is the way the light travels
        sample.distance = kInfinity;
        sample.intensity = light.intensity;
        return sample;
    }
    const Vec3 to_light = light.position - point;
    const Real r = glm::length(to_light);
    sample.distance = r;
    sample.direction = r > 0 ? to_light / r : Vec3(0);
    const Vec3& a = light.attenuation;
    sample.intensity = light.intensity / float(a.x + a.y * r + a.z * r * r);
    return sample;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/03-blinn-phong/README.md#lights");
    // (void)light; (void)point;
    // return {};
    // END SOLUTION
}

// One light's diffuse and specular reflection: incident * (k_d max(0, N.L) + k_s max(0, N.H)^n).
// N.L <= 0 means the light is behind the surface: no contribution at all.
Color blinn_phong(const Material& material, const Vec3& normal, const Vec3& to_viewer,
                  const Vec3& to_light, const Color& incident) {
    // BEGIN SOLUTION
    const Real n_dot_l = glm::dot(normal, to_light);
    if (!(n_dot_l > 0)) return Color(0);
    Color reflected = material.diffuse * float(n_dot_l);
    const Vec3 half = to_light + to_viewer;
    const Real half_length = glm::length(half);
    if (half_length > 0) {
        const Real n_dot_h = std::max(Real(0), glm::dot(normal, half / half_length));
        reflected += material.specular * float(std::pow(n_dot_h, Real(material.shininess)));
    }
    return incident * reflected;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/03-blinn-phong/README.md#diffuse-and-specular");
    // (void)material; (void)normal; (void)to_viewer; (void)to_light; (void)incident;
    // return Color(0);
    // END SOLUTION
}

// I_direct = k_e + k_a I_a + sum over lights of visibility[i] * blinn_phong(...).
// Ask illuminate() for each light's sample; visibility[i] is (1, 1, 1) until stage 04.
Color direct_light(const Scene& scene, const Material& material, const Vec3& point,
                   const Vec3& normal, const Vec3& to_viewer, LightVisibility visibility) {
    // BEGIN SOLUTION
    Color color = material.emissive + material.ambient * scene.ambient_light;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const LightSample sample = illuminate(scene.lights[i], point);
        const Color shading =
            blinn_phong(material, normal, to_viewer, sample.direction, sample.intensity);
        color += visibility[i] * shading;
    }
    return color;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/03-blinn-phong/README.md#summing-the-terms");
    // (void)scene; (void)material; (void)point; (void)normal; (void)to_viewer; (void)visibility;
    // return Color(0);
    // END SOLUTION
}

}  // namespace rt
