#include "view/view_settings.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <nlohmann/json.hpp>

#include "core/not_implemented.h"
#include "render/prepare.h"
#include "scene/scene_format.h"
#include "scene/scene_loader.h"

namespace rt::view {
namespace {

std::optional<bool> on_off(const std::string& value) {
    if (value == "on" || value == "true" || value == "1") return true;
    if (value == "off" || value == "false" || value == "0") return false;
    return std::nullopt;
}

}  // namespace

bool ViewSettings::operator==(const ViewSettings& o) const {
    const Camera &a = camera, &b = o.camera;
    const bool same_camera =
        a.projection == b.projection && a.eye == b.eye && a.u == b.u && a.v == b.v && a.w == b.w &&
        a.vertical_fov_degrees == b.vertical_fov_degrees && a.view_height == b.view_height;
    return same_camera && mode == o.mode && shadows == o.shadows && max_depth == o.max_depth &&
           accelerator == o.accelerator && texture_lookup == o.texture_lookup && gpu == o.gpu &&
           ambient == o.ambient && diffuse == o.diffuse && specular == o.specular &&
           emissive == o.emissive && reflection == o.reflection && refraction == o.refraction &&
           environment == o.environment && fresnel == o.fresnel;
}

ViewSettings settings_of(const Scene& scene) {
    ViewSettings s;
    s.mode = scene.mode;
    s.shadows = scene.shadows;
    s.max_depth = scene.max_depth;
    s.accelerator = scene.accelerator;
    s.texture_lookup = scene.texture_lookup;
    s.camera = scene.camera;
    s.fresnel = scene.fresnel;
    return s;
}

SceneSource::SceneSource(Scene loaded)
    : initial_(settings_of(loaded)),
      // The copy with a BVH is made the first time a setting asks for one.
      loaded_(prepare_scene(std::move(loaded), {.accelerator = Accelerator::None})) {
    if (initial_.accelerator == Accelerator::None && worth_a_tree(loaded_)) try_tree();
}

// A lecture shows solved stages: a scene of many primitives starts with stage 06's BVH when its
// build_bvh is written. Tried quietly: in a starter tree short of stage 06 it is a stub, and
// the viewer starts without a tree, as the scene file says, with nothing printed.
bool SceneSource::worth_a_tree(const Scene& scene) {
    constexpr std::size_t kFewPrimitives = 16;  // a loop over fewer is as fast as a tree
    return scene.moving_spheres.empty() &&
           scene.spheres.size() + scene.triangles.size() + scene.boxes.size() > kFewPrimitives;
}

void SceneSource::try_tree() {
    QuietStubs quiet;
    PreparedScene scene = prepare_scene(loaded_, {.accelerator = Accelerator::Bvh});
    if (quiet.reached() || !uses_bvh(scene)) return;
    with_bvh_ = std::move(scene);
    initial_.accelerator = Accelerator::Bvh;
}

PreparedScene SceneSource::make(const ViewSettings& settings) {
    const bool bvh = settings.accelerator == Accelerator::Bvh;
    // May fall back to None (an invalid tree).
    if (bvh && !with_bvh_) with_bvh_ = prepare_scene(loaded_, {.accelerator = Accelerator::Bvh});
    PreparedScene scene = bvh ? *with_bvh_ : loaded_;
    scene.mode = settings.mode;
    scene.shadows = settings.shadows;
    scene.max_depth = std::clamp(settings.max_depth, 0, kMaxDepthLimit);
    scene.texture_lookup = settings.texture_lookup;
    scene.camera = settings.camera;
    scene.fresnel = settings.fresnel;
    switch_off_terms(scene, {.ambient = settings.ambient,
                             .diffuse = settings.diffuse,
                             .specular = settings.specular,
                             .emissive = settings.emissive,
                             .reflection = settings.reflection,
                             .refraction = settings.refraction,
                             .environment = settings.environment});
    refresh_features(scene);  // prepare_scene's step 3 again, after the viewer's own changes
    return scene;
}

std::string setting_names() {
    return "mode " + join_render_mode_names("|") + ", shadows on|off, max-depth 0.." +
           std::to_string(kMaxDepthLimit) +
           ", bvh on|off, filter scene|nearest|bilinear, "
           "gpu on|off, "
           "ambient|diffuse|specular|emissive|reflection|refraction|fresnel|environment on|off";
}

std::string set_by_name(ViewSettings& s, const std::string& name, const std::string& value) {
    if (name == "mode") {
        const std::optional<RenderMode> mode = parse_render_mode(value);
        if (!mode) return "mode \"" + value + "\" is not one of " + join_render_mode_names(", ");
        s.mode = *mode;
        return "";
    }
    const std::map<std::string, bool*> switches = {
        {"shadows", &s.shadows},       {"gpu", &s.gpu},
        {"ambient", &s.ambient},       {"diffuse", &s.diffuse},
        {"specular", &s.specular},     {"emissive", &s.emissive},
        {"reflection", &s.reflection}, {"refraction", &s.refraction},
        {"fresnel", &s.fresnel},       {"environment", &s.environment}};
    if (switches.count(name) || name == "bvh") {
        const std::optional<bool> on = on_off(value);
        if (!on) return name + " takes on or off, not \"" + value + "\"";
        if (name == "bvh")
            s.accelerator = *on ? Accelerator::Bvh : Accelerator::None;
        else
            *switches.at(name) = *on;
        return "";
    }
    if (name == "max-depth") {
        char* end = nullptr;
        const long depth = std::strtol(value.c_str(), &end, 10);
        if (value.empty() || *end != '\0' || depth < 0 || depth > kMaxDepthLimit)
            return "max-depth takes a whole number 0.." + std::to_string(kMaxDepthLimit) +
                   ", not \"" + value + "\"";
        s.max_depth = int(depth);
        return "";
    }
    if (name == "filter") {
        const std::optional<TextureLookup> lookup = parse_texture_lookup(value);
        if (!lookup || int(*lookup) > int(TextureLookup::Bilinear))
            return "filter takes scene, nearest or bilinear, not \"" + value + "\"";
        s.texture_lookup = *lookup;
        return "";
    }
    return "unknown setting \"" + name + "\"; settings: " + setting_names();
}

namespace {

// Nine significant digits, which give the float back exactly: written as the double it widens
// to, a float would carry 17 digits of noise.
double tidy(Real value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(value));
    return std::strtod(text, nullptr);
}

nlohmann::json tidy(const Vec3& v) {
    return nlohmann::json::array({tidy(v.x), tidy(v.y), tidy(v.z)});
}

}  // namespace

std::string with_camera(const std::string& scene_text, const std::string& name,
                        const Camera& camera, Real distance) {
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(scene_text);
    } catch (const nlohmann::json::exception&) {
        throw SceneError(name + ": error: not a JSON scene file; run rt fmt " + name +
                         " to see where");
    }
    if (!root.is_object())
        throw SceneError(name + ": error: the top level is not an object; it is not a scene");
    const bool ortho = camera.projection == Projection::Orthographic;
    nlohmann::json c = {{"eye", tidy(camera.eye)},
                        {"look_at", tidy(camera.eye - camera.w * distance)},
                        {"up", tidy(camera.v)}};
    if (ortho) {
        c["projection"] = "orthographic";
        c["view_height"] = tidy(camera.view_height);
    } else {
        c["fov"] = tidy(camera.vertical_fov_degrees);
    }
    root["camera"] = c;
    return canonical_scene_text(root.dump(), name, std::filesystem::path(name).parent_path());
}

}  // namespace rt::view
