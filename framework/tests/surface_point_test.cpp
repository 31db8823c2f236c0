// The surface point's texture coordinates (stage 07's input): distinct from Hit::uv.
#include <gtest/gtest.h>

#include "geometry/offset.h"
#include "scene/scene.h"

namespace rt {
namespace {

TEST(SurfacePoint, SphereTexcoordIsItsAngles) {
    Scene scene;
    scene.spheres.push_back(Sphere{Vec3(0), 1, 0});
    Hit hit;
    hit.t = 1, hit.point = Vec3(0, 0, 1), hit.normal = Vec3(0, 0, 1);
    hit.primitive = scene.primitive_id(Scene::Kind::Sphere, 0);
    hit.uv = Vec2(0.25f, 0.5f);  // what stage 02 computes: longitude, latitude
    const SurfacePoint at = surface_point(scene, Ray{Vec3(0, 0, 2), Vec3(0, 0, -1)}, hit);
    EXPECT_EQ(at.texcoord, Vec2(0.25f, 0.5f));
}

TEST(SurfacePoint, TriangleTexcoordInterpolatesVertexUvsNotBarycentrics) {
    Scene scene;
    scene.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    scene.uvs = {Vec2(0.5f, 0.5f), Vec2(1, 0.5f), Vec2(0.5f, 1)};
    scene.triangles.push_back(Triangle{{0, 1, 2}, 0});
    Hit hit;
    hit.t = 1, hit.point = Vec3(0.25f, 0.5f, 0), hit.normal = Vec3(0, 0, 1);
    hit.primitive = scene.primitive_id(Scene::Kind::Triangle, 0);
    hit.uv = Vec2(0.25f, 0.5f);  // barycentrics of b and c
    const SurfacePoint at = surface_point(scene, Ray{Vec3(0.25f, 0.5f, 1), Vec3(0, 0, -1)}, hit);
    EXPECT_NEAR(at.texcoord.x, 0.5f + 0.25f * 0.5f, 1e-6f);
    EXPECT_NEAR(at.texcoord.y, 0.5f + 0.5f * 0.5f, 1e-6f);
    scene.uvs.clear();  // a mesh without uvs: (0, 0) until stage 07 says otherwise
    EXPECT_EQ(surface_point(scene, Ray{Vec3(0.25f, 0.5f, 1), Vec3(0, 0, -1)}, hit).texcoord,
              Vec2(0));
}

TEST(Background, IsTheScenesColourInEveryDirection) {
    Scene scene;
    scene.background = Color(0.1f, 0.2f, 0.3f);
    EXPECT_EQ(background(scene, Vec3(0, 0, -1)), scene.background);
    EXPECT_EQ(background(scene, Vec3(5, 1, 0)), scene.background);
}

}  // namespace
}  // namespace rt
