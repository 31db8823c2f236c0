// Shadertoy's wrapper, glslangValidator and a headless draw around an export (shadertoy_run.h).
#include "render/gpu/shadertoy_run.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <vector>

#include "core/not_implemented.h"
#include "gpu/gl/compute_program.h"
#include "gpu/gl/gl_context.h"
#include "gpu/shader_constants.h"
#include "render/gpu/shadertoy_export.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

// A compiler's log of the wrapped export with each line number it names ("ERROR: x.frag:379:"
// from glslang, "0:379(12):" from Mesa) replaced by the student's file and line it came from,
// or by "the export's line N" for the scene's constants: the wrapped file is gone by now.
std::string with_source_lines(const std::string& log, const ShadertoyExport& shader) {
    static const std::regex line_re(R"((?:[^\s:]*\.frag|\b0):(\d+))");
    const long head = shadertoy_wrapper_head_lines();
    std::string out;
    auto from = log.cbegin();
    for (std::sregex_iterator it(log.begin(), log.end(), line_re), end; it != end; ++it) {
        out.append(from, (*it)[0].first);
        const long line = std::stol((*it)[1]) - head;  // 1-based, in the export
        const bool known = line >= 1 && std::size_t(line) <= shader.line_origins.size();
        const std::string& origin = known ? shader.line_origins[line - 1] : std::string();
        out += !origin.empty() ? origin : "the export's line " + std::to_string(line);
        from = (*it)[0].second;
    }
    return out.append(from, log.cend());
}

// glslangValidator's verdict on the wrapped export: "" when it compiles.
std::string glslang_errors(const std::string& wrapped, const ShadertoyExport& shader) {
    if (std::system("glslangValidator --version > /dev/null 2>&1") != 0)
        return "glslangValidator not installed (apt-get install glslang-tools)";
    const fs::path file =
        fs::temp_directory_path() / ("rt-shadertoy-" + std::to_string(getpid()) + ".frag");
    std::ofstream(file, std::ios::binary) << wrapped;
    const fs::path log = file.string() + ".log";
    const int status = std::system(
        ("glslangValidator '" + file.string() + "' > '" + log.string() + "' 2>&1").c_str());
    std::ifstream in(log);
    std::ostringstream text;
    text << in.rdbuf();
    fs::remove(file);
    fs::remove(log);
    if (status == 0) return "";
    std::string errors = text.str();  // without the line naming the wrapped file, which is gone
    if (errors.starts_with(file.string() + "\n")) errors.erase(0, file.string().size() + 1);
    return with_source_lines(errors, shader);
}

// Reports each stub a pixel reached, once, as the compute path does (render/gpu/gpu_render.cpp).
void report_export_stubs(const ShadertoyExport& shader, const std::vector<std::uint8_t>& rgba) {
    static std::map<std::string, std::unique_ptr<std::atomic<bool>>> reported;
    for (std::size_t i = 3; i < rgba.size(); i += 4) {
        if (rgba[i] == 255 || rgba[i] >= shader.stubs.size()) continue;
        const ShaderStub& s = shader.stubs[rgba[i]];
        auto& once = reported[s.file + ":" + std::to_string(s.line)];
        if (!once) once = std::make_unique<std::atomic<bool>>(false);
        if (s.loop)
            report_endless_loop(s.file.c_str(), s.line, gpu::kLoopLimit, *once);
        else
            report_not_implemented(s.function.c_str(), s.file.c_str(), s.line, s.handout.c_str(),
                                   *once);
    }
}

}  // namespace

ShadertoyRun run_shadertoy_export(const PreparedScene& scene, RenderMode mode) {
    const ShadertoyExport shader = export_shadertoy(scene, mode);
    const std::string wrapped = wrap_shadertoy_export(shader);
    ShadertoyRun run;
    run.compile_errors = glslang_errors(wrapped, shader);
    const std::unique_ptr<GlContext> context = GlContext::create(GlKind::Egl, run.draw_error);
    if (!context) return run;
    const int width = scene.image.width, height = scene.image.height;
    std::vector<std::uint8_t> rgba;
    run.draw_error = with_source_lines(
        draw_fragment_shader(context->gl(), wrapped, width, height, rgba), shader);
    if (!run.draw_error.empty()) return run;
    report_export_stubs(shader, rgba);
    run.image = {width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 3)};
    for (std::size_t i = 0; i < run.image.data.size(); ++i)
        run.image.data[i] = rgba[i / 3 * 4 + i % 3];
    return run;
}

}  // namespace rt
