// The sections of a scene file (camera, image, render, environment, materials, surfaces, meshes,
// lights), each read into a Scene on top of the typed reader. The readers live in
// scene_settings.cpp, scene_environment.cpp, scene_materials.cpp, scene_surfaces.cpp and
// scene_meshes.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"
#include "scene/obj_loader.h"
#include "scene/procedural_sky.h"
#include "scene/scene.h"
#include "scene/scene_reader.h"

namespace rt::scene_internal {

// Limits against absurd sizes (documented in docs/scene-format.md).
constexpr std::size_t kMaxTriangles = 20'000'000;

class SceneSections : public SceneReader {
  public:
    // Relative mesh paths are resolved against `base_dir`.
    SceneSections(const std::string& text, const std::string& name,
                  const std::filesystem::path& base_dir)
        : SceneReader(text, name), base_dir_(base_dir) {}

    // Parses and reads the whole scene (scene_loader.cpp). Throws SceneError.
    Scene load();

  private:
    // scene_settings.cpp
    void read_image(const json& root);
    void read_render(const json& root);
    void read_sampling(const json& render);
    void read_camera(const json& root);
    void read_lens_and_shutter(const json& camera, Projection projection);
    void read_lights(const json& root);
    void read_light(const json& object, const std::string& pointer);
    void read_area_light(const json& object, const std::string& pointer, AreaLightKind kind);
    void read_light_links(const json& object, const std::string& pointer, Light& light) const;
    // Stage 10, optional: "fog" (after the lights: fog and area lights do not mix).
    void read_fog(const json& root);
    // Fails at the first axis where `max` is below `min` (pointers: the two corners' arrays).
    void check_corners(const Vec3& min, const Vec3& max, const std::string& at_min,
                       const std::string& at_max) const;

    // scene_environment.cpp
    void read_environment(const json& root);
    // The image file named by the string at `pointer` (relative to base_dir_), linear.
    Image read_environment_image(const json& value, const std::string& pointer);
    // "sky": the procedural sky's parameters (scene/procedural_sky.h).
    SkyParameters read_sky(const json& value, const std::string& pointer);
    // The environment's images into the texture table: one of the three is given.
    void read_environment_images(const json* latlong, const json* cube, const json* sky,
                                 const std::string& at);

    // scene_materials.cpp
    void read_materials(const json& root);
    void read_material(const json& object, const std::string& pointer);
    // "material": a name or an index; omitted means material 0.
    int material_of(const json& surface, const std::string& pointer) const;
    // A material name (string) or index (whole number) at `at`.
    int material_ref(const json& value, const std::string& at) const;

    // scene_textures.cpp
    void read_textures(const json& root);
    void read_texture(const json& object, const std::string& pointer);
    const char* color_space_key(const json& object, const std::string& pointer) const;
    // A material's texture slot: a texture name, or {"texture", "scale", "offset"}.
    TextureSlot texture_slot(const json& value, const std::string& pointer);
    // The texture image of `path`, read once however many textures use it; errors at `pointer`.
    int texture_image(const std::filesystem::path& path, const std::string& pointer);
    // A slot for an MTL map (colour, or `data` for normal maps), its texture named `name`.
    TextureSlot mtl_texture_slot(const ObjTextureMap& map, bool data, const std::string& name,
                                 const std::string& pointer);
    // After the materials: which image textures are sRGB-decoded (by file type and use).
    void finish_textures();

    // scene_surfaces.cpp
    void read_surfaces(const json& root);
    void read_surface(const json& s, const std::string& pointer);
    void read_sphere(const json& s, const std::string& pointer);
    void read_plane(const json& s, const std::string& pointer);
    void read_triangle(const json& s, const std::string& pointer);
    void read_box(const json& s, const std::string& pointer);
    void read_checkerboard(const json& s, const std::string& pointer);
    void check_vertex_room(std::size_t more, const std::string& pointer) const;
    void check_triangle_room(std::size_t more, const std::string& pointer) const;

    // scene_meshes.cpp
    void read_mesh(const json& s, const std::string& pointer);
    void read_procedural_mesh(const json& s, const std::string& pointer, Vec3 scale, Vec3 translate,
                              int material);
    void read_heightfield_mesh(const json& h, const std::string& pointer, Vec3 scale,
                               Vec3 translate, int material);
    void read_obj_mesh(const json& file_value, const std::string& file_pointer, Vec3 scale,
                       Vec3 translate, int material);
    template <typename MaterialOf>
    void append_mesh(const std::vector<Vec3>& vertices, const std::vector<Vec3>& normals,
                     const std::vector<Vec2>& uvs,
                     const std::vector<std::array<std::uint32_t, 3>>& triangles,
                     MaterialOf material_of_triangle);
    void pad_shading_data();

    // scene_transforms.cpp
    // How many of each primitive there were before a surface was read.
    struct GeometryMark {
        std::size_t spheres, planes, boxes, vertices, triangles;
    };
    GeometryMark mark_geometry() const;
    glm::dvec3 dvec3(const json& value, const std::string& pointer) const;
    glm::dmat4 read_matrix(const json& rows, const std::string& pointer) const;
    glm::dmat4 read_transform_step(const json& step, const std::string& pointer) const;
    glm::dmat4 read_transform(const json& value, const std::string& pointer) const;
    void place_surface(const glm::dmat4& m, const GeometryMark& mark, const std::string& pointer);
    void add_shape_instance(Scene shape, const glm::dmat4& m, const std::string& pointer);
    void read_instance(const json& s, const std::string& pointer);
    void read_objects(const json& root);

    std::filesystem::path base_dir_;
    std::optional<std::string> reading_object_;  // the object whose surfaces are being read
    Scene scene_;
    std::map<std::string, int> material_ids_;
    std::map<std::string, int> texture_ids_;
    std::map<std::string, int> image_ids_;      // texture images by normalised path, read once
    std::vector<int> texture_color_space_;      // per texture: -1 unsaid, 0 linear, 1 sRGB
    std::vector<bool> texture_float_file_;      // per texture: reads an EXR or HDR file
    std::vector<std::string> texture_pointer_;  // per texture: where errors about it point
    std::map<int, ImageInfo> image_info_;       // by texture image index: channels, float or not
};

}  // namespace rt::scene_internal
