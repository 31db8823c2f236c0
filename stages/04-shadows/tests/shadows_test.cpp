// Stage 04 tests: the shadow ray, self-intersection (acne) far from the origin and at grazing
// light, thin occluders, light filtered through transparent surfaces, and light linking (the
// visibility the framework gives direct_light).
#include <cmath>
#include <source_location>
#include <sstream>
#include <string>

#include "render/prepare.h"
#include "render/render.h"
#include "stage_api/stage02.h"
#include "stage_api/stage04.h"
#include "testing/expect_near.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(ShadowRayContract, "shadow-rays");
RT_TEST_SUITE(Acne, "robust-ray-origins");
RT_TEST_SUITE(Transmittance, "coloured-shadows-through-glass");
RT_TEST_SUITE(LightLinking, "light-linking");

Light point_light(Vec3 position) {
    Light l;
    l.kind = LightKind::Point;
    l.position = position;
    l.intensity = Color(10);
    return l;
}

Light directional_light(Vec3 direction, Color intensity = Color(1)) {
    Light l;
    l.kind = LightKind::Directional;
    l.direction = glm::normalize(direction);
    l.intensity = intensity;
    return l;
}

Material glass(Color k_t) {
    Material m;
    m.transmissive = k_t;
    return m;
}

// A floor y = 0 (plane 0, material 0: opaque) and whatever a test adds after it.
PreparedScene floor_scene() {
    PreparedScene scene;
    scene.materials = {Material{}};
    scene.planes = {Plane{Vec3(0), Vec3(0, 1, 0), 0}};
    return scene;
}

// The surface point of the floor at (x, 0, z), seen from above.
SurfacePoint floor_point(const PreparedScene& scene, Real x, Real z) {
    Hit hit;
    hit.t = 1;
    hit.point = Vec3(x, 0, z);
    hit.normal = Vec3(0, 1, 0);
    hit.front_face = true;
    hit.primitive = scene.primitive_id(Scene::Kind::Plane, 0);
    hit.material = 0;
    return surface_point(scene, Ray{Vec3(x, 1, z), Vec3(0, -1, 0)}, hit);
}

using rt::testing::expect_color_near;

// The origin is the framework's robust offset origin, the direction the light's, and the range
// ends at the light (point) or never (directional).
TEST_F(ShadowRayContract, RobustOriginAndRange) {
    const PreparedScene scene = floor_scene();
    const SurfacePoint at = floor_point(scene, 0.3f, -0.2f);
    const LightSample sample = illuminate(point_light(Vec3(0.3f, 4, -0.2f)), at.point);
    const ShadowRay s = shadow_ray(at, sample);
    EXPECT_EQ(s.ray.origin, offset_ray_origin(at.point, at.error, at.normal, sample.direction));
    EXPECT_GE(s.ray.origin.y, 0);  // never below the surface
    Hit self;
    EXPECT_FALSE(intersect_nearest(s.ray, scene, s.t_range, self))
        << "the shadow ray hits its own surface";
    EXPECT_EQ(s.ray.direction, sample.direction);
    EXPECT_EQ(s.t_range.min, 0);
    EXPECT_NEAR(s.t_range.max, 4, 1e-5);
    const ShadowRay d = shadow_ray(at, illuminate(directional_light(Vec3(0, -1, 0)), at.point));
    EXPECT_TRUE(std::isinf(d.t_range.max));
}

// Stage 10's motion blur gives rays a time; a shadow ray sees the scene at its point's time.
TEST_F(ShadowRayContract, KeepsThePointsTime) {
    const PreparedScene scene = floor_scene();
    SurfacePoint at = floor_point(scene, 0.3f, -0.2f);
    at.time = 0.75f;
    const ShadowRay s = shadow_ray(at, illuminate(point_light(Vec3(0.3f, 4, -0.2f)), at.point));
    EXPECT_EQ(s.ray.time, at.time) << "make the ray with spawn_ray(at, at.normal, direction)";
}

// Renders `scene` with and without shadows and counts the pixels that differ (`acne`) and the
// pixels lit without shadows (`lit`). With nothing that can cast a shadow on the lit surface the
// two images must be identical: any difference is shadow acne.
struct AcneCount {
    int acne = 0, lit = 0, pixels = 0;
};
// `scene` rendered shaded, with its shadows on or off.
Image render_with_shadows(PreparedScene scene, bool shadows) {
    scene.shadows = shadows;
    refresh_features(scene);
    return render(scene, RenderMode::Shaded);
}

