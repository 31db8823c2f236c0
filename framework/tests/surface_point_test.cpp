// The surface point. (The background hook, which calls stage 08 code, is tested in
// stages/08-environment/tests/radiance_test.cpp.)
#include <gtest/gtest.h>

#include "scene/scene.h"
#include "scene/surface_point.h"

namespace rt {
namespace {

TEST(SurfacePoint, TexcoordIsLeftToTheTexturingStep) {
    // surface_point calls no stage 07 code: a scene without textures never needs it.
    Scene scene;
    scene.spheres.push_back(Sphere{Vec3(0), 1, 0});
    Hit hit;
    hit.t = 1;
    hit.point = Vec3(0, 0, 1);
    hit.normal = Vec3(0, 0, 1);
    hit.primitive = scene.primitive_id(Scene::Kind::Sphere, 0);
    hit.uv = Vec2(0.25f, 0.5f);
    EXPECT_EQ(surface_point(scene, Ray{Vec3(0, 0, 2), Vec3(0, 0, -1)}, hit).texcoord, Vec2(0));
}

}  // namespace
}  // namespace rt
