// Stage 07 tests: the texture coordinates of each primitive (docs/conventions.md#textures),
// checked at points whose (u, v) the conventions fix, and through the framework's texturing
// step on real hits.
#include <cmath>

#include "render/prepare.h"
#include "render/texturing.h"
#include "stage_api/stage07.h"
#include "testing/expect_near.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

RT_TEST_SUITE(SphereTexcoord, "spheres");
RT_TEST_SUITE(PlaneTexcoord, "planes");
RT_TEST_SUITE(BoxTexcoord, "boxes");
RT_TEST_SUITE(TriangleTexcoord, "triangles");

constexpr Real kTol = Real(1e-5);

void expect_uv(Vec2 got, Vec2 want, const char* what) {
    EXPECT_NEAR(got.x, want.x, kTol) << what << ": u";
    EXPECT_NEAR(got.y, want.y, kTol) << what << ": v";
}

TEST_F(SphereTexcoord, AxesAndPoles) {
    expect_uv(sphere_texcoord(Vec3(1, 0, 0)), Vec2(0, 0.5f), "+x: u = 0 on the equator");
    expect_uv(sphere_texcoord(Vec3(0, 0, -1)), Vec2(0.25f, 0.5f), "-z: u = 0.25");
    expect_uv(sphere_texcoord(Vec3(-1, 0, 0)), Vec2(0.5f, 0.5f), "-x: u = 0.5");
    expect_uv(sphere_texcoord(Vec3(0, 0, 1)), Vec2(0.75f, 0.5f), "+z: u = 0.75 (faces the camera)");
    EXPECT_NEAR(sphere_texcoord(Vec3(0, 1, 0)).y, 0, kTol) << "north pole: v = 0 (image top)";
    EXPECT_NEAR(sphere_texcoord(Vec3(0, -1, 0)).y, 1, kTol) << "south pole: v = 1";
}

TEST_F(SphereTexcoord, LatitudeAndRange) {
    const Real s = std::sqrt(Real(0.5));
    EXPECT_NEAR(sphere_texcoord(Vec3(s, s, 0)).y, 0.25f, kTol) << "45 degrees north: v = 0.25";
    // Slightly past +x towards +z the longitude is just below 1, never negative.
    const Vec2 uv = sphere_texcoord(glm::normalize(Vec3(1, 0, Real(1e-3))));
    EXPECT_GT(uv.x, 0.99f);
    EXPECT_LE(uv.x, 1.0f);
    // y a little over 1 (rounding of a normalised vector) is clamped, not NaN.
    const Vec2 top = sphere_texcoord(Vec3(0, Real(1.0000001), 0));
    EXPECT_FALSE(std::isnan(top.x) || std::isnan(top.y)) << "y just above 1 must be clamped";
}

TEST_F(SphereTexcoord, GrowsLeftToRightSeenFromOutside) {
    // Seen from +z, moving right (+x) across the front must increase u.
    const Vec2 left = sphere_texcoord(glm::normalize(Vec3(-0.1f, 0, 1)));
    const Vec2 right = sphere_texcoord(glm::normalize(Vec3(0.1f, 0, 1)));
    EXPECT_LT(left.x, right.x) << "u must grow to the right, as on a globe";
}

TEST_F(PlaneTexcoord, FloorFrame) {
    const Plane floor{Vec3(1, -1, 2), Vec3(0, 1, 0), 0};
    expect_uv(plane_texcoord(floor, Vec3(1, -1, 2)), Vec2(0, 0), "plane.point is (0, 0)");
    expect_uv(plane_texcoord(floor, Vec3(3, -1, 2)), Vec2(2, 0), "u along +x in world units");
    expect_uv(plane_texcoord(floor, Vec3(1, -1, 5)), Vec2(0, 3), "v along +z (towards the camera)");
    expect_uv(plane_texcoord(floor, Vec3(0, -1, 1)), Vec2(-1, -1), "negative on the other side");
}

TEST_F(PlaneTexcoord, WallIsUpright) {
    const Plane wall{Vec3(0, 0, -3), Vec3(0, 0, 1), 0};  // facing the camera
    expect_uv(plane_texcoord(wall, Vec3(1, 0, -3)), Vec2(1, 0), "u along +x");
    expect_uv(plane_texcoord(wall, Vec3(0, 1, -3)), Vec2(0, -1), "v grows downwards");
    // A wall facing +x, seen from +x: its right is -z.
    const Plane side{Vec3(0), Vec3(1, 0, 0), 0};
    expect_uv(plane_texcoord(side, Vec3(0, 0, -1)), Vec2(1, 0), "facing +x: u to the right (-z)");
    expect_uv(plane_texcoord(side, Vec3(0, 1, 0)), Vec2(0, -1), "facing +x: v downwards");
    const Plane tilted{Vec3(0), glm::normalize(Vec3(1, 2, 3)), 0};
    const PlaneFrame f = plane_frame(tilted.normal);
    const Vec3 p = Real(0.5) * f.t - Real(2) * f.b;
    expect_uv(plane_texcoord(tilted, p), Vec2(0.5f, -2), "any normal: the frame's coordinates");
}

