// The scene format's schema: one table per element of a scene file, defined beside the reader of
// that element (the comment on each declaration below says where). A table lists the keys the
// element takes, in the order `rt fmt` writes them, and which of them are required. The readers
// refuse any other key through it (SceneReader::check_keys), `rt fmt` orders keys by it
// (scene_format.cpp), and Framework.SceneSchema.* check docs/scene-format.md against it, so a
// key is added in one table and the test names the documentation it still lacks.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rt {

struct SchemaKey {
    const char* name;
    bool required = false;
};
inline constexpr bool kRequired = true;  // {"density", kRequired}: the element needs the key

struct SchemaElement {
    const char* what;  // as messages name it: "\"camera\"", "a material", "a sphere"
    const char* type;  // the value of its "type" key (surfaces, lights), else ""
    std::vector<std::string> doc_sections;  // the headings of docs/scene-format.md that document it
    std::vector<SchemaKey> keys;

    std::vector<std::string> key_names() const;
    bool has(std::string_view key) const;
};

namespace schema {

// Defined in scene_loader.cpp.
extern const SchemaElement kScene;
// Defined in scene_settings.cpp.
extern const SchemaElement kImage, kRender, kCamera, kFog;
extern const SchemaElement kPointLight, kDirectionalLight, kRectangleLight, kSphereLight;
// Defined in scene_environment.cpp.
extern const SchemaElement kEnvironment, kSky, kCubeFaces;
// Defined in scene_materials.cpp.
extern const SchemaElement kMaterial;
// Defined in scene_surfaces.cpp.
extern const SchemaElement kSphere, kPlane, kTriangle, kBox, kMesh, kCheckerboard, kInstance;
// Defined in scene_meshes.cpp.
extern const SchemaElement kHeightField;
// Defined in scene_textures.cpp.
extern const SchemaElement kTexture, kTextureSlot, kCheckerTexture, kChecker3dTexture,
    kMarbleTexture;
// Defined in scene_transforms.cpp.
extern const SchemaElement kObject, kTransformStep, kRotation;

// Every element above, for `rt fmt` and the documentation test.
std::vector<const SchemaElement*> all();
// The surface or light element whose "type" is `type`, or nullptr.
const SchemaElement* surface_of_type(std::string_view type);
const SchemaElement* light_of_type(std::string_view type);

}  // namespace schema
}  // namespace rt
