// Stage 03 tests with closed-form answers: light samples, the Blinn-Phong terms, their sum, and
// a rendered pixel of one sphere lit by one light.
#include <cmath>
#include <source_location>
#include <sstream>
#include <string>

#include "render/prepare.h"
#include "render/shade.h"
#include "stage_api/stage03.h"
#include "testing/expect_near.h"
#include "testing/random.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(Lights, "lights");
RT_TEST_SUITE(BlinnPhong, "diffuse-and-specular");
RT_TEST_SUITE(DirectLight, "summing-the-terms");

constexpr float kTol = 1e-5f;

// Relative tolerance: some expected values here exceed 1.
void expect_color_near(const Color& actual, const Color& expected, const std::string& what,
                       float tol = kTol,
                       std::source_location where = std::source_location::current()) {
    testing::expect_color_near(actual, expected, what, tol, testing::Scale::Relative, where);
}

Light point_light(Vec3 position, Color intensity, Vec3 attenuation = Vec3(1, 0, 1)) {
    Light l;
    l.kind = LightKind::Point;
    l.position = position;
    l.intensity = intensity;
    l.attenuation = attenuation;
    return l;
}

Light directional_light(Vec3 direction, Color intensity) {
    Light l;
    l.kind = LightKind::Directional;
    l.direction = glm::normalize(direction);
    l.intensity = intensity;
    return l;
}

Material material(Color kd, Color ks, float shininess) {
    Material m;
    m.diffuse = kd;
    m.specular = ks;
    m.shininess = shininess;
    return m;
}

// Default attenuation 1 / (1 + r^2): at r = 3 a tenth of I_L arrives.
TEST_F(Lights, PointLightDefaultAttenuation) {
    const LightSample s = illuminate(point_light(Vec3(1, 5, 2), Color(2, 1, 0.5f)), Vec3(1, 2, 2));
    EXPECT_NEAR(s.distance, 3, kTol);
    EXPECT_NEAR(s.direction.x, 0, kTol);
    EXPECT_NEAR(s.direction.y, 1, kTol);
    EXPECT_NEAR(s.direction.z, 0, kTol);
    expect_color_near(s.intensity, Color(0.2f, 0.1f, 0.05f),
                      "point light 3 away, attenuation (1, 0, 1): I_L / (1 + 9)");
}

// 1 / (c + l r + q r^2) with (c, l, q) = (2, 0.5, 0.25) at r = 2: 1 / 4.
TEST_F(Lights, PointLightCustomAttenuation) {
    const LightSample s =
        illuminate(point_light(Vec3(0, 0, 2), Color(1), Vec3(2, 0.5f, 0.25f)), Vec3(0));
    EXPECT_NEAR(s.distance, 2, kTol);
    expect_color_near(s.intensity, Color(0.25f),
                      "point light 2 away, attenuation (2, 0.5, 0.25): I_L / (2 + 1 + 1)");
}

// A directional light's direction is the way the light travels: the point sees it in -direction,
// at infinite distance, without attenuation.
TEST_F(Lights, DirectionalLight) {
    const LightSample s =
        illuminate(directional_light(Vec3(0, -1, 0), Color(0.7f)), Vec3(100, -3, 7));
    EXPECT_NEAR(s.direction.y, 1, kTol);
    EXPECT_TRUE(std::isinf(s.distance));
    expect_color_near(s.intensity, Color(0.7f), "directional light: intensity I_L, no attenuation");
}

// N.L = 0.6 and V the mirror of L: H = N, so the specular term is k_s whatever n_s.
TEST_F(BlinnPhong, MirrorGeometryClosedForm) {
    const Material m = material(Color(0.5f, 0.25f, 0.1f), Color(0.3f), 50);
    const Color c =
        blinn_phong(m, Vec3(0, 0, 1), Vec3(-0.8f, 0, 0.6f), Vec3(0.8f, 0, 0.6f), Color(2));
    expect_color_near(c, Color(2) * (m.diffuse * 0.6f + m.specular),
                      "N.L = 0.6, H = N: incident * (k_d 0.6 + k_s)");
}

// V = N, L = (0.8, 0, 0.6): N.H = 2 / sqrt(5), so with n_s = 2 the specular factor is 4/5.
TEST_F(BlinnPhong, SpecularExponent) {
    const Material m = material(Color(0), Color(1, 0.5f, 0.25f), 2);
    const Color c = blinn_phong(m, Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0.8f, 0, 0.6f), Color(1));
    expect_color_near(c, Color(0.8f, 0.4f, 0.2f),
                      "V = N, N.H = 2 / sqrt(5), n_s = 2: k_s * 4/5 (is H normalised?)");
}

// A light below the surface adds nothing, specular included (its half vector can still lean
// towards N).
TEST_F(BlinnPhong, LightBehindSurfaceGivesNothing) {
    const Material m = material(Color(0.8f), Color(1), 4);
    const Color c =
        blinn_phong(m, Vec3(0, 0, 1), Vec3(0.6f, 0, 0.8f), Vec3(0.8f, 0, -0.6f), Color(1));
    expect_color_near(c, Color(0), "light below the surface (N.L < 0): no diffuse, no specular");
}