TEST_F(BoxTexcoord, EachFaceSpansTheImageUpright) {
    const Box box{Vec3(-1, 0, -2), Vec3(3, 2, 2), 0};  // 4 x 2 x 4
    // Front face (+z): u along +x over 4 units, v downwards over 2.
    expect_uv(box_texcoord(box, Vec3(1, 1, 2), Vec3(0, 0, 1)), Vec2(0.5f, 0.5f), "+z centre");
    expect_uv(box_texcoord(box, Vec3(-1, 2, 2), Vec3(0, 0, 1)), Vec2(0, 0), "+z top-left corner");
    expect_uv(box_texcoord(box, Vec3(3, 0, 2), Vec3(0, 0, 1)), Vec2(1, 1), "+z bottom-right");
    // The other side faces, each upright as seen from outside: top-left corner (0, 0).
    expect_uv(box_texcoord(box, Vec3(3, 2, 2), Vec3(1, 0, 0)), Vec2(0, 0), "+x top-left corner");
    expect_uv(box_texcoord(box, Vec3(3, 0, -2), Vec3(1, 0, 0)), Vec2(1, 1), "+x bottom-right");
    expect_uv(box_texcoord(box, Vec3(-1, 2, -2), Vec3(-1, 0, 0)), Vec2(0, 0), "-x top-left");
    expect_uv(box_texcoord(box, Vec3(3, 2, -2), Vec3(0, 0, -1)), Vec2(0, 0), "-z top-left");
    // Top face (+y): u along +x, v along +z (as a floor).
    expect_uv(box_texcoord(box, Vec3(-1, 2, -2), Vec3(0, 1, 0)), Vec2(0, 0), "+y far-left corner");
    expect_uv(box_texcoord(box, Vec3(3, 2, 2), Vec3(0, 1, 0)), Vec2(1, 1), "+y near-right corner");
    // Every face: the centre at (0.5, 0.5), the range [0, 1].
    const Vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const Vec3& n : normals) {
        const Vec3 center = Vec3(1, 1, 0) + n * Vec3(2, 1, 2);
        expect_uv(box_texcoord(box, center, n), Vec2(0.5f, 0.5f), "face centre");
    }
}

TEST_F(TriangleTexcoord, InterpolatesVertexUvs) {
    const Vec2 a(0.1f, 0.2f), b(0.9f, 0.2f), c(0.1f, 0.8f);
    expect_uv(triangle_texcoord(a, b, c, Vec2(0, 0)), a, "barycentrics (0, 0): vertex a");
    expect_uv(triangle_texcoord(a, b, c, Vec2(1, 0)), b, "beta = 1: vertex b");
    expect_uv(triangle_texcoord(a, b, c, Vec2(0, 1)), c, "gamma = 1: vertex c");
    expect_uv(triangle_texcoord(a, b, c, Vec2(0.25f, 0.5f)), Vec2(0.3f, 0.5f), "interior");
}

TEST_F(TriangleTexcoord, TheTexturingStepUsesVertexUvsNotBarycentrics) {
    PreparedScene scene;
    scene.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    scene.uvs = {Vec2(0.5f, 0.5f), Vec2(1, 0.5f), Vec2(0.5f, 1)};
    scene.triangles.push_back(Triangle{{0, 1, 2}, 0});
    Hit hit;
    hit.primitive = Scene::primitive_id(Scene::Kind::Triangle, 0);
    hit.uv = Vec2(0.25f, 0.5f);
    SurfacePoint at;
    at.point = Vec3(0.25f, 0.5f, 0);
    at.normal = Vec3(0, 0, 1);
    expect_uv(surface_texcoord(scene, hit, at), Vec2(0.625f, 0.75f), "vertex uvs interpolated");
    scene.uvs.clear();  // no uvs anywhere: corners (0, 0), (1, 0), (0, 1)
    expect_uv(surface_texcoord(scene, hit, at), Vec2(0.25f, 0.5f), "default corners");
}

}  // namespace
}  // namespace rt
