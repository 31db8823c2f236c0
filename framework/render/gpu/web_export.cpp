#include "render/gpu/web_export.h"

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "core/base64.h"
#include "core/source_dir.h"
#include "core/text_file.h"
#include "gpu/shader_constants.h"
#include "render/camera_ray.h"
#include "render/gpu/gpu_render.h"
#include "render/gpu/shadertoy_export.h"
#include "render/prepare.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

// A file the page is made of: its template and scripts (render/gpu/web/), beside this file.
std::string read_page_file(const std::string& name) {
    const fs::path file = source_dir() / "framework/render/gpu/web" / name;
    std::string text;
    if (!read_text_if(file, text))
        throw GpuError(display_path(file) + ": cannot read this part of the page");
    return text;
}

// The CPU render as a data URL, through the framework's PNG writer (a temporary file: it writes
// files only).
std::string png_data_url(const Image8& image) {
    if (image.data.empty()) return "";
    const fs::path file =
        fs::temp_directory_path() / ("rt-export-web-" + std::to_string(getpid()) + ".png");
    write_image8(image, file);
    const std::string bytes = read_text(file);
    fs::remove(file);
    return "data:image/png;base64," + base64(bytes);
}

// What the page's shader is compiled for: every mode (depth and bvh_visits mapped by the page's
// second pass, page_ranges.js), with shaded's code and shadows in it, so that each setting of the
// panel has its code; or, when the scene cannot be shaded here (stage 10), the requested mode
// alone.
struct PageShader {
    ShadertoyExport shader;
    std::vector<RenderMode> modes;
};

// Stage 10's camera samples a draw of the page adds (as trace.comp's dispatches do): a few, so
// that a slow GPU still answers between draws.
constexpr int kWebSamplesPerFrame = 4;

// The page's shader reads meshes, BVHs and images from data textures (render/gpu/web_arrays.h).
const ShadertoyOptions kWeb{.web_page = true};

PageShader page_shader(const PreparedScene& scene, RenderMode mode) {
    ShadertoyExport requested = export_shadertoy(scene, mode, kWeb);  // its refusals: the page's
    PreparedScene every = scene;
    every.shadows = true;
    refresh_features(every);
    std::vector<RenderMode> modes = {RenderMode::Directions, RenderMode::Normals,
                                     RenderMode::PrimitiveId, RenderMode::Depth};
    if (scene.accelerator == Accelerator::Bvh && scene.bvh.built())
        modes.push_back(RenderMode::BvhVisits);
    modes.push_back(RenderMode::Shaded);
    try {
        return {export_shadertoy(every, RenderMode::Shaded, kWeb), modes};
    } catch (const GpuError&) {
        return {std::move(requested), {mode}};
    }
}

// For each mode, scene_features with shadows off and on, refraction off and on (index 2 * shadows
// + refraction), as gpu_feature_bits gives them for the scene the viewer makes of those settings.
nlohmann::json feature_bits(const PreparedScene& scene, const std::vector<RenderMode>& modes) {
    nlohmann::json bits = nlohmann::json::object();
    for (RenderMode m : modes) {
        nlohmann::json four = nlohmann::json::array();
        for (int k = 0; k < 4; ++k) {
            PreparedScene copy = scene;
            copy.shadows = k >= 2;
            switch_off_terms(copy, {.refraction = (k & 1) != 0});
            refresh_features(copy);
            four.push_back(gpu_feature_bits(copy, m));
        }
        bits[to_string(m)] = four;
    }
    return bits;
}

// What the page's panel starts with: the scene file's settings, every term on.
nlohmann::json page_settings(const PreparedScene& scene, RenderMode mode,
                             const std::vector<RenderMode>& modes) {
    nlohmann::json mode_names = nlohmann::json::array();
    for (RenderMode m : modes) mode_names.push_back({{"name", to_string(m)}, {"value", int(m)}});
    nlohmann::json terms = nlohmann::json::array();
    // Bit i of the page's rt_terms_off is kTermNames[i] (gpu::TermBit, shaders/page_terms.glsl).
    static_assert(std::size(kTermNames) == gpu::kTermCount);
    for (const char* name : kTermNames) terms.push_back(name);
    return {{"modes", mode_names},
            {"shaded", int(RenderMode::Shaded)},
            {"terms", terms},
            {"has_environment", scene.environment.kind != EnvironmentKind::None},
            {"feature_bits", feature_bits(scene, modes)},
            {"max_depth", gpu_trace_depth(scene, RenderMode::Shaded)},
            {"initial",
             {{"mode", to_string(mode)},
              {"shadows", scene.shadows},
              {"fresnel", scene.fresnel},
              {"max_depth", gpu_trace_depth(scene, RenderMode::Shaded)}}}};
}

// The data textures, as page.js uploads them: RGBA32UI, kDataTextureWidth texels a row (fewer
// when the array is shorter), the words as little-endian bytes in base64.
nlohmann::json data_textures(const std::vector<DataArray>& arrays) {
    nlohmann::json out = nlohmann::json::array();
    for (const DataArray& a : arrays) {
        const std::size_t texels = a.words.size() / 4;
        const std::size_t width = std::min<std::size_t>(texels, kDataTextureWidth);
        const std::string bytes(reinterpret_cast<const char*>(a.words.data()), a.words.size() * 4);
        out.push_back({{"name", a.name},
                       {"width", width},
                       {"height", (texels + width - 1) / width},
                       {"base64", base64(bytes)}});
    }
    return out;
}

