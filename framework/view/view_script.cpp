#include "view/view_script.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "view/view_settings.h"

namespace rt::view {
namespace {

struct Syntax {
    std::size_t args;
    const char* usage;
};

const std::map<std::string, Syntax> kCommands = {
    {"sleep", {1, "sleep SECONDS"}},
    {"wait-refined", {0, "wait-refined"}},
    {"key", {1, "key S|R|W|P|Q"}},
    {"click", {2, "click X Y (image pixel)"}},
    {"set", {2, "set NAME VALUE"}},
    {"toggle", {1, "toggle shadows|bvh"}},
    {"orbit", {2, "orbit YAW PITCH (degrees)"}},
    {"pan", {2, "pan RIGHT UP (fractions of the view)"}},
    {"zoom", {1, "zoom FACTOR"}},
    {"reset-camera", {0, "reset-camera"}},
    {"projection", {1, "projection perspective|orthographic"}},
    {"write-camera", {1, "write-camera FILE (the scene with the current camera, in --out)"}},
    {"show", {1, "show render|reference|difference"}},
    {"raster", {1, "raster on|off"}},
    {"screenshot", {1, "screenshot NAME"}},
    {"save-render", {1, "save-render NAME"}},
    {"save-display", {1, "save-display NAME"}},
    {"quit", {0, "quit"}},
    {"mouse-click", {2, "mouse-click X Y (image pixel)"}},
    {"mouse-drag", {5, "mouse-drag X0 Y0 X1 Y1 left|right"}},
    {"mouse-wheel", {3, "mouse-wheel X Y STEPS"}},
};

bool is_number(const std::string& text) {
    char* end = nullptr;
    std::strtod(text.c_str(), &end);
    return !text.empty() && *end == '\0';
}

// The checks a command's arguments need beyond their count; "" when fine.
std::string check(const ScriptCommand& c) {
    const std::string& name = c.name;
    if (name == "sleep" || name == "zoom" || name == "orbit" || name == "pan" || name == "click" ||
        name == "mouse-click" || name == "mouse-drag" || name == "mouse-wheel")
        for (std::size_t i = 0; i < std::min<std::size_t>(c.args.size(), 4); ++i)
            if (!is_number(c.args[i])) return "\"" + c.args[i] + "\" is not a number";
    if (name == "mouse-drag" && c.args[4] != "left" && c.args[4] != "right")
        return "drag with the left or right button";
    if (name == "zoom" && std::strtod(c.args[0].c_str(), nullptr) <= 0)
        return "the zoom factor must be above 0";
    if (name == "key" && c.args[0] != "S" && c.args[0] != "R" && c.args[0] != "Q" &&
        c.args[0] != "W" && c.args[0] != "P")
        return "unknown key \"" + c.args[0] + "\"";
    if (name == "toggle" && c.args[0] != "shadows" && c.args[0] != "bvh")
        return "only shadows and bvh toggle; use set for the others";
    if (name == "show" && c.args[0] != "render" && c.args[0] != "reference" &&
        c.args[0] != "difference")
        return "cannot show \"" + c.args[0] + "\"";
    if (name == "projection" && c.args[0] != "perspective" && c.args[0] != "orthographic")
        return "projection is perspective or orthographic, not \"" + c.args[0] + "\"";
    if (name == "write-camera" && (c.args[0].find('/') != std::string::npos || c.args[0].empty()))
        return "write-camera takes a file name (written in --out), not a path";
    if (name == "raster" && c.args[0] != "on" && c.args[0] != "off")
        return "raster takes on or off";
    if (name == "set") {
        ViewSettings probe;
        const std::string error = set_by_name(probe, c.args[0], c.args[1]);
        if (!error.empty()) return error;
    }
    if ((name == "screenshot" || name == "save-render" || name == "save-display") &&
        c.args[0].find_first_of("/\\") != std::string::npos)
        return "NAME is a file name in --out, without folders";
    return "";
}

}  // namespace

std::vector<ScriptCommand> read_script(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in)
        throw std::runtime_error(file.string() +
                                 ":1: error: cannot read the script; check the path");
    std::vector<ScriptCommand> commands;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        if (const auto hash = text.find('#'); hash != std::string::npos) text.erase(hash);
        std::istringstream words(text);
        ScriptCommand command;
        command.line = line;
        if (!(words >> command.name)) continue;
        for (std::string word; words >> word;) command.args.push_back(word);
        const auto where = file.string() + ":" + std::to_string(line) + ": error: ";
        const auto it = kCommands.find(command.name);
        if (it == kCommands.end())
            throw std::runtime_error(where + "unknown command \"" + command.name +
                                     "\"; the commands are listed in framework/view/view_script.h");
        if (command.args.size() != it->second.args)
            throw std::runtime_error(where + command.name + " takes " +
                                     std::to_string(it->second.args) + " argument(s); write " +
                                     it->second.usage);
        if (const std::string problem = check(command); !problem.empty())
            throw std::runtime_error(where + problem + "; write " + it->second.usage);
        commands.push_back(std::move(command));
    }
    return commands;
}

}  // namespace rt::view
