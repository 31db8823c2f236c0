// Stage 05 tests: reflection and refraction directions against closed forms, total internal
// reflection, Schlick's approximation, the weights of secondary rays, and the depth limit.
#include <cmath>
#include <source_location>
#include <sstream>
#include <string>

#include "render/prepare.h"
#include "render/shade.h"
#include "stage_api/stage05.h"
#include "testing/expect_near.h"
#include "testing/random.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(Reflect, "mirror-reflection");
RT_TEST_SUITE(Refract, "refraction-snells-law");
RT_TEST_SUITE(Fresnel, "fresnel-schlicks-approximation");
RT_TEST_SUITE(Secondary, "secondary-rays-and-their-weights");
RT_TEST_SUITE(Recursion, "secondary-rays-and-their-weights");

constexpr Real kTol = Real(1e-5);

using rt::testing::expect_vec_near;

TEST_F(Reflect, ClosedForm) {
    expect_vec_near(reflect(Vec3(1, -1, 0), Vec3(0, 1, 0)), Vec3(1, 1, 0),
                    "reflect((1, -1, 0), n = (0, 1, 0))");
    // Length is kept; the normal may face either way.
    expect_vec_near(reflect(Vec3(0, 0, -3), Vec3(0, 0, -1)), Vec3(0, 0, 3),
                    "reflect((0, 0, -3), n = (0, 0, -1)): length kept, either side of the normal");
    const Vec3 n = glm::normalize(Vec3(1, 1, 0));
    expect_vec_near(reflect(Vec3(-1, 0, 0), n), Vec3(0, 1, 0),
                    "reflect((-1, 0, 0), n = normalize(1, 1, 0))");
}

// 45 degrees from air into glass (1.5): sin(t) = sin(45)/1.5, bent towards the normal.
TEST_F(Refract, SnellClosedForm) {
    const Vec3 d = glm::normalize(Vec3(1, -1, 0));
    Vec3 t;
    ASSERT_TRUE(refract(d, Vec3(0, 1, 0), Real(1) / Real(1.5), t));
    const Real sin_t = std::sqrt(Real(0.5)) / Real(1.5);
    expect_vec_near(t, Vec3(sin_t, -std::sqrt(1 - sin_t * sin_t), 0),
                    "45 degrees from air into glass 1.5: sin(t) = sin(45) / 1.5");
    EXPECT_NEAR(glm::length(t), 1, kTol);
}

TEST_F(Refract, NormalIncidenceGoesStraight) {
    Vec3 t;
    ASSERT_TRUE(refract(Vec3(0, 0, -1), Vec3(0, 0, 1), Real(1) / Real(1.33), t));
    expect_vec_near(t, Vec3(0, 0, -1), "normal incidence into water: straight on");
    ASSERT_TRUE(refract(Vec3(0, 0, -1), Vec3(0, 0, 1), Real(1.5), t));  // leaving glass
    expect_vec_near(t, Vec3(0, 0, -1), "normal incidence leaving glass: straight on");
}

// From glass (1.5) into air the critical angle is asin(1/1.5) = 41.81 degrees: just below it the
// ray leaves almost along the surface; at and past it nothing leaves (total internal reflection).
TEST_F(Refract, TotalInternalReflectionAtCriticalAngle) {
    const Real critical = std::asin(Real(1) / Real(1.5));
    const Vec3 n(0, 1, 0);
    auto dir = [](Real angle) { return Vec3(std::sin(angle), -std::cos(angle), 0); };
    Vec3 t(7);
    ASSERT_TRUE(refract(dir(critical - Real(0.01)), n, Real(1.5), t));
    EXPECT_GT(t.x, Real(0.98));  // nearly grazing: sin(t) = 1.5 sin(critical - 0.01) = 0.9888
    t = Vec3(7);
    EXPECT_FALSE(refract(dir(critical + Real(1e-4)), n, Real(1.5), t));
    EXPECT_EQ(t, Vec3(7)) << "refracted must be left alone on total internal reflection";
    EXPECT_FALSE(refract(dir(Real(1.2)), n, Real(1.5), t));
    EXPECT_FALSE(refract(dir(kPi / 2 - Real(1e-3)), n, Real(1.5), t));
}

