// stages/NN-name/grading.json and stage.json: what a grading covers (docs/grading.md).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <stdexcept>

#include "grade.h"
#include "util.h"

using json = nlohmann::json;
namespace fs = std::filesystem;

namespace rt::grader {

namespace {

// ---------------------------------------------------------------- grading specs

ImageThresholds parse_thresholds(const json& j, ImageThresholds t) {
    t.tolerance = j.value("tolerance", t.tolerance);
    t.pass_percent = j.value("pass_percent", t.pass_percent);
    t.fail_percent = j.value("fail_percent", t.fail_percent);
    t.neighbourhood = j.value("neighbourhood", t.neighbourhood);
    t.block = j.value("block", t.block);
    return t;
}

void check_visibility(const std::string& v, const fs::path& file) {
    if (v != "visible" && v != "hidden" && v != "after_due_date" && v != "after_published")
        throw std::runtime_error(
            file.string() + ": visibility \"" + v +
            "\" is not one of visible, hidden, after_due_date, after_published");
}

}  // namespace

bool is_compiled_student_file(const std::string& key) {
    return fs::path(key).extension() != ".glsl";
}

std::vector<StageSpec> load_stage_specs(const fs::path& source) {
    std::vector<StageSpec> specs;
    std::vector<fs::path> folders;
    for (const auto& entry : fs::directory_iterator(source / "stages"))
        if (entry.is_directory() && fs::exists(entry.path() / "grading.json"))
            folders.push_back(entry.path());
    std::sort(folders.begin(), folders.end());
    for (const auto& folder : folders) {
        const fs::path file = folder / "grading.json";
        try {
            const json stage = json::parse(read_text(folder / "stage.json"));
            const json g = json::parse(read_text(file));
            StageSpec s;
            s.number = stage.at("number").get<int>();
            s.folder = "stages/" + folder.filename().string();
            s.title = stage.value("title", folder.filename().string());
            s.student_files = stage.at("student_files").get<std::vector<std::string>>();
            s.test_seconds = g.value("test_seconds", s.test_seconds);
            s.render_seconds = g.value("render_seconds", s.render_seconds);
            const std::string renderer = g.value("renderer", std::string("cpu"));
            if (renderer != "cpu" && renderer != "gpu")
                throw std::runtime_error(file.string() + ": \"renderer\" is \"" + renderer +
                                         "\"; use \"cpu\" (the default) or \"gpu\"");
            s.gpu = renderer == "gpu";
            const ImageThresholds defaults =
                parse_thresholds(g.value("image_defaults", json::object()), ImageThresholds{});
            for (const json& u : g.value("unit_tests", json::array())) {
                UnitGroup group;
                group.binary = u.at("binary").get<std::string>();
                group.include = u.value("include", group.include);
                group.exclude = u.value("exclude", group.exclude);
                group.hidden_sources = u.value("hidden_sources", group.hidden_sources);
                group.points = u.value("points", group.points);
                group.visibility = u.value("visibility", group.visibility);
                check_visibility(group.visibility, file);
                bool present = true;
                for (const auto& h : group.hidden_sources) {
                    if (!h.starts_with("hidden/"))
                        throw std::runtime_error(file.string() + ": hidden source " + h +
                                                 " must lie in the stage's hidden/ folder");
                    present = present && fs::is_regular_file(folder / h);
                }
                // A released starter tree has no hidden/ folder: students grading themselves
                // simply do not get those tests.
                if (present) s.groups.push_back(group);
            }
            for (const json& sc : g.value("scenes", json::array())) {
                SceneSpec scene;
                scene.name = sc.at("name").get<std::string>();
                scene.folder = s.folder;
                if (sc.contains("from")) {
                    // Another stage's scene and reference (stage 09 renders earlier scenes).
                    scene.folder = "stages/" + sc.at("from").get<std::string>();
                    if (!fs::is_regular_file(source / scene.folder / "scenes" /
                                             (scene.name + ".json")))
                        throw std::runtime_error(file.string() + ": scene \"" + scene.name +
                                                 "\" from \"" + sc.at("from").get<std::string>() +
                                                 "\": no " + scene.folder + "/scenes/" +
                                                 scene.name + ".json");
                }
                scene.points = sc.value("points", scene.points);
                scene.visibility = sc.value("visibility", scene.visibility);
                check_visibility(scene.visibility, file);
                scene.thresholds = parse_thresholds(sc, defaults);
                s.scenes.push_back(scene);
            }
            specs.push_back(std::move(s));
        } catch (const json::exception& e) {
            throw std::runtime_error(file.string() + ": " + e.what());
        }
    }
    return specs;
}

}  // namespace rt::grader
