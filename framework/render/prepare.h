// A loaded scene made ready to render, in one place for every program: `rt render`, `rt info`,
// `rt gallery`, `rt export-shadertoy`, the image tests and the benchmarks.
//
// load_scene (scene/scene_loader.h) gives the description as the file says it (a Scene).
// prepare_scene makes the PreparedScene everything renders (scene/prepared_scene.h), in order:
//   1. applies the overrides to the description (a command line's options, the grader's unseen
//      views);
//   2. loads OpenImageIO's texture system when the texture lookup asks for it;
//   3. works out what the renderer must model (scene_features), after the overrides, which can
//      switch shadows, bounces or samples;
//   4. builds stage 06's BVH when the scene asks for one (build_acceleration).
// The viewer keeps its own copies of a scene (view/view_settings.h) but makes each through this
// function too.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "render/accelerate.h"
#include "scene/prepared_scene.h"

namespace rt {

// The viewer's switches of stage 03's terms and the effects of stages 05 and 08 (rt view's panel,
// rt render --off, rt export-web's page): a term off is a coefficient of zero in every material
// (texture maps multiply it, so they go too), the environment off is none; prepare_scene's step 3
// then leaves it out of what the renderer computes. All on changes nothing.
struct TermSwitches {
    bool ambient = true, diffuse = true, specular = true, emissive = true;
    bool reflection = true, refraction = true, environment = true;
};

// Their names, as --off and the page spell them, in this order.
inline constexpr const char* kTermNames[] = {"ambient",    "diffuse",    "specular",   "emissive",
                                             "reflection", "refraction", "environment"};
// The switch of that name (one of kTermNames), or nullptr.
bool* term_switch(TermSwitches& switches, const std::string& name);

// Zeroes what `switches` has off in `scene` (the description or a prepared copy; a prepared
// copy then needs refresh_features).
void switch_off_terms(Scene& scene, const TermSwitches& switches);

struct SceneOverrides {
    int width = 0, height = 0;  // > 0: the image size instead of the scene's
    double yaw_degrees = 0;     // turns the camera about its up axis (camera/camera_moves.h)
    std::optional<Accelerator> accelerator{};
    // For every image texture; Oiio and OiioAniso load OpenImageIO's plug-in.
    std::optional<TextureLookup> texture_lookup{};
    std::optional<bool> shadows{};
    std::optional<int> max_depth{};          // >= 0
    std::optional<int> samples_per_pixel{};  // > 0 (stage 10)
    std::optional<std::uint64_t> seed{};     // stage 10
    TermSwitches terms{};                    // the viewer's switches (all on: none)
    std::optional<bool> fresnel{};
};

// Step 2 alone, for a scene that arrives prepared (the grading worker's, framework/remote/):
// OpenImageIO's texture system when the scene's lookup asks for it and it is not loaded yet.
void load_texture_system(PreparedScene& scene);

// Steps 1-4 above. `acceleration`, when given, receives step 4's report. Throws
// std::runtime_error when OpenImageIO's plug-in cannot be loaded.
PreparedScene prepare_scene(Scene description, const SceneOverrides& overrides = {},
                            const BvhBuildOptions& bvh_options = {},
                            AccelerationReport* acceleration = nullptr);

}  // namespace rt