// Schlick: R0 = 0.04 for glass at normal incidence, 1 at grazing incidence and past the
// critical angle, and always in [0, 1].
TEST_F(Fresnel, SchlickClosedForms) {
    EXPECT_NEAR(schlick_reflectance(1, 1, 1.5f), 0.04, kTol);
    EXPECT_NEAR(schlick_reflectance(1, 1.5f, 1), 0.04, kTol);
    EXPECT_NEAR(schlick_reflectance(0, 1, 1.5f), 1, kTol);
    EXPECT_NEAR(schlick_reflectance(Real(0.5), 1, 1.5f), 0.04 + 0.96 / 32, kTol);
    EXPECT_EQ(schlick_reflectance(std::cos(Real(1.0)), 1.5f, 1), 1)
        << "leaving glass (1.5 into 1) at 57 degrees, past the critical angle 41.8 degrees: "
           "F = 1; when n1 > n2 Schlick uses cos_t, the cosine on the less dense side";
    for (int i = 0; i <= 100; ++i) {
        const Real c = Real(i) / 100;
        for (Real n2 : {Real(1.33), Real(1.5), Real(2.4)}) {
            const Real in = schlick_reflectance(c, 1, n2), out = schlick_reflectance(c, n2, 1);
            EXPECT_TRUE(in >= 0 && in <= 1) << c;
            EXPECT_TRUE(out >= 0 && out <= 1) << c;
        }
    }
}

SurfacePoint flat_point(Vec3 normal, bool front_face) {
    SurfacePoint at;
    at.point = Vec3(0.25f, 0.5f, -0.75f);
    at.error = Vec3(1e-6f);
    at.normal = normal;
    at.front_face = front_face;
    return at;
}

Material mirror_glass(Color k_r, Color k_t, float ior) {
    Material m;
    m.reflective = k_r;
    m.transmissive = k_t;
    m.ior = ior;
    return m;
}

// A mirror: one reflected ray with weight k_r, starting on the incoming side.
TEST_F(Secondary, Mirror) {
    const SurfacePoint at = flat_point(Vec3(0, 1, 0), true);
    const Ray in{at.point + Vec3(-1, 1, 0), Vec3(1, -1, 0)};
    const SecondaryRays s =
        secondary_rays(in, at, mirror_glass(Color(0.8f, 0.7f, 0.6f), Color(0), 1.5f), false);
    ASSERT_TRUE(s.reflected.valid);
    EXPECT_FALSE(s.refracted.valid);
    EXPECT_EQ(s.reflected.weight, Color(0.8f, 0.7f, 0.6f));
    expect_vec_near(glm::normalize(s.reflected.ray.direction), glm::normalize(Vec3(1, 1, 0)),
                    "mirror hit along (1, -1, 0) with normal (0, 1, 0): reflected direction");
    EXPECT_EQ(s.reflected.ray.origin,
              offset_ray_origin(at.point, at.error, at.normal, s.reflected.ray.direction));
    EXPECT_GT(s.reflected.ray.origin.y, at.point.y);
}

// Stage 10's motion blur gives rays a time; reflected and refracted rays keep their point's.
TEST_F(Secondary, RaysKeepThePointsTime) {
    SurfacePoint at = flat_point(Vec3(0, 1, 0), true);
    at.time = 0.5f;
    const Ray in{at.point + Vec3(-1, 1, 0), Vec3(1, -1, 0), at.time};
    const SecondaryRays s =
        secondary_rays(in, at, mirror_glass(Color(0.5f), Color(0.5f), 1.5f), false);
    ASSERT_TRUE(s.reflected.valid && s.refracted.valid)
        << "entering glass 1.5 at 45 degrees (front face): eta = n1 / n2 = 1 / 1.5, and going "
           "into a denser medium there is no total internal reflection";
    EXPECT_EQ(s.reflected.ray.time, at.time) << "make rays with spawn_ray(at, n, direction)";
    EXPECT_EQ(s.refracted.ray.time, at.time) << "make rays with spawn_ray(at, n, direction)";
}

