// Stage 08: environment maps. Handout: stages/08-environment/README.md
// Conventions (lat-long mapping, cube faces, rotation): docs/conventions.md#environment-maps
//
// You edit only this file. Tests: ctest --test-dir build -L stage08 --output-on-failure
// The contracts are in framework/stage_api/stage08.h; the image lookup is stage 07's
// sample_bilinear (framework/stage_api/stage07.h).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/not_implemented.h"
#include "stage_api/stage07.h"
#include "stage_api/stage08.h"

namespace rt {

// Longitude and latitude of the direction, seen from inside (OpenImageIO's y-up lat-long).
Vec2 latlong_uv(const Vec3& direction) {
    // BEGIN SOLUTION
    constexpr Real pi = std::numbers::pi_v<Real>;
    const Vec3 d = glm::normalize(direction);
    Real u = std::atan2(-d.x, d.z) / (2 * pi) + Real(0.5);
    if (u >= 1) u = 0;  // atan2(+0, negative) is +pi: u = 1 is the seam, u = 0
    return Vec2(u, std::acos(std::clamp(d.y, Real(-1), Real(1))) / pi);
    // STUB
    // RT_NOT_IMPLEMENTED("stages/08-environment/README.md#1-lat-long-coordinates");
    // (void)direction;
    // return Vec2(0);
    // END SOLUTION
}

// The OpenGL cube-map table: the major axis picks the face, the other two give (u, v).
CubeFaceUv cube_face_uv(const Vec3& direction) {
    // BEGIN SOLUTION
    const Real ax = std::abs(direction.x), ay = std::abs(direction.y), az = std::abs(direction.z);
    CubeFaceUv r;
    Real sc, tc, ma;
    if (ax >= ay && ax >= az) {  // ties: x before y before z
        const bool positive = direction.x > 0;
        r.face = positive ? 0 : 1;
        sc = positive ? -direction.z : direction.z;
        tc = -direction.y;
        ma = ax;
    } else if (ay >= az) {
        const bool positive = direction.y > 0;
        r.face = positive ? 2 : 3;
        sc = direction.x;
        tc = positive ? direction.z : -direction.z;
        ma = ay;
    } else {
        const bool positive = direction.z > 0;
        r.face = positive ? 4 : 5;
        sc = positive ? direction.x : -direction.x;
        tc = -direction.y;
        ma = az;
    }
    const auto coordinate = [ma](Real c) { return std::clamp((c / ma + 1) / 2, Real(0), Real(1)); };
    r.uv = Vec2(coordinate(sc), coordinate(tc));
    return r;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/08-environment/README.md#2-cube-map-faces");
    // (void)direction;
    // return {};
    // END SOLUTION
}

// Rotate, map to an image position, filter, scale.
Color environment_radiance(const Scene& scene, const Vec3& direction) {
    // BEGIN SOLUTION
    const Environment& env = scene.environment;
    if (env.kind == EnvironmentKind::None) return scene.background;
    // The environment turned by +rotate_y: look up the direction turned back by -rotate_y.
    const Real angle = Real(env.rotate_y) * std::numbers::pi_v<Real> / 180;
    const Real c = std::cos(angle), s = std::sin(angle);
    const Vec3 d(c * direction.x - s * direction.z, direction.y, s * direction.x + c * direction.z);
    Color radiance;
    if (env.kind == EnvironmentKind::LatLong) {
        const TextureView image = scene.texture_view(std::size_t(env.image), false);
        Vec2 uv = latlong_uv(d);
        // Rows never wrap: v stays between the centres of the top and bottom rows.
        const Real half_row = Real(0.5) / Real(image.height);
        uv.y = std::clamp(uv.y, half_row, 1 - half_row);
        radiance = sample_bilinear(image, uv, TextureWrap::Repeat);
    } else {
        const CubeFaceUv at = cube_face_uv(d);
        const TextureView face = scene.texture_view(std::size_t(env.faces[at.face]), false);
        radiance = sample_bilinear(face, at.uv, TextureWrap::Clamp);
    }
    return radiance * env.intensity;
    // STUB
    // RT_NOT_IMPLEMENTED("stages/08-environment/README.md#3-looking-up-the-environment");
    // (void)scene; (void)direction;
    // return Color(0);
    // END SOLUTION
}

}  // namespace rt
