#include "render/prepare.h"

#include <iterator>

#include "camera/camera_moves.h"
#include "render/oiio_textures.h"

namespace rt {
namespace {

void apply_overrides(Scene& scene, const SceneOverrides& o) {
    if (o.width > 0) scene.image.width = o.width;
    if (o.height > 0) scene.image.height = o.height;
    if (o.yaw_degrees != 0) turn_camera(scene.camera, o.yaw_degrees);
    if (o.accelerator) scene.accelerator = *o.accelerator;
    if (o.texture_lookup) scene.texture_lookup = *o.texture_lookup;
    if (o.shadows) scene.shadows = *o.shadows;
    if (o.max_depth && *o.max_depth >= 0) scene.max_depth = *o.max_depth;
    if (o.samples_per_pixel && *o.samples_per_pixel > 0)
        scene.sampling.samples_per_pixel = *o.samples_per_pixel;
    if (o.seed) scene.sampling.seed = *o.seed;
    if (o.fresnel) scene.fresnel = *o.fresnel;
    switch_off_terms(scene, o.terms);
}

}  // namespace

bool* term_switch(TermSwitches& s, const std::string& name) {
    bool* const switches[] = {&s.ambient,    &s.diffuse,    &s.specular,   &s.emissive,
                              &s.reflection, &s.refraction, &s.environment};
    for (std::size_t i = 0; i < std::size(kTermNames); ++i)
        if (name == kTermNames[i]) return switches[i];
    return nullptr;
}

void switch_off_terms(Scene& scene, const TermSwitches& on) {
    for (Material& m : scene.materials) {
        if (!on.ambient) m.ambient = Color(0);
        if (!on.diffuse) m.diffuse = Color(0);
        if (!on.specular) m.specular = Color(0);
        if (!on.emissive) m.emissive = Color(0);
        if (!on.reflection) m.reflective = Color(0);
        if (!on.refraction) m.transmissive = Color(0);
    }
    if (!on.environment) scene.environment.kind = EnvironmentKind::None;
}

void load_texture_system(PreparedScene& scene) {
    // OpenImageIO's TextureSystem (and the plug-in) are loaded only when asked for, once.
    const TextureLookup lookup = scene.texture_lookup;
    if ((lookup == TextureLookup::Oiio || lookup == TextureLookup::OiioAniso) &&
        !scene.oiio_textures)
        use_oiio_textures(scene, lookup == TextureLookup::OiioAniso);
}

PreparedScene prepare_scene(Scene description, const SceneOverrides& overrides,
                            const BvhBuildOptions& bvh_options, AccelerationReport* acceleration) {
    apply_overrides(description, overrides);
    PreparedScene scene{std::move(description), {}, {}, {}, {}};
    load_texture_system(scene);
    refresh_features(scene);
    const AccelerationReport report = build_acceleration(scene, bvh_options);
    if (acceleration) *acceleration = report;
    return scene;
}

}  // namespace rt
