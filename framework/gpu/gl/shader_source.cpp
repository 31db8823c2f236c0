#include "gpu/gl/shader_source.h"

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include "core/source_dir.h"
#include "core/text_file.h"
#include "gpu/shader_constants.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

// The names of `#ifdef NAME` or `#if defined(A) || defined(B) ...`; empty for any other line.
std::vector<std::string> guard_names(const std::string& line) {
    static const std::regex ifdef_re(R"(^\s*#\s*ifdef\s+(\w+)\s*$)");
    static const std::regex if_re(
        R"(^\s*#\s*if\s+defined\s*\(\s*\w+\s*\)(\s*\|\|\s*defined\s*\(\s*\w+\s*\))*\s*$)");
    static const std::regex name_re(R"(defined\s*\(\s*(\w+)\s*\))");
    std::smatch m;
    if (std::regex_match(line, m, ifdef_re)) return {m[1].str()};
    std::vector<std::string> names;
    if (std::regex_match(line, if_re))
        for (std::sregex_iterator it(line.begin(), line.end(), name_re), end; it != end; ++it)
            names.push_back((*it)[1].str());
    return names;
}

std::string trim_left(const std::string& s) {
    const std::size_t i = s.find_first_not_of(" \t");
    return i == std::string::npos ? "" : s.substr(i);
}

// Mesa 22 reports every message as source string 0 whatever #line says, so the file is also
// encoded in the line number: file k's line n is line k * kFileLines + n.
constexpr int kFileLines = 100000;

// Whether `defines` (lines of "#define NAME [value]") defines `name`.
bool defined(const std::string& defines, const std::string& name) {
    std::istringstream lines(defines);
    std::string line;
    static const std::regex define_re(R"(^\s*#\s*define\s+(\w+).*$)");
    std::smatch m;
    while (std::getline(lines, line))
        if (std::regex_match(line, m, define_re) && m[1] == name) return true;
    return false;
}

std::string line_directive(int line, int file) {
    return "#line " + std::to_string(file * kFileLines + line) + " " + std::to_string(file) + "\n";
}

class Assembler {
  public:
    Assembler(const std::vector<fs::path>& dirs, AssembledShader& out) : dirs_(dirs), out_(out) {}

    // Appends `path` (source string `id`); false when an include failed (out_.error set).
    bool add(const fs::path& path, const std::string& defines, bool entry) {
        std::string text;
        if (!read_text_if(path, text)) {
            out_.error = display_path(path) + ": cannot read the shader file";
            return false;
        }
        const int id = int(out_.files.size());
        out_.files.push_back(display_path(path));
        included_.insert(fs::weakly_canonical(path));
        if (!entry) out_.text += line_directive(1, id);
        std::istringstream lines(text);
        std::string line, function;
        std::vector<std::string> guard;  // the names of the #ifdef or #if defined(..) || .. above
        int number = 0;
        static const std::regex include_re(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re");
        static const std::regex function_re(R"(^[A-Za-z_]\w*\s+([A-Za-z_]\w*)\s*\([^;]*$)");
        while (std::getline(lines, line)) {
            ++number;
            std::smatch m;
            if (entry && number == 1 && line.starts_with("#version")) {
                out_.text += line + "\n" + gpu::shader_prelude() + defines;
                out_.text += line_directive(number + 1, id);
                continue;
            }
            if (std::regex_match(line, m, include_re)) {
                // An include right under `#ifdef NAME` (or `#if defined(A) || defined(B)`) is left
                // out unless the host defines one of the names: its file (and its stubs) belong
                // to those features only.
                if (!wanted(guard, defines)) {
                    out_.text += "// " + trim_left(line) + ": not included (no " + guard[0] +
                                 (guard.size() > 1 ? " or the others" : "") + ")\n";
                    continue;
                }
                const fs::path found = find(path.parent_path(), m[1].str());
                if (found.empty()) {
                    out_.error = out_.files[std::size_t(id)] + ":" + std::to_string(number) +
                                 ": error: include \"" + m[1].str() +
                                 "\" not found beside the file or in the shader folders";
                    return false;
                }
                if (!included_.contains(fs::weakly_canonical(found)) && !add(found, defines, false))
                    return false;
                out_.text += line_directive(number + 1, id);
                continue;
            }
            // A #define right under a guard (trace.glsl's HAS_MAPS) counts when the guard holds;
            // one elsewhere always (a guess on the safe side: the file is then included).
            static const std::regex define_re(R"(^\s*#\s*define\s+(\w+).*$)");
            if (std::regex_match(line, m, define_re) && wanted(guard, defines))
                derived_.insert(m[1].str());
            guard = guard_names(line);
            if (std::regex_search(line, m, function_re) && line[0] != ' ') function = m[1].str();
            if (!list_stubs_and_loops(line, function, id, number)) return false;
            out_.text += line + "\n";
        }
        return true;
    }

  private:
    // Lists a stub (`RT_NOT_IMPLEMENTED();  // section`) or a `while` loop on this line, by the number
    // __LINE__ has there, for rt_stub_index (student_checks.glsl); the line itself is left as
    // written. False, with out_.error set, for a do-while loop, which the `while` macro would make
    // into a syntax error.
    bool list_stubs_and_loops(const std::string& line, const std::string& function, int id,
                              int number) {
        static const std::regex stub_re(R"(RT_NOT_IMPLEMENTED\(\s*\)\s*;?\s*(//\s*(\S+))?)");
        static const std::regex while_re(R"(\bwhile\s*\()");
        static const std::regex do_re(R"((^|[^\w])do\s*(\{|$))");
        const std::string code = line.substr(0, line.find("//"));
        if (trim_left(code).starts_with("#")) return true;  // a directive, such as the macros'
        const std::string& file = out_.files[std::size_t(id)];
        const long key = long(id) * kFileLines + number;
        std::smatch m;
        if (code.find("RT_NOT_IMPLEMENTED") != std::string::npos &&
            std::regex_search(line, m, stub_re))
            out_.stubs.push_back({function, file, number,
                                  m[2].matched ? m[2].str() : "this stage's README.md", false,
                                  key});
        if (std::regex_search(code, do_re)) {
            out_.error = file + ":" + std::to_string(number) +
                         ": error: a do-while loop; write it as a while loop, which the framework "
                         "guards against running forever (stages/09-gpu/README.md#what-changes-on-"
                         "a-gpu)";
            return false;
        }
        if (open_loop_ >= 0) {  // a while head that did not close on its line: its next line
            out_.stubs[std::size_t(open_loop_)].lines += 1;
            open_depth_ += paren_depth(code);
            if (open_depth_ <= 0) open_loop_ = -1;
        } else if (std::regex_search(code, m, while_re)) {
            out_.stubs.push_back({function, file, number,
                                  "stages/09-gpu/README.md#what-changes-on-a-gpu", true, key});
            // GLSL's __LINE__ in a macro call that spans lines may be any of them (Mesa's is the
            // last): the entry covers the whole head.
            open_depth_ = paren_depth(code.substr(std::size_t(m.position(0))));
            if (open_depth_ > 0) open_loop_ = int(out_.stubs.size()) - 1;
        }
        return true;
    }

    // Opening minus closing parentheses.
    static int paren_depth(const std::string& code) {
        return int(std::count(code.begin(), code.end(), '(')) -
               int(std::count(code.begin(), code.end(), ')'));
    }

    // Whether a guard (guard_names) holds: one of its names is defined by the host's `defines`
    // or by a #define of the shader seen so far. No guard: true.
    bool wanted(const std::vector<std::string>& guard, const std::string& defines) const {
        return guard.empty() || std::any_of(guard.begin(), guard.end(), [&](const std::string& n) {
                   return defined(defines, n) || derived_.contains(n);
               });
    }

    fs::path find(const fs::path& beside, const std::string& name) const {
        if (fs::is_regular_file(beside / name)) return beside / name;
        for (const fs::path& dir : dirs_)
            if (fs::is_regular_file(dir / name)) return dir / name;
        return {};
    }

    const std::vector<fs::path>& dirs_;
    AssembledShader& out_;
    std::set<fs::path> included_;
    std::set<std::string> derived_;  // names the shader #defines itself
    int open_loop_ = -1;             // the stub entry of a while head still open, or -1
    int open_depth_ = 0;             // its parentheses still open
};

}  // namespace

