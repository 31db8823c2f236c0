// The scene's settings: "image", "render", "camera" and "lights" (docs/scene-format.md).
#include "scene/scene_sections.h"

#include <cmath>

#include "scene/message_text.h"

namespace rt::schema {
const SchemaElement kImage{"\"image\"", "", {"Top level"}, {{"width"}, {"height"}}};
const SchemaElement kRender{"\"render\"",
                            "",
                            {"Render", "Sampling"},
                            {{"mode"},
                             {"max_depth"},
                             {"shadows"},
                             {"fresnel"},
                             {"accelerator"},
                             {"samples_per_pixel"},
                             {"seed"},
                             {"filter"},
                             {"indirect"},
                             {"occlusion_distance"},
                             {"integrator"}}};
const SchemaElement kCamera{"\"camera\"",
                            "",
                            {"Camera", "Sampling"},
                            {{"projection"},
                             {"eye"},
                             {"look_at"},
                             {"up"},
                             {"fov"},
                             {"view_height"},
                             {"aperture"},
                             {"focus_distance"},
                             {"shutter"}}};
const SchemaElement kFog{
    "\"fog\"", "", {"Fog"}, {{"density", kRequired}, {"albedo"}, {"min"}, {"max"}}};
const SchemaElement kPointLight{"a point light",
                                "point",
                                {"Lights", "Light linking"},
                                {{"type", kRequired},
                                 {"position", kRequired},
                                 {"intensity"},
                                 {"attenuation"},
                                 {"only"},
                                 {"except"},
                                 {"shadows"}}};
const SchemaElement kDirectionalLight{"a directional light",
                                      "directional",
                                      {"Lights", "Light linking"},
                                      {{"type", kRequired},
                                       {"direction", kRequired},
                                       {"intensity"},
                                       {"only"},
                                       {"except"},
                                       {"shadows"}}};
const SchemaElement kRectangleLight{"a rectangle light",
                                    "rectangle",
                                    {"Lights", "Sampling"},
                                    {{"type", kRequired},
                                     {"corner", kRequired},
                                     {"edge_u", kRequired},
                                     {"edge_v", kRequired},
                                     {"radiance"}}};
const SchemaElement kSphereLight{
    "a sphere light",
    "sphere",
    {"Lights", "Sampling"},
    {{"type", kRequired}, {"center", kRequired}, {"radius", kRequired}, {"radiance"}}};
}  // namespace rt::schema