// Stage 10: how the page accumulates camera samples (render/gpu/web/page_samples.js), and the
// bytes of the uniform block SampledScene (as rt render --gpu uploads them); null for other scenes.
nlohmann::json sampled_settings(const PreparedScene& scene, RenderMode mode) {
    if (mode != RenderMode::Shaded || !scene.features.sampled()) return nullptr;
    const std::vector<unsigned char> block =
        gpu::sampled_block(gpu::pack_scene(scene), std::max(1, int(scene.area_lights.size())),
                           std::max(1, int(scene.moving_spheres.size())));
    return {{"samples_per_pixel", std::max(1, scene.sampling.samples_per_pixel)},
            {"samples_per_frame", kWebSamplesPerFrame},
            {"block", base64(std::string(block.begin(), block.end()))}};
}

// Where each line of the page's shader came from, for page.js to name the student's file and line
// in a compile error (as shadertoy_run.cpp's with_source_lines does for glslang's): the lines the
// wrapper puts first, and runs [first line of the export, file, its line, line count] of
// consecutive lines of one file; the export's own lines (the scene's constants) are in none.
nlohmann::json source_lines(const ShadertoyExport& shader) {
    nlohmann::json runs = nlohmann::json::array();
    std::string file;
    long next = -1;  // the file line that would continue the last run
    for (std::size_t i = 0; i < shader.line_origins.size(); ++i) {
        const std::string& origin = shader.line_origins[i];
        const std::size_t colon = origin.rfind(':');
        if (colon == std::string::npos) {
            next = -1;
            continue;
        }
        const long line = std::stol(origin.substr(colon + 1));
        if (line == next && origin.compare(0, colon, file) == 0) {
            runs.back()[3] = runs.back()[3].get<long>() + 1;
        } else {
            file = origin.substr(0, colon);
            runs.push_back({long(i) + 1, file, line, 1});
        }
        next = line + 1;
    }
    return {{"head", shadertoy_wrapper_head_lines()}, {"runs", runs}};
}

// What page.js reads: the size, the camera (floats written as doubles, so they read back exact),
// the panel's settings, the stubs (to name the one a magenta pixel reached) and the reference.
nlohmann::json page_data(const PreparedScene& scene, RenderMode mode, const PageShader& shader,
                         const Image8& reference) {
    const Camera& c = scene.camera;
    auto v3 = [](const Vec3& v) {
        return nlohmann::json::array({float(v.x), float(v.y), float(v.z)});
    };
    nlohmann::json data = {{"scene", public_scene_name(scene.source)},
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
                           {"settings", page_settings(scene, mode, shader.modes)},
                           {"stubs", nlohmann::json::array()},
                           {"source_lines", source_lines(shader.shader)},
                           {"data_textures", data_textures(shader.shader.data_arrays)},
                           {"sampled", sampled_settings(scene, mode)},
                           {"reference", png_data_url(reference)}};
    for (const ShaderStub& s : shader.shader.stubs)
        data["stubs"].push_back({{"function", s.function},
                                 {"file", s.file},
                                 {"line", s.line},
                                 {"handout", s.handout},
                                 {"loop", s.loop}});
    return data;
}

void replace_once(std::string& text, const std::string& key, const std::string& value) {
    const std::size_t at = text.find(key);
    if (at == std::string::npos) throw GpuError("framework/render/gpu/web/page.html lacks " + key);
    text.replace(at, key.size(), value);
}

// Text inside <script> ends at the first "</script": the JSON escapes "</" as "<\/"; the GLSL
// holds none (a comment could, in a student's file: then say so).
std::string script_safe(std::string text, bool json) {
    for (std::size_t at = 0; (at = text.find("</", at)) != std::string::npos; at += 3) {
        if (!json)
            throw GpuError(
                "the shader holds \"</\", which would end the page's "
                "<script>; remove it from the GLSL (a comment?)");
        text.replace(at, 2, "<\\/");
    }
    return text;
}

}  // namespace

std::string export_web_page(const PreparedScene& scene, RenderMode mode, const Image8& reference) {
    const PageShader shader = page_shader(scene, mode);
    std::string page = read_page_file("page.html");
    const std::string title = scene.source.empty() ? "A scene" : fs::path(scene.source).stem();
    replace_once(page, "@RT_TITLE@", title);
    replace_once(page, "@RT_SHADER@", script_safe(wrap_shadertoy_export(shader.shader), false));
    replace_once(page, "@RT_DATA@",
                 script_safe(page_data(scene, mode, shader, reference).dump(), true));
    replace_once(page, "@RT_SCRIPT@",
                 read_page_file("page_camera.js") + read_page_file("page_controls.js") +
                     read_page_file("page_samples.js") + read_page_file("page_ranges.js") +
                     read_page_file("page.js"));
    return page;
}

}  // namespace rt