// Entering glass (front face) bends towards the normal with eta = 1/ior and starts below the
// surface; leaving (back face) uses eta = ior.
TEST_F(Secondary, EnteringAndLeaving) {
    const Vec3 d = glm::normalize(Vec3(1, -1, 0));
    const Material glass = mirror_glass(Color(0), Color(0.9f), 1.5f);
    SurfacePoint at = flat_point(Vec3(0, 1, 0), true);
    SecondaryRays s = secondary_rays(Ray{at.point - d, d}, at, glass, false);
    ASSERT_TRUE(s.refracted.valid)
        << "entering glass 1.5 at 45 degrees (front face): eta = n1 / n2 = 1 / 1.5, and going "
           "into a denser medium there is no total internal reflection";
    EXPECT_FALSE(s.reflected.valid);
    EXPECT_EQ(s.refracted.weight, Color(0.9f));
    Vec3 expected;
    ASSERT_TRUE(refract(d, at.normal, Real(1) / Real(1.5), expected));
    expect_vec_near(s.refracted.ray.direction, expected,
                    "entering glass (front face): refracted direction with eta = 1 / ior");
    EXPECT_LT(s.refracted.ray.origin.y, at.point.y);

    // Leaving at 30 degrees: sin(t) = 1.5 sin(30) = 0.75, bent away from the normal.
    at.front_face = false;
    const Vec3 d30(std::sin(kPi / 6), -std::cos(kPi / 6), 0);
    s = secondary_rays(Ray{at.point - d30, d30}, at, glass, false);
    ASSERT_TRUE(s.refracted.valid);
    EXPECT_NEAR(s.refracted.ray.direction.x, 0.75, kTol);
    EXPECT_FALSE(s.total_internal_reflection);
}

// The incoming direction need not be unit length (an instance's ray is not renormalised:
// docs/conventions.md#transforms); the secondary rays and their weights do not depend on it.
TEST_F(Secondary, NonUnitIncomingDirection) {
    const Material glass = mirror_glass(Color(0.1f), Color(0.9f), 1.5f);
    const Vec3 d(std::sin(kPi / 6), -std::cos(kPi / 6), 0);  // 30 degrees from the normal
    for (const bool front_face : {true, false}) {
        const SurfacePoint at = flat_point(Vec3(0, 1, 0), front_face);
        const std::string side = front_face ? "entering" : "leaving";
        const SecondaryRays unit = secondary_rays(Ray{at.point - d, d}, at, glass, true);
        const SecondaryRays scaled =
            secondary_rays(Ray{at.point - d, Real(3) * d}, at, glass, true);
        ASSERT_TRUE(unit.refracted.valid && scaled.refracted.valid) << side;
        const std::string what = side +
                                 " glass at 30 degrees, incoming direction 3 times unit length: "
                                 "refract needs a unit d, normalise incoming.direction";
        expect_vec_near(scaled.refracted.ray.direction, unit.refracted.ray.direction,
                        "refracted direction, " + what);
        expect_vec_near(glm::normalize(scaled.reflected.ray.direction),
                        glm::normalize(unit.reflected.ray.direction),
                        "reflected direction, " + what);
        EXPECT_NEAR(scaled.reflected.weight.r, unit.reflected.weight.r, kTol)
            << "reflected weight (Fresnel on), " << what;
    }
}

// Leaving glass past the critical angle: no refracted ray; all of k_t is reflected.
TEST_F(Secondary, TotalInternalReflectionReflectsTransmission) {
    const SurfacePoint at = flat_point(Vec3(0, 1, 0), false);
    const Vec3 d = glm::normalize(Vec3(2, -1, 0));  // 63 degrees from the normal
    const SecondaryRays s = secondary_rays(Ray{at.point - d, d}, at,
                                           mirror_glass(Color(0.1f), Color(0.8f), 1.5f), false);
    EXPECT_TRUE(s.total_internal_reflection);
    EXPECT_FALSE(s.refracted.valid);
    ASSERT_TRUE(s.reflected.valid);
    EXPECT_NEAR(s.reflected.weight.g, 0.9f, 1e-6f);
}