// The viewer below the surface (a back face seen from behind) with the light above: N.L = 0.6
// but H = normalize(L + V) leans below, N.H = -1/sqrt(2). The clamp max(0, N.H) comes before the
// power, so no highlight, whatever the exponent: with n_s = 2 an unclamped (-0.707)^2 adds 0.5.
TEST_F(BlinnPhong, HalfVectorBelowSurfaceGivesNoHighlight) {
    const Material m = material(Color(0.5f), Color(1), 2);
    const Color c =
        blinn_phong(m, Vec3(0, 0, 1), Vec3(-0.6f, 0, -0.8f), Vec3(0.8f, 0, 0.6f), Color(1));
    expect_color_near(c, m.diffuse * 0.6f,
                      "N.H < 0 (the viewer below the surface): the specular term is "
                      "k_s max(0, N.H)^n_s = 0; clamp N.H at 0 before the power "
                      "(stages/03-blinn-phong/README.md#diffuse-and-specular)");
}

// Never negative, never NaN: random unit vectors, including L = -V (a zero half vector).
TEST_F(BlinnPhong, NeverNegativeOrNaN) {
    testing::Random random(1234);
    auto unit = [&random] { return random.unit(); };
    const Material m = material(Color(0.8f, 0.5f, 0.2f), Color(0.5f), 16);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 n = unit(), v = unit();
        const Vec3 l = i % 10 == 0 ? -v : unit();
        const Color c = blinn_phong(m, n, v, l, Color(1));
        for (int k = 0; k < 3; ++k) {
            ASSERT_TRUE(std::isfinite(c[k])) << "n.l = " << glm::dot(n, l);
            ASSERT_GE(c[k], 0.0f);
        }
    }
}

// Without lights: k_e + k_a I_a.
TEST_F(DirectLight, EmissiveAndAmbient) {
    PreparedScene scene;
    scene.ambient_light = Color(0.5f, 0.25f, 1);
    Material m;
    m.emissive = Color(0.1f, 0.2f, 0.3f);
    m.ambient = Color(0.2f);
    expect_color_near(direct_light(scene, m, Vec3(0), Vec3(0, 1, 0), Vec3(0, 1, 0)),
                      Color(0.2f, 0.25f, 0.5f), "no lights: k_e + k_a I_a");
}

// Lights add up, and the visibility filter scales each light separately.
TEST_F(DirectLight, SumsLightsThroughVisibility) {
    PreparedScene scene;
    scene.lights = {directional_light(Vec3(0, -1, 0), Color(1)),
                    point_light(Vec3(0, 3, 0), Color(5))};
    const Material m = material(Color(0.5f), Color(0), 1);
    const Vec3 p(0), n(0, 1, 0), v(0, 1, 0);
    // Light 0: 1 * 0.5; light 1: 5 / (1 + 9) * 0.5.
    expect_color_near(direct_light(scene, m, p, n, v), Color(0.5f + 0.25f),
                      "two lights, no filter: 1 * 0.5 + 5 / (1 + 9) * 0.5");
    const Color half_second[] = {Color(1), Color(0.5f, 0, 1)};
    expect_color_near(direct_light(scene, m, p, n, v, LightVisibility{half_second}),
                      Color(0.5f + 0.125f, 0.5f, 0.75f),
                      "two lights, visibility (1, 1, 1) for light 0 and (0.5, 0, 1) for light 1");
}

// One unit sphere at the origin, seen from (0, 0, 5) through the centre pixel of a 101x101
// image, lit by one light.
PreparedScene one_sphere(const Light& light) {
    PreparedScene scene;
    scene.camera =
        make_look_at_camera(Projection::Perspective, Vec3(0, 0, 5), Vec3(0), Vec3(0, 1, 0), 30, 2);
    scene.image = {101, 101};
    scene.mode = RenderMode::Shaded;
    scene.max_depth = 0;
    scene.ambient_light = Color(0.2f);
    Material m = material(Color(0.6f, 0.4f, 0.2f), Color(0.5f), 20);
    m.ambient = Color(0.25f);
    m.emissive = Color(0.01f, 0.02f, 0.03f);
    scene.materials = {m};
    scene.spheres = {Sphere{Vec3(0), 1, 0}};
    scene.lights = {light};
    refresh_features(scene);
    return scene;
}

// The point nearest the light, (0, 0, 1): N = L = V = H, r = 2, A = 1 / 5, so the pixel is
// k_e + k_a I_a + I_L / 5 (k_d + k_s).
TEST_F(DirectLight, PixelNearestTheLight) {
    const PreparedScene scene = one_sphere(point_light(Vec3(0, 0, 3), Color(1, 2, 3)));
    const Material& m = scene.materials[0];
    const Color expected = m.emissive + m.ambient * scene.ambient_light +
                           Color(1, 2, 3) / 5.0f * (m.diffuse + m.specular);
    expect_color_near(shade_pixel(scene, 50, 50), expected,
                      "centre pixel (50, 50), the point nearest the light: "
                      "k_e + k_a I_a + I_L / 5 (k_d + k_s)");
}

// Light travelling along -x: (0, 0, 1) is on the terminator (N.L = 0), so only k_e + k_a I_a is
// left; a pixel of the lit side at the same height gets more.
TEST_F(DirectLight, PixelOnTheTerminator) {
    const PreparedScene scene = one_sphere(directional_light(Vec3(-1, 0, 0), Color(1)));
    const Material& m = scene.materials[0];
    expect_color_near(shade_pixel(scene, 50, 50), m.emissive + m.ambient * scene.ambient_light,
                      "centre pixel (50, 50), on the terminator (N.L = 0): k_e + k_a I_a only");
    const Color lit = shade_pixel(scene, 60, 50);
    EXPECT_GT(lit.r, m.emissive.r + m.ambient.r * scene.ambient_light.r + 0.05f);
    const Color dark = shade_pixel(scene, 40, 50);
    expect_color_near(dark, m.emissive + m.ambient * scene.ambient_light,
                      "pixel (40, 50), on the dark side: k_e + k_a I_a only");
}

}  // namespace
}  // namespace rt
