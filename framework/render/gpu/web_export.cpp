#include "render/gpu/web_export.h"

#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/source_dir.h"
#include "render/camera_ray.h"
#include "render/gpu/gpu_render.h"
#include "render/gpu/shadertoy_export.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

std::string read_page_file(const std::string& name) {
    const fs::path file = source_dir() / "shaders/web" / name;
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    if (!(in && text << in.rdbuf()))
        throw GpuError(display_path(file) + ": cannot read the page template");
    return text.str();
}

std::string base64(const std::string& bytes) {
    static const char* const digits =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        unsigned v = 0;
        for (std::size_t k = 0; k < 3; ++k)
            v = v << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? digits[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// The CPU render as a data URL, through the framework's PNG writer (a temporary file: it writes
// files only).
std::string png_data_url(const Image8& image) {
    if (image.data.empty()) return "";
    const fs::path file =
        fs::temp_directory_path() / ("rt-export-web-" + std::to_string(getpid()) + ".png");
    write_image8(image, file);
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    fs::remove(file);
    return "data:image/png;base64," + base64(bytes.str());
}

// The export with its baked camera as a uniform of the same name and struct, which the page sets
// from the scene's camera for the first frame (the same floats) and moves when the mouse orbits.
std::string shader_with_camera_uniform(const ShadertoyExport& shader) {
    std::string text = wrap_shadertoy_export(shader);
    const std::string baked = "\nconst Camera camera = ";
    const std::size_t at = text.find(baked);
    if (at == std::string::npos)
        throw GpuError("rt: error: the Shadertoy export bakes no camera to make a uniform of");
    text.replace(at + 1, text.find('\n', at + 1) - at - 1, "uniform Camera camera;");
    return text;
}

// What page.js reads: the size, the camera (floats written as doubles, so they read back exact),
// the stubs (to name the one a magenta pixel reached) and the reference image.
nlohmann::json page_data(const PreparedScene& scene, RenderMode mode, const ShadertoyExport& shader,
                         const Image8& reference) {
    const Camera& c = scene.camera;
    auto v3 = [](const Vec3& v) {
        return nlohmann::json::array({float(v.x), float(v.y), float(v.z)});
    };
    nlohmann::json data = {{"scene", scene.source.empty() ? "a scene" : display_path(scene.source)},
                           {"mode", to_string(mode)},
                           {"width", scene.image.width},
                           {"height", scene.image.height},
                           {"camera",
                            {{"projection", int(c.projection)},
                             {"eye", v3(c.eye)},
                             {"u", v3(c.u)},
                             {"v", v3(c.v)},
                             {"w", v3(c.w)},
                             {"vertical_fov_degrees", float(c.vertical_fov_degrees)},
                             {"view_height", float(c.view_height)}}},
                           {"pivot_distance", float(orbit_pivot_distance(scene))},
                           {"stubs", nlohmann::json::array()},
                           {"reference", png_data_url(reference)}};
    for (const ShaderStub& s : shader.stubs)
        data["stubs"].push_back({{"function", s.function},
                                 {"file", s.file},
                                 {"line", s.line},
                                 {"handout", s.handout},
                                 {"loop", s.loop}});
    return data;
}

void replace_once(std::string& text, const std::string& key, const std::string& value) {
    const std::size_t at = text.find(key);
    if (at == std::string::npos) throw GpuError("rt: error: shaders/web/page.html lacks " + key);
    text.replace(at, key.size(), value);
}

// Text inside <script> ends at the first "</script": the JSON escapes "</" as "<\/"; the GLSL
// holds none (a comment could, in a student's file: then say so).
std::string script_safe(std::string text, bool json) {
    for (std::size_t at = 0; (at = text.find("</", at)) != std::string::npos; at += 3) {
        if (!json)
            throw GpuError(
                "rt: error: the shader holds \"</\", which would end the page's "
                "<script>; remove it from the GLSL (a comment?)");
        text.replace(at, 2, "<\\/");
    }
    return text;
}

}  // namespace

std::string export_web_page(const PreparedScene& scene, RenderMode mode, const Image8& reference) {
    const ShadertoyExport shader = export_shadertoy(scene, mode);
    std::string page = read_page_file("page.html");
    const std::string title = scene.source.empty() ? "A scene" : fs::path(scene.source).stem();
    replace_once(page, "@RT_TITLE@", title);
    replace_once(page, "@RT_SHADER@", script_safe(shader_with_camera_uniform(shader), false));
    replace_once(page, "@RT_DATA@",
                 script_safe(page_data(scene, mode, shader, reference).dump(), true));
    replace_once(page, "@RT_SCRIPT@", read_page_file("page.js"));
    return page;
}

}  // namespace rt
