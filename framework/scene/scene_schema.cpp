#include "scene/scene_schema.h"

namespace rt {

std::vector<std::string> SchemaElement::key_names() const {
    std::vector<std::string> names;
    for (const SchemaKey& key : keys) names.emplace_back(key.name);
    return names;
}

bool SchemaElement::has(std::string_view key) const {
    for (const SchemaKey& k : keys)
        if (key == k.name) return true;
    return false;
}

namespace schema {
namespace {

const SchemaElement* of_type(std::string_view type,
                             const std::vector<const SchemaElement*>& elements) {
    for (const SchemaElement* element : elements)
        if (type == element->type) return element;
    return nullptr;
}

}  // namespace

std::vector<const SchemaElement*> all() {
    return {&kScene,
            &kImage,
            &kRender,
            &kCamera,
            &kFog,
            &kPointLight,
            &kDirectionalLight,
            &kRectangleLight,
            &kSphereLight,
            &kEnvironment,
            &kSky,
            &kCubeFaces,
            &kMaterial,
            &kSphere,
            &kPlane,
            &kTriangle,
            &kBox,
            &kMesh,
            &kCheckerboard,
            &kInstance,
            &kHeightField,
            &kTexture,
            &kTextureSlot,
            &kCheckerTexture,
            &kChecker3dTexture,
            &kMarbleTexture,
            &kObject,
            &kTransformStep,
            &kRotation};
}

const SchemaElement* surface_of_type(std::string_view type) {
    return of_type(type,
                   {&kSphere, &kPlane, &kTriangle, &kBox, &kMesh, &kCheckerboard, &kInstance});
}

const SchemaElement* light_of_type(std::string_view type) {
    return of_type(type, {&kPointLight, &kDirectionalLight, &kRectangleLight, &kSphereLight});
}

}  // namespace schema
}  // namespace rt
