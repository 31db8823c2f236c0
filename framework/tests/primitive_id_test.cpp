// Global primitive ids (docs/conventions.md#primitive-ids): the kind in the top bits, so ids do
// not depend on how many surfaces of other kinds a scene has.
#include <gtest/gtest.h>

#include "scene/scene.h"

namespace rt {
namespace {

TEST(PrimitiveIds, DoNotDependOnOtherKinds) {
    Scene few, many;
    few.triangles.resize(3);
    many.triangles.resize(3);
    many.spheres.resize(5);
    many.planes.resize(2);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(few.primitive_id(Scene::Kind::Triangle, i),
                  many.primitive_id(Scene::Kind::Triangle, i));
}

TEST(PrimitiveIds, RoundTripEveryKind) {
    for (Scene::Kind kind :
         {Scene::Kind::Sphere, Scene::Kind::Plane, Scene::Kind::Triangle, Scene::Kind::Box})
        for (std::size_t index : {std::size_t(0), std::size_t(1), std::size_t(19'999'999)}) {
            const int id = Scene::primitive_id(kind, index);
            EXPECT_GE(id, 0);
            std::size_t back = 99;
            EXPECT_EQ(Scene::primitive_kind(id, back), kind);
            EXPECT_EQ(back, index);
        }
    EXPECT_EQ(Scene::primitive_id(Scene::Kind::Box, 7) >> Scene::kKindShift, 3)
        << "GLSL decodes so";
}

TEST(PrimitiveIds, ValidityAndRank) {
    Scene scene;
    scene.spheres.resize(2);
    scene.planes.resize(1);
    scene.boxes.resize(4);
    EXPECT_TRUE(scene.is_primitive(Scene::primitive_id(Scene::Kind::Box, 3)));
    EXPECT_FALSE(scene.is_primitive(Scene::primitive_id(Scene::Kind::Box, 4)));
    EXPECT_FALSE(scene.is_primitive(Scene::primitive_id(Scene::Kind::Triangle, 0)));
    EXPECT_FALSE(scene.is_primitive(-1));
    EXPECT_FALSE(scene.is_primitive(7 << Scene::kKindShift)) << "an unknown kind";
    // The rank lists spheres, planes, triangles, boxes: what the primitive-id view colours.
    EXPECT_EQ(scene.primitive_rank(Scene::primitive_id(Scene::Kind::Sphere, 1)), 1u);
    EXPECT_EQ(scene.primitive_rank(Scene::primitive_id(Scene::Kind::Plane, 0)), 2u);
    EXPECT_EQ(scene.primitive_rank(Scene::primitive_id(Scene::Kind::Box, 2)), 5u);
}

}  // namespace
}  // namespace rt