AssembledShader assemble_shader(const fs::path& entry, const std::vector<fs::path>& include_dirs,
                                const std::string& defines) {
    AssembledShader out;
    if (!Assembler(include_dirs, out).add(entry, defines, true)) return out;
    out.code_size = out.text.size();
    std::vector<long> lines;
    for (const ShaderStub& stub : out.stubs) lines.push_back(stub.key);
    out.text += stub_index_function(out.stubs, lines);
    return out;
}

std::string stub_index_function(const std::vector<ShaderStub>& stubs,
                                const std::vector<long>& lines) {
    std::string text =
        "\n// The stubs and loops the host listed (framework/gpu/gl/shader_source.h).\n"
        "int rt_stub_index(int line) {\n";
    for (std::size_t k = 0; k < stubs.size() && k < lines.size(); ++k) {
        if (lines[k] <= 0) continue;
        const std::string first = std::to_string(lines[k]);
        const std::string where = stubs[k].lines == 1 ? "line == " + first
                                                      : "line >= " + first + " && line < " + first +
                                                            " + " + std::to_string(stubs[k].lines);
        text += "    if (" + where + ") return " + std::to_string(k) + ";  // " + stubs[k].file +
                ":" + std::to_string(stubs[k].line) + "\n";
    }
    return text + "    return -1;\n}\n";
}

std::string display_path(const fs::path& path) {
    const fs::path absolute = fs::weakly_canonical(path);
    const fs::path root = fs::weakly_canonical(source_dir());
    const fs::path relative = absolute.lexically_relative(root);
    if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
    return absolute.generic_string();
}

ShaderLocation shader_location(long line, const std::vector<std::string>& files,
                               std::size_t source_string) {
    const std::size_t i = line >= kFileLines ? std::size_t(line / kFileLines) : source_string;
    return {i < files.size() ? files[i] : "source " + std::to_string(i), int(line % kFileLines)};
}

std::string map_compile_log(const std::string& log, const std::vector<std::string>& files) {
    static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\): (.*)$)");
    static const std::regex glslang(R"(^(ERROR|WARNING): (\d+):(\d+): (.*)$)");
    // "file:line" of a (source string, line) pair; the line number carries the file.
    auto where = [&](const std::string& k, const std::string& l) {
        const ShaderLocation at = shader_location(std::stol(l), files, std::stoul(k));
        return at.file + ":" + std::to_string(at.line);
    };
    std::istringstream lines(log);
    std::string line, out;
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_match(line, m, mesa))
            line = where(m[1], m[2]) + ":" + m[3].str() + ": " + m[4].str();
        else if (std::regex_match(line, m, glslang))
            line =
                where(m[2], m[3]) + ": " + (m[1] == "ERROR" ? "error: " : "warning: ") + m[4].str();
        if (!line.empty()) out += line + "\n";
    }
    return out;
}

}  // namespace rt
