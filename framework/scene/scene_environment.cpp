// The scene's "environment" (stage 08): a lat-long image or six cube faces, read into the
// texture table (docs/scene-format.md#environment).
#include <cmath>
#include <string>

#include "image/image.h"
#include "scene/message_text.h"
#include "scene/scene_sections.h"

namespace rt::schema {
const SchemaElement kEnvironment{
    "\"environment\"",
    "",
    {"Environment"},
    {{"latlong"}, {"cube"}, {"sky"}, {"intensity"}, {"rotate_y"}, {"ambient"}}};
const SchemaElement kSky{"\"sky\"",
                         "",
                         {"Environment"},
                         {{"zenith"},
                          {"horizon"},
                          {"ground"},
                          {"sun_direction"},
                          {"sun_radius_degrees"},
                          {"sun"},
                          {"resolution"}}};
const SchemaElement kCubeFaces{"\"cube\"",
                               "",
                               {"Environment"},
                               {{"px", kRequired},
                                {"nx", kRequired},
                                {"py", kRequired},
                                {"ny", kRequired},
                                {"pz", kRequired},
                                {"nz", kRequired}}};
}  // namespace rt::schema

namespace rt::scene_internal {

namespace {

namespace fs = std::filesystem;

}  // namespace

Image SceneSections::read_environment_image(const json& value, const std::string& pointer) {
    const std::string file = string(value, pointer, "\"sky.exr\"");
    if (file.empty()) fail_value(pointer, "the image file name is empty", "name an image file");
    const fs::path path = fs::path(file).is_absolute() ? fs::path(file) : base_dir_ / file;
    try {
        // Stored linear: 8-bit files are decoded from sRGB once, here (float files are linear).
        return rt::read_image(path, Encoding::Srgb);
    } catch (const ImageError& e) {
        fail_value(pointer, "environment image " + quote(file) + ": " + e.problem());
    }
}

SkyParameters SceneSections::read_sky(const json& value, const std::string& pointer) {
    require_object(value, pointer, "{\"sun_direction\": [0.5, 0.6, -0.6]}");
    check_keys(value, pointer, schema::kSky);
    SkyParameters sky;
    const auto at = [&](const char* key) { return JsonPositions::child(pointer, key); };
    if (const json* v = member(value, "zenith")) sky.zenith = color(*v, at("zenith"));
    if (const json* v = member(value, "horizon")) sky.horizon = color(*v, at("horizon"));
    if (const json* v = member(value, "ground")) sky.ground = color(*v, at("ground"));
    if (const json* v = member(value, "sun")) sky.sun = color(*v, at("sun"));
    if (const json* v = member(value, "sun_direction"))
        sky.sun_direction = unit_direction(
            *v, at("sun_direction"), "give the direction towards the sun, e.g. [0.5, 0.6, -0.6]");
    if (const json* v = member(value, "sun_radius_degrees"))
        sky.sun_radius_degrees = float(real_in(
            *v, at("sun_radius_degrees"), [](double d) { return d >= 0 && d <= 45; },
            "between 0 and 45", "e.g. 2; 0 leaves the sun out"));
    if (const json* v = member(value, "resolution"))
        sky.height = int(real_in(
            *v, at("resolution"),
            [](double d) { return d >= 8 && d <= 2048 && d == std::floor(d); },
            "a whole number from 8 to 2048",
            "the sky is baked into an image 2 resolution x resolution texels"));
    // A disc narrower than a texel could fall between texel centres and vanish from the image.
    const double texel_degrees = 180.0 / sky.height;
    if (sky.sun_radius_degrees > 0 && sky.sun_radius_degrees < texel_degrees) {
        const int needed = int(std::ceil(180.0 / sky.sun_radius_degrees));
        fail_value(
            member(value, "sun_radius_degrees") ? at("sun_radius_degrees") : pointer,
            "a sun of radius " + std::to_string(sky.sun_radius_degrees).substr(0, 5) +
                " degrees is narrower than a texel of the baked sky (" +
                std::to_string(texel_degrees).substr(0, 5) + " degrees at resolution " +
                std::to_string(sky.height) + ")",
            "set \"resolution\" to at least " + std::to_string(needed) + " or make the sun larger");
    }
    return sky;
}

void SceneSections::read_environment(const json& root) {
    const json* env = member(root, "environment");
    if (!env) return;
    const std::string at = "/environment";
    const std::string example = "{\"latlong\": \"sky.exr\"}";
    require_object(*env, at, example);
    check_keys(*env, at, schema::kEnvironment);
    const json* latlong = member(*env, "latlong");
    const json* cube = member(*env, "cube");
    const json* sky = member(*env, "sky");
    if (int(latlong != nullptr) + int(cube != nullptr) + int(sky != nullptr) > 1)
        fail_key(JsonPositions::child(at, sky ? "sky" : "cube"),
                 "an environment is one of \"latlong\", \"cube\" and \"sky\"", "keep one of them");
    if (!latlong && !cube && !sky)
        fail_value(
            at, "the environment needs \"latlong\", \"cube\" or \"sky\"",
            "write e.g. " + example + " (paths relative to the scene file) or {\"sky\": {}}");
    Environment& e = scene_.environment;
    if (const json* v = member(*env, "intensity"))
        e.intensity = float(real_in(
            *v, JsonPositions::child(at, "intensity"), [](double d) { return d >= 0; }, ">= 0",
            "1 shows the image as it is"));
    if (const json* v = member(*env, "rotate_y")) {
        const std::string pointer = JsonPositions::child(at, "rotate_y");
        e.rotate_y = float(real_in(
            *v, pointer, [](double d) { return std::abs(d) <= 360; }, "between -360 and 360",
            "give the turn about +y in degrees"));
    }

    read_environment_images(latlong, cube, sky, at);
    if (const json* v = member(*env, "ambient")) {
        const Real k = real_in(
            *v, JsonPositions::child(at, "ambient"), [](double d) { return d >= 0; }, ">= 0",
            "0 adds nothing; 1 adds the environment's mean radiance to ambient_light");
        scene_.ambient_light += mean_environment_radiance(scene_) * float(k);
    }
}

void SceneSections::read_environment_images(const json* latlong, const json* cube, const json* sky,
                                            const std::string& at) {
    Environment& e = scene_.environment;
    if (latlong || sky) {
        const Image image =
            latlong ? read_environment_image(*latlong, JsonPositions::child(at, "latlong"))
                    : bake_sky(read_sky(*sky, JsonPositions::child(at, "sky")));
        e.kind = EnvironmentKind::LatLong;
        e.image = scene_.add_texture_image(image.width, image.height, image.pixels);
        return;
    }
    const std::string cube_at = JsonPositions::child(at, "cube");
    require_object(*cube, cube_at,
                   "{\"px\": \"px.png\", \"nx\": \"nx.png\", \"py\": \"py.png\", \"ny\": "
                   "\"ny.png\", \"pz\": \"pz.png\", \"nz\": \"nz.png\"}");
    check_keys(*cube, cube_at, schema::kCubeFaces);
    int size = 0;
    std::string first;
    for (int f = 0; f < kCubeFaces; ++f) {
        const char* name = kCubeFaceNames[f];
        const json& value =
            required(*cube, cube_at, name, "a cube map", std::string("\"") + name + ".png\"");
        const std::string pointer = JsonPositions::child(cube_at, name);
        const Image face = read_environment_image(value, pointer);
        const std::string dims = std::to_string(face.width) + "x" + std::to_string(face.height);
        if (face.width != face.height)
            fail_value(pointer, "cube face " + quote(name) + " is " + dims + ", not square",
                       "make every face square (the same width and height)");
        if (f == 0) {
            size = face.width;
            first = dims;
        } else if (face.width != size) {
            fail_value(pointer,
                       "cube face " + quote(name) + " is " + dims + " but \"px\" is " + first,
                       "give all six faces the same size");
        }
        e.faces[f] = scene_.add_texture_image(face.width, face.height, face.pixels);
    }
    e.kind = EnvironmentKind::CubeMap;
}

}  // namespace rt::scene_internal
