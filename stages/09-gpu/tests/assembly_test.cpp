// The student's GLSL reaches the compiler as written: the assembled compute shader holds every
// line of every student file of stages 09-11 unchanged. Stubs and the guard on `while` loops are
// macros of GLSL's preprocessor (shaders/student_checks.glsl), and the assembler only lists them
// (framework/gpu/gl/shader_source.h): every one it lists is on a line that has one.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "core/source_dir.h"
#include "core/text_file.h"
#include "gpu/gl/shader_source.h"
#include "render/gpu/gpu_render.h"
#include "render/gpu/shadertoy_export.h"
#include "render/prepare.h"
#include "scene/scene_loader.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        lines.push_back(text.substr(start, end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return lines;
}

// The assembled text's lines by the source string (file) each came from, read off its #line
// directives ("#line N K": file K).
std::map<int, std::vector<std::string>> lines_by_file(const std::string& text) {
    static const std::regex directive(R"(^#line \d+ (\d+)$)");
    std::map<int, std::vector<std::string>> files;
    int file = 0;
    for (const std::string& line : split_lines(text)) {
        std::smatch m;
        if (std::regex_match(line, m, directive)) {
            file = std::stoi(m[1]);
            continue;
        }
        files[file].push_back(line);
    }
    return files;
}

// Whether a line (code, not comment) holds a stub's marker or a `while` loop: what the table lists.
int marks(const std::string& line) {
    static const std::regex stub(std::string("RT_NOT_IMPLEMENTED") + R"(\(\s*\))");
    static const std::regex loop(R"(\bwhile\s*\()");
    const std::string code = line.substr(0, line.find("//"));
    return (std::regex_search(code, stub) ? 1 : 0) + (std::regex_search(code, loop) ? 1 : 0);
}

// Every stage's GLSL in one shader: stage 11's path-traced Cornell box, with every feature.
AssembledShader every_student_file() {
    const PreparedScene scene =
        prepare_scene(load_scene(source_dir() / "stages/11-path-tracing/scenes/cornell_box.json"),
                      {.width = 8, .height = 8});
    return assemble_trace_shader(scene, RenderMode::Shaded, {}, /*uber=*/true);
}

// What reached the compiler otherwise than written, one message a line or file; and the number of
// student files looked at.
std::vector<std::string> unexpected_changes(const AssembledShader& shader, int& student_files) {
    std::vector<std::string> problems;
    const std::map<int, std::vector<std::string>> assembled = lines_by_file(shader.text);
    student_files = 0;
    for (std::size_t id = 0; id < shader.files.size(); ++id) {
        const std::string& name = shader.files[id];
        if (name.find("stages/") == std::string::npos) continue;
        ++student_files;
        const std::vector<std::string> written = split_lines(read_text(source_dir() / name));
        const auto found = assembled.find(int(id));
        const std::vector<std::string> compiled =
            found == assembled.end() ? std::vector<std::string>{} : found->second;
        if (compiled.size() != written.size()) {
            problems.push_back(name + ": lines added or dropped");
            continue;
        }
        int marked = 0;
        for (std::size_t k = 0; k < written.size(); ++k) {
            marked += marks(written[k]);
            if (compiled[k] != written[k])
                problems.push_back(name + ":" + std::to_string(k + 1) +
                                   " reached the compiler changed:\n  written:  " + written[k] +
                                   "\n  compiled: " + compiled[k]);
        }
        int listed = 0;
        for (const ShaderStub& stub : shader.stubs)
            listed += stub.file == name && marks(written[std::size_t(stub.line - 1)]) > 0 ? 1 : 0;
        if (marked != listed)
            problems.push_back(name + ": " + std::to_string(marked) + " stubs and loops, " +
                               std::to_string(listed) + " listed in the stub table");
    }
    return problems;
}

TEST(GpuAssembly, StudentFilesReachTheCompilerAsWritten) {
    const AssembledShader shader = every_student_file();
    ASSERT_EQ(shader.error, "");
    int student_files = 0;
    for (const std::string& problem : unexpected_changes(shader, student_files))
        ADD_FAILURE() << problem;
    EXPECT_EQ(student_files, 10) << "stage 09's seven files, stage 10's one, stage 11's two";
}

// The web page's shader (the GLSL ES export in page mode) holds the student's lines as written
// too: each line the export says came from a student file is that line of the file.
TEST(GpuAssembly, StudentFilesReachTheWebPageAsWritten) {
    const PreparedScene scene =
        prepare_scene(load_scene(source_dir() / "stages/11-path-tracing/scenes/cornell_box.json"),
                      {.width = 8, .height = 8});
    const ShadertoyExport page = export_shadertoy(scene, RenderMode::Shaded, {.web_page = true});
    const std::vector<std::string> exported = split_lines(page.text);
    ASSERT_GE(exported.size(), page.line_origins.size());  // the export's own main comes last
    std::map<std::string, std::vector<std::string>> files;
    std::map<std::string, int> compared;  // lines, by file
    for (std::size_t i = 0; i < page.line_origins.size(); ++i) {
        const std::string& origin = page.line_origins[i];
        if (!origin.starts_with("stages/")) continue;
        const std::string name = origin.substr(0, origin.rfind(':'));
        const std::size_t line = std::stoul(origin.substr(origin.rfind(':') + 1));
        if (!files.contains(name)) files[name] = split_lines(read_text(source_dir() / name));
        ASSERT_LE(line, files[name].size()) << origin;
        EXPECT_EQ(exported[i], files[name][line - 1]) << origin << " reached the page changed";
        ++compared[name];
    }
    std::string names;
    for (const auto& [name, lines] : files) names += " " + name;
    // Stage 09's intersect, bvh, camera, shade and recursion, stage 10's sampling, stage 11's
    // bsdf and path: all but textures.glsl and environment.glsl (the box has neither).
    EXPECT_EQ(files.size(), 8u) << names;
    // Every line of each (a starter tree's files are shorter: its stubs).
    for (const auto& [name, lines] : files)
        EXPECT_EQ(compared[name], int(lines.size())) << name << ": lines the page does not hold";
}

// The check catches a rewrite such as the old one of name[i] into name_at(i): the assembled text
// with the first line of the first student file changed (a line every tree has, starter or not).
TEST(GpuAssembly, ARewrittenLineIsCaught) {
    AssembledShader shader = every_student_file();
    std::size_t id = 0;
    while (id < shader.files.size() && shader.files[id].find("stages/") == std::string::npos) ++id;
    ASSERT_LT(id, shader.files.size());
    const std::string directive =
        "#line " + std::to_string(id * 100000 + 1) + " " + std::to_string(id) + "\n";
    const std::size_t at = shader.text.find(directive);
    ASSERT_NE(at, std::string::npos) << directive;
    shader.text.insert(at + directive.size(), "rewritten ");
    int student_files = 0;
    const std::vector<std::string> problems = unexpected_changes(shader, student_files);
    ASSERT_FALSE(problems.empty());
    EXPECT_NE(problems[0].find(shader.files[id] + ":1 reached the compiler changed"),
              std::string::npos)
        << problems[0];
}

}  // namespace
}  // namespace rt