// Energy is never created: whatever the angle, side, index and Fresnel setting, the weights
// sum to k_r + k_t and none is negative.
TEST_F(Secondary, WeightsNeverExceedMaterial) {
    testing::Random random(42);
    auto u = [&random] { return float(random.uniform(0, 1)); };
    for (int i = 0; i < 500; ++i) {
        const float angle = u() * 1.55f;
        const Vec3 d(std::sin(angle), -std::cos(angle), 0);
        const SurfacePoint at = flat_point(Vec3(0, 1, 0), i % 2 == 0);
        // Drawn one a statement: the order of a call's arguments is the compiler's choice.
        const Color k_r(u() * 0.5f);
        const float t_red = u() * 0.5f;
        const float t_green = u() * 0.5f;
        const float ior = 1 + 1.5f * u();
        const Material m = mirror_glass(k_r, Color(t_red, t_green, 0.5f), ior);
        const SecondaryRays s = secondary_rays(Ray{at.point - d, d}, at, m, i % 3 != 0);
        const Color total = s.reflected.weight + s.refracted.weight;
        for (int k = 0; k < 3; ++k) {
            EXPECT_GE(s.reflected.weight[k], 0);
            EXPECT_GE(s.refracted.weight[k], 0);
            EXPECT_LE(total[k], m.reflective[k] + m.transmissive[k] + 1e-6f);
            EXPECT_NEAR(total[k], m.reflective[k] + m.transmissive[k], 1e-6f);
        }
    }
}

// Fresnel moves F k_t from refraction to reflection: at normal incidence F = 0.04.
TEST_F(Secondary, FresnelWeights) {
    const SurfacePoint at = flat_point(Vec3(0, 1, 0), true);
    const SecondaryRays s = secondary_rays(Ray{at.point + Vec3(0, 1, 0), Vec3(0, -1, 0)}, at,
                                           mirror_glass(Color(0), Color(1), 1.5f), true);
    ASSERT_TRUE(s.reflected.valid && s.refracted.valid);
    EXPECT_NEAR(s.reflected.weight.r, 0.04f, 1e-5f);
    EXPECT_NEAR(s.refracted.weight.r, 0.96f, 1e-5f);
}

// Two parallel mirrors z = 0 and z = 2 (k_r = 1/2, emission e): a ray bouncing between them sees
// e (1 + 1/2 + ... + 1/2^N) with N = max_depth, and its tree is exactly N + 1 rays deep.
TEST_F(Recursion, DepthLimitRespected) {
    PreparedScene scene;
    Material m;
    m.diffuse = Color(0);
    m.emissive = Color(0.1f, 0.2f, 0.4f);
    m.reflective = Color(0.5f);
    scene.materials = {m};
    scene.planes = {Plane{Vec3(0), Vec3(0, 0, 1), 0}, Plane{Vec3(0, 0, 2), Vec3(0, 0, -1), 0}};
    refresh_features(scene);
    for (int depth : {0, 1, 2, 5, 12}) {
        scene.max_depth = depth;
        RayNode tree;
        const Color c = trace_ray(scene, Ray{Vec3(0, 0, 1), Vec3(0, 0, -1)}, 0, &tree);
        const float sum = 2 - std::ldexp(1.0f, -depth);  // 1 + 1/2 + ... + 1/2^depth
        EXPECT_NEAR(c.b, 0.4f * sum, 1e-5f) << "max_depth " << depth;
        int levels = 1;
        for (const RayNode* n = &tree; !n->children.empty(); n = &n->children[0]) ++levels;
        EXPECT_EQ(levels, depth + 1) << "max_depth " << depth;
    }
}

}  // namespace
}  // namespace rt
