// The scene's "environment" (stage 08): a lat-long image or six cube faces, read into the
// texture table (docs/scene-format.md#environment).
#include <cmath>
#include <string>

#include "image/image.h"
#include "scene/message_text.h"
#include "scene/scene_sections.h"

namespace rt::scene_internal {

namespace {

namespace fs = std::filesystem;

// An ImageError reads "<file>: error: <what>; <fix>"; the scene's message names the file as the
// scene wrote it, so only "<what>; <fix>" is kept.
std::string image_problem(const std::string& message) {
    const std::string marker = ": error: ";
    const std::size_t at = message.find(marker);
    return at == std::string::npos ? message : message.substr(at + marker.size());
}

}  // namespace

Image SceneSections::read_environment_image(const json& value, const std::string& pointer) {
    const std::string file = string(value, pointer, "\"sky.exr\"");
    if (file.empty()) fail_value(pointer, "the image file name is empty", "name an image file");
    const fs::path path = fs::path(file).is_absolute() ? fs::path(file) : base_dir_ / file;
    try {
        // Stored linear: 8-bit files are decoded from sRGB once, here (float files are linear).
        return rt::read_image(path, Encoding::Srgb);
    } catch (const ImageError& e) {
        fail_value(pointer, "environment image " + quote(file) + ": " + image_problem(e.what()));
    }
}

void SceneSections::read_environment(const json& root) {
    const json* env = member(root, "environment");
    if (!env) return;
    const std::string at = "/environment";
    const std::string example = "{\"latlong\": \"sky.exr\"}";
    require_object(*env, at, example);
    check_keys(*env, at, "\"environment\"", {"latlong", "cube", "intensity", "rotate_y"});
    const json* latlong = member(*env, "latlong");
    const json* cube = member(*env, "cube");
    if (latlong && cube)
        fail_key(JsonPositions::child(at, "cube"),
                 "an environment is either \"latlong\" or \"cube\"", "keep one of the two");
    if (!latlong && !cube)
        fail_value(at, "the environment needs \"latlong\" or \"cube\"",
                   "write e.g. " + example + " (paths relative to the scene file)");
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

    if (latlong) {
        const Image image = read_environment_image(*latlong, JsonPositions::child(at, "latlong"));
        e.kind = EnvironmentKind::LatLong;
        e.image = scene_.add_texture_image(image.width, image.height, image.pixels);
        return;
    }
    const std::string cube_at = JsonPositions::child(at, "cube");
    require_object(*cube, cube_at,
                   "{\"px\": \"px.png\", \"nx\": \"nx.png\", \"py\": \"py.png\", \"ny\": "
                   "\"ny.png\", \"pz\": \"pz.png\", \"nz\": \"nz.png\"}");
    check_keys(*cube, cube_at, "\"cube\"", {"px", "nx", "py", "ny", "pz", "nz"});
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
            size = face.width, first = dims;
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