AcneCount count_acne(PreparedScene scene) {
    scene.mode = RenderMode::Shaded;
    const Image unshadowed = render_with_shadows(scene, false);
    const Image shadowed = render_with_shadows(scene, true);
    AcneCount count;
    count.pixels = int(shadowed.pixels.size());
    for (std::size_t i = 0; i < shadowed.pixels.size(); ++i) {
        count.acne += shadowed.pixels[i] != unshadowed.pixels[i];
        count.lit += unshadowed.pixels[i].g > 0.01f;
    }
    return count;
}

void expect_no_acne(const PreparedScene& scene) {
    const AcneCount c = count_acne(scene);
    EXPECT_GT(c.lit, c.pixels / 2) << "the test scene should be mostly lit";
    EXPECT_EQ(c.acne, 0) << c.acne << " of " << c.pixels
                         << " pixels are darker with shadows on: the surface shadows itself";
}

// A slightly tilted plane through `point` (tilted so that no coordinate of its points is exact:
// an axis-aligned plane would hide the rounding error), the camera at `point + eye_offset`, and a
// directional light `elevation_degrees` above the plane.
PreparedScene plane_scene(Vec3 point, Vec3 eye_offset, float elevation_degrees) {
    PreparedScene scene;
    const Vec3 n = glm::normalize(Vec3(0.05f, 1, 0.03f));
    const Vec3 tangent = glm::normalize(glm::cross(Vec3(0, 0, 1), n));
    const Real e = glm::radians(Real(elevation_degrees));
    const Vec3 to_light = std::cos(e) * tangent + std::sin(e) * n;
    scene.camera = make_look_at_camera(Projection::Perspective, point + eye_offset, point,
                                       Vec3(0, 1, 0), 60, 2);
    scene.image = {96, 64};
    scene.max_depth = 0;
    scene.materials = {Material{}};
    scene.planes = {Plane{point, n, 0}};
    scene.lights = {directional_light(-to_light, Color(50))};
    return scene;
}

// A plane 1e4 from the origin: float spacing there is about 1e-3, so a fixed epsilon of 1e-4
// does not get the shadow ray clear of the rounding error of the hit point.
TEST_F(Acne, PlaneFarFromOrigin) {
    expect_no_acne(plane_scene(Vec3(1e4f, 1e4f, -1e4f), Vec3(0, 3, 6), 40));
}

// Light 0.3 degrees above a plane near the origin: a hit point off by d along the normal re-hits
// the plane at t = d / sin(0.3 degrees), about 200 d.
TEST_F(Acne, GrazingLight) {
    expect_no_acne(plane_scene(Vec3(0, -1, 0), Vec3(0, 2, 8), 0.3f));
}

// A sphere far from the origin lit from the side: acne shows up near the terminator.
TEST_F(Acne, SphereFarFromOriginNearTerminator) {
    PreparedScene scene;
    const Vec3 c(-1e4f, 2e3f, 1e4f);
    scene.camera =
        make_look_at_camera(Projection::Perspective, c + Vec3(0, 0, 6), c, Vec3(0, 1, 0), 30, 2);
    scene.image = {64, 64};
    scene.max_depth = 0;
    scene.materials = {Material{}};
    scene.spheres = {Sphere{c, 1, 0}};
    scene.lights = {directional_light(Vec3(-1, 0, -0.3f), Color(50))};
    const int acne = count_acne(scene).acne;
    EXPECT_EQ(acne, 0) << acne << " pixels of a convex sphere shadow themselves";
}

// An opaque slab 1e-5 thick, 1e-5 above the floor, still shades the floor under it: the offset
// is as small as the rounding error allows, not a fixed distance.
TEST_F(Transmittance, ThinOccluderCloseToSurface) {
    PreparedScene scene = floor_scene();
    scene.boxes = {Box{Vec3(-0.5f, 1e-5f, -0.5f), Vec3(0.5f, 2e-5f, 0.5f), 0}};
    const SurfacePoint at = floor_point(scene, 0.2f, 0.1f);
    expect_color_near(
        light_transmittance(scene, at, illuminate(point_light(Vec3(0.2f, 3, 0.1f)), at.point)),
        Color(0), "floor under an opaque slab 1e-5 above it: in shadow (no epsilon of your own)");
    // Beside the slab the floor is lit.
    const SurfacePoint beside = floor_point(scene, 0.7f, 0.1f);
    expect_color_near(
        light_transmittance(scene, beside,
                            illuminate(point_light(Vec3(0.7f, 3, 0.1f)), beside.point)),
        Color(1), "floor beside the thin slab: lit");
}

