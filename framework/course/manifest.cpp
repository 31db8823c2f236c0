#include "course/manifest.h"

#include "core/text_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <stdexcept>

using json = nlohmann::json;
namespace fs = std::filesystem;

namespace rt {
namespace {

// A manifest file's text; throws std::runtime_error naming the file when it cannot be read.
std::string read_manifest(const fs::path& file) {
    return read_text_file(file, std::uintmax_t(1) << 20, [&](const FileProblem&) {
        throw std::runtime_error(file.string() + ": cannot be read");
    });
}

json parse_file(const fs::path& file) {
    return json::parse(read_manifest(file));
}

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

bool read_renderer_is_gpu(const json& g, const fs::path& file) {
    const std::string renderer = g.value("renderer", std::string("cpu"));
    if (renderer != "cpu" && renderer != "gpu")
        throw std::runtime_error(file.string() + ": \"renderer\" is \"" + renderer +
                                 "\"; use \"cpu\" (the default) or \"gpu\"");
    return renderer == "gpu";
}

// A released starter tree has no hidden/ folder: students grading themselves simply do not get
// the groups that need it (false).
bool read_unit_group(const json& u, const fs::path& folder, const fs::path& file,
                     UnitGroup& group) {
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
    return present;
}

SceneSpec read_scene(const json& sc, const StageSpec& stage, const fs::path& source,
                     const fs::path& file) {
    SceneSpec scene;
    scene.name = sc.at("name").get<std::string>();
    scene.folder = stage.folder;
    if (sc.contains("from")) {
        // Another stage's scene and reference (stage 09 renders earlier scenes).
        const std::string from = sc.at("from").get<std::string>();
        scene.folder = "stages/" + from;
        if (!fs::is_regular_file(source / scene.folder / "scenes" / (scene.name + ".json")))
            throw std::runtime_error(file.string() + ": scene \"" + scene.name + "\" from \"" +
                                     from + "\": no " + scene.folder + "/scenes/" + scene.name +
                                     ".json");
    }
    scene.points = sc.value("points", scene.points);
    scene.visibility = sc.value("visibility", scene.visibility);
    check_visibility(scene.visibility, file);
    scene.thresholds = parse_thresholds(sc, stage.image_defaults);
    return scene;
}

}  // namespace

CompareOptions ImageThresholds::compare_options() const {
    CompareOptions options;
    options.tolerance = tolerance;
    options.max_failing_percent = pass_percent;
    options.neighbourhood = neighbourhood;
    options.block = block;
    return options;
}

ImageThresholds StageSpec::thresholds_of(const std::string& name) const {
    const SceneSpec* graded = scene(name);
    return graded ? graded->thresholds : image_defaults;
}

const SceneSpec* StageSpec::scene(const std::string& name) const {
    for (const SceneSpec& s : scenes)
        if (s.name == name) return &s;
    return nullptr;
}

StageInfo read_stage_info(const fs::path& stage_json) {
    StageInfo info;
    std::string text;
    try {
        text = read_manifest(stage_json);
    } catch (const std::runtime_error&) {
        info.problem = "missing or unreadable";
        return info;
    }
    try {
        const json j = json::parse(text);
        if (j.contains("number") && j["number"].is_number_integer()) info.number = j["number"];
        if (j.contains("title") && j["title"].is_string()) info.title = j["title"];
        if (!j.contains("student_files") || !j["student_files"].is_array()) {
            info.problem = "has no \"student_files\" array";
            return info;
        }
        for (const auto& file : j["student_files"]) {
            if (!file.is_string()) {
                info.problem = "lists a \"student_files\" entry that is not a string";
                return info;
            }
            info.student_files.push_back(file.get<std::string>());
        }
    } catch (const json::exception& e) {
        info.problem = std::string("is not valid JSON (") + e.what() + ")";
    }
    return info;
}

StageSpec load_stage_spec(const fs::path& source, const fs::path& folder) {
    const fs::path file = folder / "grading.json";
    try {
        const json stage = parse_file(folder / "stage.json");
        const json g = parse_file(file);
        StageSpec s;
        s.number = stage.at("number").get<int>();
        s.folder = "stages/" + folder.filename().string();
        s.title = stage.value("title", folder.filename().string());
        s.student_files = stage.at("student_files").get<std::vector<std::string>>();
        s.test_seconds = g.value("test_seconds", s.test_seconds);
        s.render_seconds = g.value("render_seconds", s.render_seconds);
        s.gpu = read_renderer_is_gpu(g, file);
        s.image_defaults = parse_thresholds(g.value("image_defaults", json::object()), {});
        for (const json& u : g.value("unit_tests", json::array())) {
            UnitGroup group;
            if (read_unit_group(u, folder, file, group)) s.groups.push_back(group);
        }
        for (const json& sc : g.value("scenes", json::array()))
            s.scenes.push_back(read_scene(sc, s, source, file));
        if (g.contains("leaderboard")) {
            s.leaderboard_scene = g["leaderboard"].at("scene").get<std::string>();
            if (!s.scene(s.leaderboard_scene))
                throw std::runtime_error(
                    file.string() + ": \"leaderboard\": scene \"" + s.leaderboard_scene +
                    "\" is not one of the graded \"scenes\"; name one of them");
            const std::string rank_by = g["leaderboard"].value("rank_by", "speed");
            if (rank_by != "speed" && rank_by != "traversal_cost")
                throw std::runtime_error(file.string() + ": \"leaderboard\": \"rank_by\": \"" +
                                         rank_by + "\" is not \"speed\" or \"traversal_cost\"");
            s.leaderboard_traversal_cost = rank_by == "traversal_cost";
        }
        return s;
    } catch (const json::exception& e) {
        throw std::runtime_error(file.string() + ": " + e.what());
    }
}

std::vector<StageSpec> load_stage_specs(const fs::path& source) {
    std::vector<fs::path> folders;
    for (const auto& entry : fs::directory_iterator(source / "stages"))
        if (entry.is_directory() && fs::exists(entry.path() / "grading.json"))
            folders.push_back(entry.path());
    std::sort(folders.begin(), folders.end());
    std::vector<StageSpec> specs;
    for (const auto& folder : folders) specs.push_back(load_stage_spec(source, folder));
    return specs;
}

}  // namespace rt