namespace rt::scene_internal {

namespace {

// Limits against absurd sizes (documented in docs/scene-format.md).
constexpr double kMaxImageSide = 16384;
constexpr double kMaxPixels = 64.0 * 1024 * 1024;
constexpr double kMaxSamplesPerPixel = 65536;

}  // namespace

void SceneSections::read_image(const json& root) {
    const json* image = member(root, "image");
    if (!image) return;
    require_object(*image, "/image", "{\"width\": 640, \"height\": 480}");
    check_keys(*image, "/image", schema::kImage);
    auto side = [&](const char* key, int& out) {
        const json* v = member(*image, key);
        if (!v) return;
        std::string pointer = JsonPositions::child("/image", key);
        double d = whole_number(*v, pointer);
        if (d < 1 || d > kMaxImageSide)
            fail_value(pointer,
                       label(pointer) + " must be between 1 and 16384, got " + source_text(pointer),
                       "choose a sensible image size");
        out = int(d);
    };
    side("width", scene_.image.width);
    side("height", scene_.image.height);
    if (double(scene_.image.width) * double(scene_.image.height) > kMaxPixels)
        fail_value("/image",
                   "the image has " + std::to_string(scene_.image.width) + "x" +
                       std::to_string(scene_.image.height) +
                       " pixels, more than the 67108864 (64 Mi) allowed",
                   "make it smaller");
}

void SceneSections::read_render(const json& root) {
    const json* render = member(root, "render");
    if (!render) return;
    require_object(*render, "/render", "{\"mode\": \"shaded\", \"max_depth\": 5}");
    check_keys(*render, "/render", schema::kRender);
    if (const json* v = member(*render, "mode")) {
        static const std::vector<std::string> modes = render_mode_names();
        scene_.mode = RenderMode(choice(*v, "/render/mode", modes));
    }
    if (const json* v = member(*render, "max_depth")) {
        double d = whole_number(*v, "/render/max_depth");
        if (d < 0 || d > kMaxDepthLimit)
            fail_value("/render/max_depth",
                       "\"max_depth\" must be between 0 and " + std::to_string(kMaxDepthLimit) +
                           ", got " + source_text("/render/max_depth"),
                       "a few bounces are enough");
        scene_.max_depth = int(d);
    }
    if (const json* v = member(*render, "shadows")) scene_.shadows = boolean(*v, "/render/shadows");
    if (const json* v = member(*render, "fresnel")) scene_.fresnel = boolean(*v, "/render/fresnel");
    if (const json* v = member(*render, "accelerator")) {
        static const std::vector<std::string> names{"none", "bvh"};
        scene_.accelerator =
            choice(*v, "/render/accelerator", names) == 0 ? Accelerator::None : Accelerator::Bvh;
    }
    read_sampling(*render);
    if (scene_.mode == RenderMode::BvhVisits && scene_.accelerator != Accelerator::Bvh)
        fail_value(
            "/render/mode",
            "mode \"bvh_visits\" draws the BVH, but the scene has no \"accelerator\": \"bvh\"",
            "add \"accelerator\": \"bvh\" to \"render\"");
}

// Stage 10's keys of "render" (docs/scene-format.md#sampling).
void SceneSections::read_sampling(const json& render) {
    SamplingSettings& s = scene_.sampling;
    if (const json* v = member(render, "samples_per_pixel")) {
        const double d = whole_number(*v, "/render/samples_per_pixel");
        if (d < 1 || d > kMaxSamplesPerPixel)
            fail_value("/render/samples_per_pixel",
                       "\"samples_per_pixel\" must be between 1 and 65536, got " +
                           source_text("/render/samples_per_pixel"),
                       "16 to 256 is usual");
        s.samples_per_pixel = int(d);
    }
    if (const json* v = member(render, "seed")) {
        const double d = whole_number(*v, "/render/seed");
        if (d < 0 || d > 9007199254740992.0)
            fail_value("/render/seed",
                       "\"seed\" must be between 0 and 2^53, got " + source_text("/render/seed"),
                       "any whole number picks another noise pattern");
        s.seed = std::uint64_t(d);
    }
    if (const json* v = member(render, "filter"))
        s.filter = choice(*v, "/render/filter", {"box", "tent"}) == 0 ? PixelFilter::Box
                                                                      : PixelFilter::Tent;
    if (const json* v = member(render, "indirect")) {
        static const IndirectLight values[] = {IndirectLight::Ambient, IndirectLight::Occlusion,
                                               IndirectLight::Diffuse};
        s.indirect = values[choice(*v, "/render/indirect", {"ambient", "occlusion", "diffuse"})];
    }
    if (const json* v = member(render, "occlusion_distance"))
        s.occlusion_distance = real_in(
            *v, "/render/occlusion_distance", [](double d) { return d > 0; }, "> 0",
            "blockers farther than this do not occlude");
    if (const json* v = member(render, "integrator"))
        s.integrator = choice(*v, "/render/integrator", {"whitted", "path"}) == 0
                           ? Integrator::Whitted
                           : Integrator::Path;
}

void SceneSections::read_camera(const json& root) {
    Projection projection = Projection::Perspective;
    Vec3 eye{0, 0, 5}, look_at{0, 0, 0}, up{0, 1, 0};
    Real fov = 45, view_height = 2;
    const json* camera = member(root, "camera");
    const json empty = json::object();
    if (!camera) camera = &empty;
    require_object(*camera, "/camera", "{\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]}");
    check_keys(*camera, "/camera", schema::kCamera);
    if (const json* v = member(*camera, "projection"))
        projection = choice(*v, "/camera/projection", {"perspective", "orthographic"}) == 0
                         ? Projection::Perspective
                         : Projection::Orthographic;
    if (const json* v = member(*camera, "eye")) eye = vec3(*v, "/camera/eye");
    if (const json* v = member(*camera, "look_at")) look_at = vec3(*v, "/camera/look_at");
    if (const json* v = member(*camera, "up")) up = vec3(*v, "/camera/up");
    if (const json* v = member(*camera, "fov"))
        fov = real_in(
            *v, "/camera/fov", [](double d) { return d > 0 && d < 180; },
            "between 0 and 180 degrees (exclusive)", "a typical vertical fov is 30 to 60");
    if (const json* v = member(*camera, "view_height"))
        view_height = real_in(
            *v, "/camera/view_height", [](double d) { return d > 0; }, "> 0",
            "give the height of the visible rectangle in world units");

    read_lens_and_shutter(*camera, projection);

    // The frame is only defined for a real viewing direction and an up that is not along it.
    auto where = [&](const char* key) {
        return member(*camera, key) ? JsonPositions::child("/camera", key) : std::string("/camera");
    };
    glm::dvec3 direction = glm::dvec3(look_at) - glm::dvec3(eye);
    glm::dvec3 upward(up);
    if (glm::length(direction) == 0)
        fail_value(where(member(*camera, "look_at") ? "look_at" : "eye"),
                   "\"look_at\" equals \"eye\", so the camera has no viewing direction",
                   "move the camera or its target");
    double sine =
        glm::length(glm::cross(upward, direction)) / (glm::length(upward) * glm::length(direction));
    if (!(sine > 1e-4))
        fail_value(
            where("up"), "\"up\" is zero or parallel to the viewing direction",
            "choose an up vector that is not along look_at - eye, e.g. [0, 1, 0] or [0, 0, 1]");
    scene_.camera = make_look_at_camera(projection, eye, look_at, up, fov, view_height);
    const Camera& c = scene_.camera;
    if (!all_finite(c.u) || !all_finite(c.v) || !all_finite(c.w))
        fail_value("/camera", "the camera frame cannot be computed (coordinates too large)",
                   "use smaller camera coordinates");
}

// Stage 10: the thin lens and the shutter interval of "camera".
void SceneSections::read_lens_and_shutter(const json& camera, Projection projection) {
    SamplingSettings& s = scene_.sampling;
    if (const json* v = member(camera, "aperture")) {
        s.aperture = real_in(
            *v, "/camera/aperture", [](double d) { return d >= 0; }, ">= 0",
            "the lens diameter in world units; 0 is a pinhole");
        if (s.aperture > 0 && projection != Projection::Perspective)
            fail_value("/camera/aperture", "an orthographic camera has no lens",
                       "drop \"aperture\" or use \"projection\": \"perspective\"");
    }
    if (const json* v = member(camera, "focus_distance"))
        s.focus_distance = real_in(
            *v, "/camera/focus_distance", [](double d) { return d > 0; }, "> 0",
            "the distance from the eye to the plane in focus");
    if (const json* v = member(camera, "shutter")) {
        require_array_of(*v, "/camera/shutter", 2, "numbers", "numbers",
                         "write it as [open, close], e.g. [0, 1]");
        const Real open = real((*v)[0], JsonPositions::child("/camera/shutter", std::size_t(0)));
        const Real close = real((*v)[1], JsonPositions::child("/camera/shutter", std::size_t(1)));
        if (!(open <= close))
            fail_value("/camera/shutter", "the shutter closes before it opens",
                       "give [open, close] with open <= close, e.g. [0, 1]");
        s.shutter_open = open;
        s.shutter_close = close;
    }
}

void SceneSections::read_lights(const json& root) {
    const json* list = member(root, "lights");
    if (!list) return;
    require_array(*list, "/lights", "[{\"type\": \"point\", \"position\": [0, 5, 0]}]");
    for (std::size_t i = 0; i < list->size(); ++i)
        read_light((*list)[i], JsonPositions::child("/lights", i));
}

void SceneSections::read_light(const json& object, const std::string& pointer) {
    static const std::vector<std::string> types{"point", "directional", "rectangle", "sphere"};
    require_object(object, pointer, "{\"type\": \"point\", \"position\": [0, 5, 0]}");
    const json& type_value = required(object, pointer, "type", "a light", list_of(types));
    Light light;
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    const std::size_t type = choice(type_value, at("type"), types);
    if (type >= 2) {
        read_area_light(object, pointer,
                        type == 2 ? AreaLightKind::Rectangle : AreaLightKind::Sphere);
        return;
    }
    if (type == 0) {
        check_keys(object, pointer, schema::kPointLight);
        light.kind = LightKind::Point;
        light.position = vec3(required(object, pointer, "position", "a point light", "[x, y, z]"),
                              at("position"));
        if (const json* v = member(object, "attenuation")) {
            Color a = color(*v, at("attenuation"));
            if (a.x == 0 && a.y == 0 && a.z == 0)
                fail_value(at("attenuation"), "\"attenuation\" must not be all zero",
                           "use [1, 0, 0] for no fall-off");
            light.attenuation = Vec3(a);
        }
    } else {
        check_keys(object, pointer, schema::kDirectionalLight);
        light.kind = LightKind::Directional;
        light.direction = unit_direction(
            required(object, pointer, "direction", "a directional light", "[0, -1, 0]"),
            at("direction"), "give the direction the light travels, e.g. [0, -1, 0]");
    }
    if (const json* v = member(object, "intensity")) light.intensity = color(*v, at("intensity"));
    read_light_links(object, pointer, light);
    scene_.lights.push_back(light);
}

// Light linking: "only" (the materials the light lights) or "except" (those it does not), and
// "shadows": false (nothing blocks it).
void SceneSections::read_light_links(const json& object, const std::string& pointer,
                                     Light& light) const {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    const json* only = member(object, "only");
    const json* except = member(object, "except");
    if (only && except)
        fail_value(at("except"), "a light takes \"only\" or \"except\", not both",
                   "list the materials it lights under \"only\", or those it does not under "
                   "\"except\"");
    if (const json* list = only ? only : except) {
        const std::string where = at(only ? "only" : "except");
        if (!list->is_array() || list->empty())
            fail_value(where, label(where) + " must be a list of material names",
                       "write e.g. [\"gold\"]");
        std::uint32_t named = 0;
        for (std::size_t i = 0; i < list->size(); ++i) {
            const std::string item = JsonPositions::child(where, i);
            const int m = material_ref((*list)[i], item);
            if (m >= kLinkedMaterials)
                fail_value(item,
                           "material " + std::to_string(m) + " is past the " +
                               std::to_string(kLinkedMaterials) + " a light can be linked to",
                           "list the materials lights are linked to among the first " +
                               std::to_string(kLinkedMaterials));
            named |= std::uint32_t(1) << m;
        }
        light.reach_mask = only ? named : ~named;
        light.reach_rest = !only;
    }
    if (const json* v = member(object, "shadows")) light.casts_shadows = boolean(*v, at("shadows"));
}

// Stage 10's area lights: a rectangle or a sphere of constant radiance.
void SceneSections::read_area_light(const json& object, const std::string& pointer,
                                    AreaLightKind kind) {
    auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    AreaLight light;
    light.kind = kind;
    if (kind == AreaLightKind::Rectangle) {
        check_keys(object, pointer, schema::kRectangleLight);
        const char* what = "a rectangle light";
        light.corner = vec3(required(object, pointer, "corner", what, "[x, y, z]"), at("corner"));
        light.edge_u = vec3(required(object, pointer, "edge_u", what, "[1, 0, 0]"), at("edge_u"));
        light.edge_v = vec3(required(object, pointer, "edge_v", what, "[0, 0, 1]"), at("edge_v"));
        const glm::dvec3 u(light.edge_u), v(light.edge_v);
        const double lengths = glm::length(u) * glm::length(v);
        if (!(lengths > 0) || !std::isfinite(glm::length(glm::cross(light.edge_u, light.edge_v))))
            fail_value(at("edge_v"), "the rectangle has no area (an edge is zero)",
                       "give two non-zero edges");
        if (std::abs(glm::dot(u, v)) > 1e-6 * lengths)
            fail_value(at("edge_v"), "\"edge_u\" and \"edge_v\" are not perpendicular",
                       "a rectangle light needs perpendicular edges");
    } else {
        check_keys(object, pointer, schema::kSphereLight);
        light.center =
            vec3(required(object, pointer, "center", "a sphere light", "[x, y, z]"), at("center"));
        light.radius = real_in(
            required(object, pointer, "radius", "a sphere light", "0.5"), at("radius"),
            [](double d) { return d > 0; }, "> 0", "give the light a positive radius");
    }
    if (const json* v = member(object, "radiance")) light.radiance = color(*v, at("radiance"));
    scene_.area_lights.push_back(light);
}

// Stage 10, optional: "fog", a homogeneous medium everywhere or in a box
// (docs/scene-format.md#fog).
void SceneSections::read_fog(const json& root) {
    const json* fog = member(root, "fog");
    if (!fog) return;
    require_object(*fog, "/fog", "{\"density\": 0.3, \"albedo\": [0.9, 0.9, 0.9]}");
    check_keys(*fog, "/fog", schema::kFog);
    Medium medium;
    medium.density = real_in(
        required(*fog, "/fog", "density", "the fog", "0.3"), "/fog/density",
        [](double d) { return d > 0; }, "> 0",
        "the fraction of light scattered or absorbed per unit distance; leave out \"fog\" for "
        "none");
    if (const json* v = member(*fog, "albedo")) {
        medium.albedo = color(*v, "/fog/albedo");
        for (int k = 0; k < 3; ++k)
            if (medium.albedo[k] > 1) {
                const std::string at = JsonPositions::child("/fog/albedo", std::size_t(k));
                fail_value(at, "\"albedo\" must be between 0 and 1, got " + source_text(at),
                           "it is the part of the light the fog takes out that it scatters; "
                           "above 1 the fog would make light");
            }
    }
    const json* min = member(*fog, "min");
    const json* max = member(*fog, "max");
    if (min || max) {
        if (!min || !max)
            fail_value(min ? "/fog/min" : "/fog/max", "a fog box needs both \"min\" and \"max\"",
                       "give both corners, or neither for fog everywhere");
        medium.bounded = true;
        medium.min = vec3(*min, "/fog/min");
        medium.max = vec3(*max, "/fog/max");
        check_corners(medium.min, medium.max, "/fog/min", "/fog/max");
    }
    if (!scene_.area_lights.empty())
        fail_value("/fog",
                   "fog and area lights together are not supported (an area light's shadow rays "
                   "do not pass through the fog)",
                   "light a foggy scene with point or directional lights");
    scene_.fog = medium;
}

}  // namespace rt::scene_internal