// Nothing between the point and the light: occluders beyond the light, or below the surface,
// do not count.
TEST_F(Transmittance, OnlyBetweenPointAndLight) {
    PreparedScene scene = floor_scene();
    scene.spheres = {Sphere{Vec3(0, 6, 0), 1, 0}, Sphere{Vec3(0, -3, 0), 1, 0}};
    const SurfacePoint at = floor_point(scene, 0, 0);
    expect_color_near(
        light_transmittance(scene, at, illuminate(point_light(Vec3(0, 4, 0)), at.point)), Color(1),
        "point light at height 4, spheres beyond it and below the floor: lit (t_range ends at "
        "the light)");
    // A directional light has no end: the sphere 6 units up blocks it.
    expect_color_near(
        light_transmittance(scene, at, illuminate(directional_light(Vec3(0, -1, 0)), at.point)),
        Color(0), "directional light from above, sphere 6 up: in shadow (t_range (0, inf))");
}

// Thin-shell shadows: a glass triangle filters once, a glass sphere twice (in and out), and
// several filters multiply.
TEST_F(Transmittance, ColoredShadowsThroughGlass) {
    PreparedScene scene = floor_scene();
    scene.materials.push_back(glass(Color(0.9f, 0.5f, 0.2f)));
    scene.materials.push_back(glass(Color(0.5f, 1, 0.8f)));
    scene.vertices = {Vec3(-1, 1, -1), Vec3(1, 1, -1), Vec3(0, 1, 2)};
    scene.triangles = {Triangle{{0, 1, 2}, 1}};
    const Light light = point_light(Vec3(0, 4, 0));
    SurfacePoint at = floor_point(scene, 0, 0);
    expect_color_near(light_transmittance(scene, at, illuminate(light, at.point)),
                      Color(0.9f, 0.5f, 0.2f), "one glass triangle: k_t once");

    scene.triangles.clear();
    scene.vertices.clear();
    scene.spheres = {Sphere{Vec3(0, 2, 0), 0.5f, 2}};
    at = floor_point(scene, 0, 0);
    expect_color_near(light_transmittance(scene, at, illuminate(light, at.point)),
                      Color(0.25f, 1, 0.64f), "one glass sphere: k_t^2 (in and out)");

    scene.vertices = {Vec3(-1, 1, -1), Vec3(1, 1, -1), Vec3(0, 1, 2)};
    scene.triangles = {Triangle{{0, 1, 2}, 1}};
    at = floor_point(scene, 0, 0);
    expect_color_near(light_transmittance(scene, at, illuminate(light, at.point)),
                      Color(0.9f * 0.25f, 0.5f, 0.2f * 0.64f),
                      "glass triangle and glass sphere: the filters multiply");

    // An opaque box behind the glass (seen from the floor) blocks everything.
    scene.boxes = {Box{Vec3(-0.2f, 3, -0.2f), Vec3(0.2f, 3.2f, 0.2f), 0}};
    at = floor_point(scene, 0, 0);
    expect_color_near(light_transmittance(scene, at, illuminate(light, at.point)), Color(0),
                      "an opaque box behind the glass: blocked");
}

// Shadow rays crossing a glass sphere at oblique angles, through points with no exact
// coordinates: each surface filters once, whatever the rounding of the hit points.
TEST_F(Transmittance, GlassSphereFiltersOncePerSurface) {
    PreparedScene scene = floor_scene();
    scene.materials.push_back(glass(Color(0.5f, 0.8f, 0.9f)));
    const Vec3 center(0.13f, 1.7f, -0.21f);
    const Vec3 light_position(0.37f, 4.1f, 0.29f);
    scene.spheres = {Sphere{center, 0.5f, 1}};
    const Light light = point_light(light_position);
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            // Aim from the light through a point well inside the sphere's silhouette.
            const Vec3 aim = center + Vec3(Real(0.04) * (Real(i) - Real(3.5)), 0,
                                           Real(0.04) * (Real(j) - Real(3.5)));
            const Real s = light_position.y / (light_position.y - aim.y);
            const Vec3 p = light_position + s * (aim - light_position);
            const SurfacePoint at = floor_point(scene, p.x, p.z);
            expect_color_near(light_transmittance(scene, at, illuminate(light, at.point)),
                              Color(0.25f, 0.64f, 0.81f),
                              "floor point (" + std::to_string(p.x) + ", " + std::to_string(p.z) +
                                  ") in the shadow of a glass sphere: k_t^2, each surface once; "
                                  "after a transparent surface continue from offset_ray_origin "
                                  "on its far side, not from the hit point, or the walk hits the "
                                  "same surface again");
        }
    }
}

