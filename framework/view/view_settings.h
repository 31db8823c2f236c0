// What the viewer's panel changes: settings that change what the renderer computes (never a
// post-process), applied to a copy of the loaded scene, and the camera controls.
#pragma once

#include <optional>
#include <string>

#include "scene/prepared_scene.h"

namespace rt::view {

struct ViewSettings {
    RenderMode mode = RenderMode::Shaded;
    bool shadows = false;
    int max_depth = 5;
    Accelerator accelerator = Accelerator::None;
    TextureLookup texture_lookup = TextureLookup::PerTexture;
    Camera camera;
    bool gpu = false;  // stage 09's compute shader renders (the renderer's choice, not the scene's)
    // Terms and effects, switched off in the scene copy itself (a material coefficient zeroed, the
    // environment dropped), so the renderer computes less rather than hiding a result.
    bool ambient = true, diffuse = true, specular = true, emissive = true;
    bool reflection = true, refraction = true, environment = true;
    bool fresnel = false;  // as the scene file says, until changed

    bool operator==(const ViewSettings& other) const;  // Camera has no ==: field by field
};

// The settings the scene file asks for.
ViewSettings settings_of(const Scene& scene);

// Keeps the loaded scene prepared, once without and (when first asked for) once with its BVH,
// and makes the scene a setting describes: a copy with the setting's fields and its features
// worked out again (refresh_features), exactly what `rt render` does with the same flags.
class SceneSource {
  public:
    explicit SceneSource(Scene loaded);
    // The scene file's settings, with the BVH on for a big scene when stage 06 is written.
    const ViewSettings& initial() const { return initial_; }
    PreparedScene make(const ViewSettings& settings);

  private:
    static bool worth_a_tree(const Scene& scene);
    void try_tree();

    ViewSettings initial_;
    PreparedScene loaded_;                   // without a BVH
    std::optional<PreparedScene> with_bvh_;  // loaded_ with its BVH built
};

// Sets one setting by name, as scripts and tests write it: "mode shaded", "shadows off",
// "max-depth 2", "bvh on", "filter nearest". Returns an error (empty when it worked) that names
// the accepted values.
std::string set_by_name(ViewSettings& settings, const std::string& name, const std::string& value);

// The names of set_by_name, for messages.
std::string setting_names();

// `scene_text` (a scene file) with its "camera" replaced by `camera` (look_at the pivot
// `distance` in front of the eye, up the camera's v), in rt fmt's canonical form; everything
// else is kept. Throws SceneError when the text is not a scene (naming `name`).
std::string with_camera(const std::string& scene_text, const std::string& name,
                        const Camera& camera, Real distance);

}  // namespace rt::view
