#include "workspace/object_check.h"

#include <cstring>
#include <sstream>

#include "util.h"

namespace fs = std::filesystem;

namespace rt::grader {

std::vector<std::pair<std::string, std::string>> defined_symbols(const fs::path& file) {
    std::string out;
    run_argv({"/usr/bin/nm", "-g", "--defined-only", "-P", file.string()}, "/", out);
    std::vector<std::pair<std::string, std::string>> symbols;
    std::istringstream lines(out);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string name, type;
        if (!(words >> name >> type) || name.back() == ':' || name.back() == ']') continue;
        symbols.push_back({name, type});
    }
    return symbols;
}

bool strong(const std::string& type) {
    return type == "T" || type == "D" || type == "B" || type == "R" || type == "G" || type == "S";
}

std::string check_and_localize(const fs::path& object, const std::set<std::string>& api,
                               const BuildPlan& plan, const fs::path& out) {
    std::string problems;
    auto demangle = [](const std::string& name) {
        std::string d;
        run_argv({"/usr/bin/c++filt", name}, "/", d);
        while (!d.empty() && d.back() == '\n') d.pop_back();
        return d;
    };
    // Symbols: after localization nothing but the API can take part in symbol resolution, so
    // only what shows intent to replace trusted code is refused (a clear message beats a
    // silently ignored definition); helpers, templates, inline variables, extern "C" helpers and
    // what the compiler emits for exceptions and RTTI are simply made local.
    std::string renames;  // unique globals ('u'): objcopy cannot make them local, so rename
    for (const auto& [name, type] : defined_symbols(object)) {
        if (api.count(name)) continue;
        if (type == "u") renames += name + " rt.student." + name + "\n";
        if (type == "i") {
            problems += "  " + demangle(name) + " (an IFUNC resolver: runs before main)\n";
        } else if (name == "main") {
            problems += "  main (the test runner's main is the grader's)\n";
        } else if (name.find("7testing") != std::string::npos ||
                   name.find("gtest") != std::string::npos) {
            problems += "  " + demangle(name) + " (GoogleTest code)\n";
        } else if (strong(type) && plan.instructor_symbols.count(name)) {
            problems += "  " + demangle(name) + " (defined by the framework or the tests)\n";
        }
    }
    // Sections: code that runs before main must be ordinary constructors (.init_array), which
    // run after the trusted test main has taken its channel.
    std::string text;
    run_argv({"/usr/bin/readelf", "-S", "-W", object.string()}, "/", text);
    std::istringstream sections(text);
    std::string line;
    while (std::getline(sections, line)) {
        const auto open = line.find('[');
        const auto close = line.find("] ", open == std::string::npos ? 0 : open);
        if (open == std::string::npos || close == std::string::npos) continue;
        std::istringstream words(line.substr(close + 2));
        std::string section;
        if (!(words >> section) || section == "Name" || section == "NULL") continue;
        std::string base = section;
        for (const char* rel : {".rela", ".rel"})
            if (base.starts_with(std::string(rel) + ".")) {
                base = base.substr(std::strlen(rel));
                break;
            }
        const bool early = base.starts_with(".init_array.") || base.starts_with(".ctors") ||
                           base.starts_with(".preinit_array") || base == ".init";
        if (early) problems += "  section " + section + " (runs code before main)\n";
    }
    if (!problems.empty()) return problems;
    // Localize all but the API; dissolve COMDAT groups, or the linker would let the student's
    // copy of an inline function stand in for the framework's (groups are merged by name).
    std::string keep;
    for (const auto& s : api) keep += s + "\n";
    const fs::path keep_file = out.string() + ".keep";
    write_text(keep_file, keep);
    const fs::path rename_file = out.string() + ".renames";
    write_text(rename_file, renames);
    std::string log;
    const int code = run_argv({"/usr/bin/objcopy", "--keep-global-symbols=" + keep_file.string(),
                               "--redefine-syms=" + rename_file.string(), "--remove-section=.group",
                               object.string(), out.string()},
                              "/", log);
    if (code != 0) return "  objcopy failed: " + clean_output(log) + "\n";
    return "";
}

}  // namespace rt::grader
