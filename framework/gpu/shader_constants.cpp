#include "gpu/shader_constants.h"

#include <initializer_list>
#include <utility>

#include "accel/bvh.h"
#include "gpu/gpu_scene.h"
#include "scene/environment.h"
#include "scene/scene.h"
#include "scene/texture.h"

namespace rt::gpu {
namespace {

using Named = std::pair<const char*, int>;

// "const int a = 1, b = 2;\n"
std::string constants(std::initializer_list<Named> list) {
    std::string line = "const int ";
    bool first = true;
    for (const auto& [name, value] : list) {
        line += (first ? "" : ", ") + std::string(name) + " = " + std::to_string(value);
        first = false;
    }
    return line + ";\n";
}

template <typename E>
Named named(const char* name, E value) {
    return {name, int(value)};
}

std::string bindings() {
    std::string text;
    for (const auto& [name, value] :
         {named("SPHERES", kSpheres), named("PLANES", kPlanes), named("BOXES", kBoxes),
          named("TRIANGLES", kTriangles), named("POSITIONS", kPositions),
          named("NORMALS", kNormals), named("UVS", kUvs), named("MATERIALS", kMaterials),
          named("LIGHTS", kLights), named("BVH_NODES", kBvhNodes),
          named("BVH_PRIMITIVES", kBvhPrimitives), named("TEXTURES", kTextures),
          named("TEXTURE_IMAGES", kTextureImages), named("TEXELS", kTexels),
          named("ENVIRONMENT", kEnvironment), named("OUTPUT", kOutputBinding),
          named("SAMPLED_SCENE", kSampledSceneBinding)})
        text += "#define RT_BINDING_" + std::string(name) + " " + std::to_string(value) + "\n";
    return text;
}

}  // namespace

std::string shader_prelude() {
    using K = Scene::Kind;
    return "// Shared with the C++ host: framework/gpu/shader_constants.cpp writes these.\n" +
           constants({named("kSphere", K::Sphere), named("kPlane", K::Plane),
                      named("kTriangle", K::Triangle), named("kBox", K::Box),
                      named("kKindShift", Scene::kKindShift)}) +
           constants({named("kFeatureBvh", kFeatureBvh), named("kFeatureShadows", kFeatureShadows),
                      named("kFeatureVertexNormals", kFeatureVertexNormals),
                      named("kFeatureVertexUvs", kFeatureVertexUvs),
                      named("kFeatureRefraction", kFeatureRefraction),
                      named("kFeatureSampled", kFeatureSampled),
                      named("kFeatureAreaLights", kFeatureAreaLights),
                      named("kFeatureDepthOfField", kFeatureDepthOfField),
                      named("kFeatureGlossy", kFeatureGlossy),
                      named("kFeatureOcclusion", kFeatureOcclusion),
                      named("kFeatureIndirect", kFeatureIndirect),
                      named("kFeaturePathTracing", kFeaturePathTracing)}) +
           constants({named("kModeDirections", RenderMode::Directions),
                      named("kModeNormals", RenderMode::Normals),
                      named("kModeDepth", RenderMode::Depth),
                      named("kModePrimitiveId", RenderMode::PrimitiveId),
                      named("kModeShaded", RenderMode::Shaded),
                      named("kModeBvhVisits", RenderMode::BvhVisits)}) +
           constants({named("kLookupPerTexture", kLookupPerTexture),
                      named("kLookupNearest", kLookupNearest),
                      named("kLookupBilinear", kLookupBilinear)}) +
           constants({named("kTextureImage", TextureKind::Image),
                      named("kTextureChecker2D", TextureKind::Checker2D),
                      named("kTextureChecker3D", TextureKind::Checker3D),
                      named("kTextureMarble", TextureKind::Marble),
                      named("kFilterNearest", TextureFilter::Nearest),
                      named("kFilterBilinear", TextureFilter::Bilinear),
                      named("kWrapRepeat", TextureWrap::Repeat),
                      named("kWrapClamp", TextureWrap::Clamp),
                      named("kWrapMirror", TextureWrap::Mirror)}) +
           constants({named("kEnvironmentNone", EnvironmentKind::None),
                      named("kEnvironmentLatLong", EnvironmentKind::LatLong),
                      named("kEnvironmentCubeMap", EnvironmentKind::CubeMap)}) +
           constants({named("kProjectionPerspective", Projection::Perspective),
                      named("kProjectionOrthographic", Projection::Orthographic),
                      named("kLightPoint", LightKind::Point),
                      named("kLightDirectional", LightKind::Directional),
                      named("kLightReachRest", kLightReachRest),
                      named("kLightCastsShadows", kLightCastsShadows),
                      named("kLinkedMaterials", kLinkedMaterials),
                      named("kPixelFilterBox", PixelFilter::Box),
                      named("kPixelFilterTent", PixelFilter::Tent)}) +
           constants({named("kDebugValue", kDebugValue), named("kDebugRay", kDebugRay),
                      named("kDebugDirection", kDebugDirection), named("kDebugHit", kDebugHit),
                      named("kDebugPoint", kDebugPoint), named("kDebugNormal", kDebugNormal),
                      named("kDebugMiss", kDebugMiss), named("kDebugShadow", kDebugShadow),
                      named("kDebugLocal", kDebugLocal), named("kDebugReflected", kDebugReflected),
                      named("kDebugRefracted", kDebugRefracted), named("kDebugPixel", kDebugPixel),
                      named("kDebugSample", kDebugSample), named("kDebugCapacity", kDebugCapacity),
                      named("kLoopLimit", kLoopLimit)}) +
           constants(
               {named("kBvhMaxDepth", kBvhMaxDepth), named("kMaxDepthLimit", kMaxDepthLimit)}) +
           constants({named("kTermAmbient", kTermAmbient), named("kTermDiffuse", kTermDiffuse),
                      named("kTermSpecular", kTermSpecular), named("kTermEmissive", kTermEmissive),
                      named("kTermReflection", kTermReflection),
                      named("kTermRefraction", kTermRefraction),
                      named("kTermEnvironment", kTermEnvironment)}) +
           bindings();
}

}  // namespace rt::gpu
