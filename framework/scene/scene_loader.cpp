// Loading a scene file: the file itself, then its sections (docs/scene-format.md). Parsing is
// nlohmann::json's job; the rest turns the parsed value into a Scene and checks every field, so
// that a mistake in a scene file is reported as one compiler-style line pointing at the
// offending value instead of a crash or a silently wrong picture.
#include "scene/scene_loader.h"

#include "core/diagnostics.h"
#include "core/text_file.h"
#include "scene/scene_sections.h"

namespace rt {

namespace schema {
// The top level of a scene file (docs/scene-format.md#top-level).
const SchemaElement kScene{"the scene",
                           "",
                           {"Top level"},
                           {{"camera"},
                            {"image"},
                            {"render"},
                            {"background"},
                            {"environment"},
                            {"fog"},
                            {"ambient_light"},
                            {"textures"},
                            {"materials"},
                            {"objects"},
                            {"surfaces"},
                            {"lights"}}};
}  // namespace schema

namespace scene_internal {

Scene SceneSections::load() {
    parse();
    const json& root = document();
    if (!root.is_object())
        fail_value("", "the top level must be a JSON object, got " + describe(root),
                   "wrap the scene in { ... }");
    check_keys(root, "", schema::kScene);
    scene_.source = name_;
    read_image(root);
    read_render(root);
    if (const json* v = member(root, "background")) scene_.background = color(*v, "/background");
    if (const json* v = member(root, "ambient_light"))
        scene_.ambient_light = color(*v, "/ambient_light");
    read_environment(root);  // after ambient_light: its "ambient" adds to it
    read_camera(root);
    read_textures(root);
    read_materials(root);
    finish_textures();
    read_objects(root);
    read_surfaces(root);
    read_lights(root);
    read_fog(root);
    return std::move(scene_);
}

}  // namespace scene_internal

namespace {

namespace fs = std::filesystem;
using scene_internal::json;

constexpr std::size_t kMaxSceneFileBytes = std::size_t(64) << 20;

}  // namespace

Scene parse_scene(const std::string& text, const std::string& name, const fs::path& base_dir) {
    try {
        return scene_internal::SceneSections(text, name, base_dir).load();
    } catch (const json::exception& e) {  // a safety net: every check should come first
        throw SceneError(one_line(name + ":1:1: error: unexpected problem reading the scene (" +
                                  std::string(e.what()) + "); please report this file"));
    }
}

std::string read_scene_text(const fs::path& file) {
    const std::string name = file.string();
    auto fail = [&](const std::string& what, const std::string& fix) {
        throw SceneError(one_line(name + ":1:1: error: " + what + "; " + fix));
    };
    return read_text_file(file, kMaxSceneFileBytes, [&](const FileProblem& problem) {
        switch (problem.kind) {
            case FileProblem::Missing:
                return fail("no such file", "check the path");
            case FileProblem::Directory:
                return fail("is a directory, not a scene file", "give the path of a .json file");
            case FileProblem::CannotOpen:
                return fail("cannot open the file", "check its permissions");
            case FileProblem::TooLarge:
                return fail("the file is larger than 64 MiB", "put large geometry in an OBJ mesh");
            case FileProblem::ReadError:
                return fail("the file could not be read", "check the file");
        }
    });
}

Scene load_scene(const fs::path& file) {
    return parse_scene(read_scene_text(file), file.string(), file.parent_path());
}

}  // namespace rt