// Past a transparent surface the walk still ends at the light: an opaque sphere beyond a point
// light casts no shadow through the glass either.
TEST_F(Transmittance, RangeStillEndsAtTheLightPastGlass) {
    PreparedScene scene = floor_scene();
    scene.materials.push_back(glass(Color(0.9f, 0.5f, 0.2f)));
    scene.vertices = {Vec3(-1, 3, -1), Vec3(1, 3, -1), Vec3(0, 3, 2)};
    scene.triangles = {Triangle{{0, 1, 2}, 1}};
    scene.spheres = {Sphere{Vec3(0, 5.5f, 0), 1, 0}};
    const SurfacePoint at = floor_point(scene, 0, 0);
    expect_color_near(
        light_transmittance(scene, at, illuminate(point_light(Vec3(0, 4, 0)), at.point)),
        Color(0.9f, 0.5f, 0.2f),
        "point light at height 4, a glass triangle at height 3 and an opaque sphere beyond the "
        "light (4.5 to 6.5): k_t; after moving the origin past a transparent surface, shorten "
        "t_range.max by the distance moved, so the range still ends at the light");
}

// Two diffuse spheres side by side, materials 0 (left) and 1 (right), seen from the front under
// one point light at the camera; no ambient term, a black background.
PreparedScene two_spheres() {
    PreparedScene scene;
    scene.camera =
        make_look_at_camera(Projection::Perspective, Vec3(0, 0, 6), Vec3(0), Vec3(0, 1, 0), 40, 2);
    scene.image = {64, 32};
    scene.max_depth = 0;
    Material left;
    left.diffuse = Color(0.8f);
    Material right = left;
    scene.materials = {left, right};
    scene.spheres = {Sphere{Vec3(-1.2f, 0, 0), 1, 0}, Sphere{Vec3(1.2f, 0, 0), 1, 1}};
    scene.lights = {point_light(Vec3(0, 0, 6))};
    refresh_features(scene);
    return scene;
}

TEST_F(LightLinking, ALightLinkedToAMaterialLightsOnlyIt) {
    // The light says "only": [material 0]: the framework gives it visibility 0 at the right
    // sphere, and direct_light must leave it out there (stage 03's visibility[light]).
    // With shadows: the left sphere's shadow ray is your light_transmittance's.
    PreparedScene scene = two_spheres();
    scene.lights[0].reach_mask = 1;
    scene.lights[0].reach_rest = false;
    scene.shadows = true;
    refresh_features(scene);
    const Image image = render(scene, RenderMode::Shaded);
    const Color left = image.at(16, 16), right = image.at(48, 16);
    EXPECT_GT(left.g, 0.05f) << "the linked sphere (left) must be lit";
    EXPECT_EQ(right, Color(0))
        << "the right sphere is not linked to the light, which gets visibility 0 there: "
           "direct_light must multiply each light's term by visibility[light]";
}

TEST_F(LightLinking, AShadowlessLightIsNotBlocked) {
    // A small sphere between the light (right of the camera) and the left sphere. With
    // "shadows": false the light is blocked by nothing: the image is the one without shadows,
    // pixel for pixel.
    PreparedScene scene = two_spheres();
    scene.spheres.push_back(Sphere{Vec3(-0.6f, 0.2f, 2), Real(0.4), 1});
    scene.lights[0].position = Vec3(3, 2, 6);
    const Image open = render_with_shadows(scene, false);
    const Image blocked = render_with_shadows(scene, true);
    scene.lights[0].casts_shadows = false;
    const Image lit = render_with_shadows(scene, true);
    EXPECT_NE(blocked.pixels, open.pixels) << "the small sphere should cast a shadow";
    EXPECT_EQ(lit.pixels, open.pixels)
        << "a light with \"shadows\": false is blocked by nothing: the framework gives it "
           "visibility 1 without a shadow ray";
}

}  // namespace
}  // namespace rt
