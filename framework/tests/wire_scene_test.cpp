// The judge/worker wire format of scenes (remote/wire_types.h) refuses what a hostile worker could
// send to crash the judge: objects nested inside objects (a decoder that recursed without bound),
// a null object, an instance of an object the scene lacks, a prepared scene whose instanced
// objects are not prepared. A well-formed prepared scene with an instance reads back.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "remote/wire.h"
#include "remote/wire_types.h"
#include "scene/prepared_scene.h"
#include "scene/transform.h"

namespace rt {
namespace {

// A scene with one instance of one object holding a sphere, prepared (its object too).
PreparedScene instanced() {
    Scene object;
    object.spheres.push_back(Sphere{});
    PreparedScene scene;
    scene.objects.push_back(std::make_shared<const Scene>(object));
    scene.instances.push_back(make_instance(glm::dmat4(1), 0, -1));
    auto prepared = std::make_shared<PreparedScene>();
    static_cast<Scene&>(*prepared) = object;
    scene.prepared_objects.push_back(prepared);
    return scene;
}

// Whether `scene` survives a trip through the wire.
bool reads_back(const PreparedScene& scene) {
    remote::Writer w;
    remote::put(w, scene);
    remote::Reader r(w.data());
    PreparedScene decoded;
    remote::get(r, decoded);
    return r.ok();
}

TEST(WireScene, AnInstancedSceneReadsBack) {
    EXPECT_TRUE(reads_back(instanced()));
}

TEST(WireScene, AnObjectInsideAnObjectIsRefused) {
    PreparedScene scene = instanced();
    Scene nested = *scene.objects[0];
    nested.objects.push_back(std::make_shared<const Scene>(Scene{}));
    scene.objects[0] = std::make_shared<const Scene>(nested);
    EXPECT_FALSE(reads_back(scene));
}

TEST(WireScene, ANullObjectIsRefused) {
    PreparedScene scene = instanced();
    scene.objects[0] = nullptr;
    EXPECT_FALSE(reads_back(scene));
}

TEST(WireScene, AnInstanceOfAMissingObjectIsRefused) {
    PreparedScene scene = instanced();
    scene.instances[0].object = 5;
    EXPECT_FALSE(reads_back(scene));
}

TEST(WireScene, UnpreparedObjectsAreRefused) {
    PreparedScene scene = instanced();
    scene.prepared_objects.clear();
    EXPECT_FALSE(reads_back(scene));
}

}  // namespace
}  // namespace rt
