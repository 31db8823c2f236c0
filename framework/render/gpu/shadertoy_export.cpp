#include "render/gpu/shadertoy_export.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <regex>
#include <sstream>

#include "core/source_dir.h"
#include "core/text_file.h"
#include "gpu/gpu_scene.h"
#include "gpu/shader_constants.h"
#include "render/gpu/flatten_instances.h"
#include "render/gpu/gpu_render.h"
#include "render/render.h"

namespace fs = std::filesystem;

namespace rt {

// What a published export calls its scene (shadertoy_export.h).
std::string public_scene_name(const std::string& source) {
    if (source.empty()) return "a scene";
    const fs::path path = fs::path(source).lexically_normal();
    fs::path from_stages;
    for (const fs::path& part : path) {
        if (part == "stages") from_stages.clear();
        from_stages /= part;
    }
    const bool in_stages = *from_stages.begin() == "stages";
    return in_stages ? from_stages.generic_string() : path.filename().string();
}

namespace {

// The shortest literal that reads back as exactly `x` (std::to_chars round-trips).
std::string literal(float x) {
    if (!std::isfinite(x))
        throw GpuError("the scene holds a value that is not finite (" + std::to_string(x) +
                       "), which a GLSL constant cannot spell");
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
    std::string s(buffer, end);
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

std::string literal(int x) {
    return std::to_string(x);
}
std::string literal(std::uint32_t x) {
    return std::to_string(x) + "u";
}

// A float whose bits hold an int (gpu_scene.h's int_bits: a material, a light's kind). glslang
// does not fold intBitsToFloat into a constant, so a small non-negative int is written as the
// denormal float of the same bits (its shortest literal reads back exactly).
std::string bits_literal(float x) {
    int bits;
    std::memcpy(&bits, &x, sizeof bits);
    if (bits < 0 || bits >= (1 << 23))
        throw GpuError("an index of " + std::to_string(bits) +
                       " (a material, a light's kind or its linked materials) cannot be baked "
                       "into a constant");
    return literal(x);
}

// "vec4(a, b, c, d)" and the like; `bits_w`: w holds an int's bits.
template <typename V>
std::string vec(const char* type, const V& v, int n, bool bits_w = false) {
    std::string s = std::string(type) + "(";
    for (int i = 0; i < n; ++i)
        s += (i ? ", " : "") + (bits_w && i == 3 ? bits_literal(v[i]) : literal(v[i]));
    return s + ")";
}
std::string v4(const glm::vec4& v, bool bits_w = false) {
    return vec("vec4", v, 4, bits_w);
}
std::string iv4(const glm::ivec4& v) {
    return vec("ivec4", v, 4);
}
std::string v3(const Vec3& v) {
    return "vec3(" + literal(float(v.x)) + ", " + literal(float(v.y)) + ", " + literal(float(v.z)) +
           ")";
}

// The accessors of a GLSL array `name` of `type`s (shaders/scene_buffers.glsl): name_at(i) for
// int and uint indices, as every shader reads the scene's arrays.
std::string array_accessors(const std::string& type, const std::string& name) {
    return type + " " + name + "_at(int i) { return " + name + "[i]; }\n" + type + " " + name +
           "_at(uint i) { return " + name + "[i]; }\n";
}

// How an array is declared: `writable` leaves `const` out (the web page's term switches change
// the materials and the environment); `accessors` adds name_at(i) (all but the moving spheres'
// rest positions, which shadertoy.glsl copies into the moved spheres the accessors read).
struct ArrayForm {
    bool writable = false;
    bool accessors = true;
};

// `const T name[N] = T[N](...)`, one element a line, and its accessors. GLSL has no empty
// arrays: an empty one gets `dummy` (the counts keep the shader from reading it).
template <typename T, typename F>
std::string const_array(const char* type, const char* name, const std::vector<T>& items, F format,
                        const std::string& dummy, ArrayForm form = {}) {
    const std::size_t n = std::max<std::size_t>(1, items.size());
    std::string s = (form.writable ? "" : "const ") + std::string(type) + " " + name + "[" +
                    std::to_string(n) + "] = " + type + "[" + std::to_string(n) + "](\n";
    for (std::size_t i = 0; i < n; ++i)
        s += "    " + (items.empty() ? dummy : format(items[i])) + (i + 1 < n ? ",\n" : ");\n");
    if (form.accessors) s += array_accessors(type, name);
    return s;
}

std::string vec4_item(const glm::vec4& x) {
    return v4(x);
}

// GLSL zeros, for the dummy element of an empty array.
const std::string kZero4 = "vec4(0.0)", kZeroInt4 = "ivec4(0)";

// What trace.comp takes as uniforms, as constants; on a web page, those its panel changes stay
// uniforms (the page sets them from the scene's settings before its first frame).
std::string uniform_constants(const PreparedScene& scene, RenderMode mode, bool page) {
    const Camera& c = scene.camera;
    std::string s = "// The scene (" +
                    (scene.source.empty() ? "built in code" : public_scene_name(scene.source)) +
                    "), as trace.comp reads it from its storage buffers and uniforms.\n";
    if (page)
        s += "uniform Camera camera;\n";
    else
        s += "const Camera camera = Camera(" + literal(int(c.projection)) + ", " + v3(c.eye) +
             ", " + v3(c.u) + ", " + v3(c.v) + ", " + v3(c.w) + ", " +
             literal(float(c.vertical_fov_degrees)) + ", " + literal(float(c.view_height)) + ");\n";
    s += "const ivec4 primitive_counts = ivec4(" + std::to_string(scene.spheres.size()) + ", " +
         std::to_string(scene.planes.size()) + ", " + std::to_string(scene.triangles.size()) +
         ", " + std::to_string(scene.boxes.size()) + ");\n";
    s += "const int light_count = " + std::to_string(scene.lights.size()) + ";\n";
    s += "const int material_count = " + std::to_string(scene.materials.size()) + ";\n";
    s += "const vec3 background_color = " + vec("vec3", scene.background, 3) + ";\n";
    s += "const vec3 ambient_light = " + vec("vec3", scene.ambient_light, 3) + ";\n";
    if (page) {
        s += "uniform bool fresnel;\nuniform int render_mode;\nuniform int max_depth;\n";
        s += "uniform int scene_features;\n";
    } else {
        s += std::string("const bool fresnel = ") + (scene.fresnel ? "true" : "false") + ";\n";
        s += "const int render_mode = " + std::to_string(int(mode)) + ";\n";
        s += "const int max_depth = " + std::to_string(gpu_trace_depth(scene, mode)) + ";\n";
        s += "const int scene_features = " + std::to_string(gpu_feature_bits(scene, mode)) + ";\n";
    }
    s += "const int texture_lookup = " + std::to_string(gpu_texture_lookup(scene)) + ";\n";
    return s;
}

// `const_array`'s text, or nothing for an array the page reads from a data texture.
template <typename F>
std::string unless_data(bool page, const char* name, F text) {
    return page && is_web_data_array(name) ? "" : text();
}

// The geometry arrays: spheres, triangles and their vertices.
std::string geometry_constants(const gpu::GpuScene& g, bool page, bool moving) {
    std::string s;
    s += const_array("Sphere", moving ? "spheres_at_rest" : "spheres", g.spheres,
                     [](const gpu::GpuSphere& x) {
                         return "Sphere(" + v4(x.center_radius) + ", " + iv4(x.material) + ")";
                     },
                     "Sphere(" + kZero4 + ", " + kZeroInt4 + ")", {.accessors = !moving});
    s += unless_data(page, "triangles", [&] {
        return const_array(
            "Triangle", "triangles", g.triangles,
            [](const gpu::GpuTriangle& x) {
                return "Triangle(" + vec("uvec4", x.vertices_material, 4) + ")";
            },
            "Triangle(uvec4(0u))");
    });
    s += unless_data(page, "positions", [&] {
        return const_array("vec4", "positions", g.positions, vec4_item, kZero4);
    });
    s += unless_data(page, "normals",
                     [&] { return const_array("vec4", "normals", g.normals, vec4_item, kZero4); });
    s += unless_data(page, "uvs", [&] {
        return const_array(
            "vec2", "uvs", g.uvs, [](const glm::vec2& x) { return vec("vec2", x, 2); },
            "vec2(0.0)");
    });
    return s;
}

// Materials, the BVH, textures and the environment.
std::string material_constants(const gpu::GpuScene& g, bool page) {
    std::string s;
    s += const_array("Material", "materials", g.materials,
                     [](const gpu::GpuMaterial& m) {
                         std::string t = "Material(" + v4(m.ambient) + ", " + v4(m.diffuse) + ", " +
                                         v4(m.specular_shininess) + ", " + v4(m.emissive) + ", " +
                                         v4(m.reflective) + ", " + v4(m.transmissive_ior) + ", " +
                                         iv4(m.maps) + ", vec4[4](";
                         for (int i = 0; i < 4; ++i)
                             t += v4(m.map_transform[i]) + (i < 3 ? ", " : "))");
                         return t;
                     },
                     "Material(" + kZero4 + ", " + kZero4 + ", " + kZero4 + ", " + kZero4 + ", " +
                         kZero4 + ", " + kZero4 + ", " + kZeroInt4 + ", vec4[4](" + kZero4 + ", " +
                         kZero4 + ", " + kZero4 + ", " + kZero4 + "))",
                     {.writable = page});
    s += unless_data(page, "bvh_nodes", [&] {
        return const_array(
            "BvhNode", "bvh_nodes", g.bvh_nodes,
            [](const BvhNode& n) {
                return "BvhNode(" + vec("vec3", n.min, 3) + ", " + literal(n.first) + ", " +
                       vec("vec3", n.max, 3) + ", " + literal(n.count) + ")";
            },
            "BvhNode(vec3(0.0), 0u, vec3(0.0), 0u)");
    });
    s += unless_data(page, "bvh_primitives", [&] {
        return const_array(
            "uint", "bvh_primitives", g.bvh_primitives, [](std::uint32_t x) { return literal(x); },
            "0u");
    });
    s += const_array(
        "Texture", "textures", g.textures,
        [](const gpu::GpuTexture& t) {
            return "Texture(" + iv4(t.kind_image_filter_wrap) + ", " + v4(t.a_srgb) + ", " +
                   v4(t.b_scale) + ")";
        },
        "Texture(" + kZeroInt4 + ", " + kZero4 + ", " + kZero4 + ")");
    s += unless_data(page, "texture_images", [&] {
        return const_array(
            "TextureImage", "texture_images", g.texture_images,
            [](const gpu::GpuTextureImage& t) {
                return "TextureImage(" + iv4(t.width_height_first) + ")";
            },
            "TextureImage(" + kZeroInt4 + ")");
    });
    s += unless_data(page, "texels",
                     [&] { return const_array("vec4", "texels", g.texels, vec4_item, kZero4); });
    s += const_array(
        "Environment", "environment", g.environment,
        [](const gpu::GpuEnvironment& e) {
            return "Environment(" + iv4(e.kind_image) + ", " + iv4(e.faces_px_nx_py_ny) + ", " +
                   iv4(e.faces_pz_nz) + ", " + v4(e.intensity_rotate_y) + ")";
        },
        "Environment(" + kZeroInt4 + ", " + kZeroInt4 + ", " + kZeroInt4 + ", " + kZero4 + ")",
        {.writable = page});

    return s;
}

// Planes, boxes and lights (their int fields ride in float bits).
std::string plane_box_light_constants(const gpu::GpuScene& g) {
    std::string s;
    s += const_array(
        "Plane", "planes", g.planes,
        [](const gpu::GpuPlane& p) {
            return "Plane(" + v4(p.point_material, true) + ", " + v4(p.normal) + ")";
        },
        "Plane(" + kZero4 + ", " + kZero4 + ")");
    s += const_array(
        "Box", "boxes", g.boxes,
        [](const gpu::GpuBox& b) {
            return "Box(" + v4(b.min_material, true) + ", " + v4(b.max) + ")";
        },
        "Box(" + kZero4 + ", " + kZero4 + ")");
    s += const_array(
        "Light", "lights", g.lights,
        [](const gpu::GpuLight& l) {
            return "Light(" + v4(l.position_kind, true) + ", " + v4(l.direction, true) + ", " +
                   v4(l.intensity, true) + ", " + v4(l.attenuation) + ")";
        },
        "Light(" + kZero4 + ", " + kZero4 + ", " + kZero4 + ", " + kZero4 + ")");
    return s;
}

std::string scene_constants(const PreparedScene& scene, RenderMode mode, const gpu::GpuScene& g,
                            bool page) {
    // Stage 10 (rt export-web only): the sampled scene's uniform block, which the page fills with
    // gpu::sampled_block's bytes, and the moving spheres' rest positions.
    const bool sampled = page && mode == RenderMode::Shaded && scene.features.sampled();
    const std::string block =
        "layout(std140) uniform SampledScene { Sampling sampling; AreaLight "
        "area_lights[MAX_AREA_LIGHTS]; MovingSphere moving_spheres[MAX_MOVING_SPHERES]; };\n";
    return uniform_constants(scene, mode, page) +
           geometry_constants(g, page, sampled && scene.features.motion_blur) +
           material_constants(g, page) + plane_box_light_constants(g) +
           (page ? web_data_accessors() : "") + (sampled ? block : "");
}

// Shadertoy's GLSL ES 3.00: `#line N K` out (a comment names each file as it starts). ES takes
// `const` only with a constant initialiser, where the course's desktop GLSL marks any local that
// does not change; a `#define const` before the shader's own code drops the qualifier through
// GLSL's preprocessor, so every line stays as written. (The export's constants above it keep
// theirs.) Appends to `out` and, line for line, where each came from to `origins`.
void for_shadertoy(const AssembledShader& shader, std::string& out,
                   std::vector<std::string>& origins) {
    static const std::regex line_re(R"(^#line (\d+) (\d+)$)");
    constexpr long kFileLines = 100000;  // shader_source.cpp's encoding of the file in the line
    out += "#define const  // GLSL ES: const takes constant initialisers only\n";
    origins.push_back("");
    std::istringstream lines(shader.text.substr(0, shader.code_size));
    std::string line, file_name;
    long file_line = 0;
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_match(line, m, line_re)) {
            const std::size_t file = std::stoul(m[2]);
            file_name = file < shader.files.size() ? shader.files[file] : "";
            file_line = std::stol(m[1]) % kFileLines;
            if (file_line == 1 && !file_name.empty()) {
                out += "// ---- " + file_name + " ----\n";
                origins.push_back("");
            }
            continue;
        }
        out += line + "\n";
        origins.push_back(file_name.empty() ? "" : file_name + ":" + std::to_string(file_line));
        ++file_line;
    }
}

// __LINE__ at each stub and loop of the export, as our wrapper (and the web page) compiles it:
// after the wrapper's head. Shadertoy's own head differs, but Shadertoy shows no report anyway.
std::vector<long> export_lines(const std::vector<ShaderStub>& stubs,
                               const std::vector<std::string>& origins) {
    std::vector<long> lines;
    for (const ShaderStub& stub : stubs) {
        const auto at =
            std::find(origins.begin(), origins.end(), stub.file + ":" + std::to_string(stub.line));
        lines.push_back(at == origins.end()
                            ? 0
                            : shadertoy_wrapper_head_lines() + long(at - origins.begin()) + 1);
    }
    return lines;
}

// scene_layout.glsl's structs (the storage buffers are scene_buffers.glsl's; the export's arrays
// are constants with their accessors).
std::string scene_structs() {
    const fs::path file = source_dir() / "shaders/scene_layout.glsl";
    std::string text;
    if (!read_text_if(file, text))
        throw GpuError(display_path(file) + ": cannot read the shader file");
    std::istringstream lines(text);
    std::string line, out;
    while (std::getline(lines, line))
        if (!line.starts_with("layout(")) out += line + "\n";
    return out;
}

void check_exportable(const PreparedScene& scene, RenderMode mode, bool page) {
    const std::string where = scene.source.empty() ? "the scene" : scene.source;
    if (!page && (mode == RenderMode::Depth || mode == RenderMode::BvhVisits))
        throw GpuError(where + ": mode \"" + to_string(mode) +
                       "\" scales each pixel by the whole image's range, which one Shadertoy "
                       "pixel cannot know; export it with --mode normals or --mode shaded");
    if (!page && scene.texels.size() > kMaxShadertoyTexels)
        throw GpuError(where + ": its images hold " + std::to_string(scene.texels.size()) +
                       " texels; Shadertoy cannot load the scene's image files and an export "
                       "bakes at most " +
                       std::to_string(kMaxShadertoyTexels) +
                       " as constants: use a checker or marble texture, or a smaller image");
    if (!page && mode == RenderMode::Shaded && scene.features.sampled())
        throw GpuError(
            where +
            ": stage 10 (several camera samples per pixel, accumulated over "
            "dispatches) is not in the Shadertoy export; render it with rt render --gpu");
    check_gpu_supported(scene, mode);
}

// What Shadertoy puts before the Image tab's code (its uniforms).
const char* const kShadertoyHead =
    "#version 300 es\n"
    "precision highp float;\nprecision highp int;\nprecision mediump sampler3D;\n"
    "uniform vec3 iResolution;\nuniform float iTime;\nuniform float iTimeDelta;\n"
    "uniform float iFrameRate;\nuniform int iFrame;\nuniform float iChannelTime[4];\n"
    "uniform vec3 iChannelResolution[4];\nuniform vec4 iMouse;\nuniform vec4 iDate;\n"
    "uniform float iSampleRate;\nuniform sampler2D iChannel0;\nuniform sampler2D iChannel1;\n"
    "uniform sampler2D iChannel2;\nuniform sampler2D iChannel3;\n";
// A main of our own after the export: calls mainImage, then writes the stub this pixel reached
// as alpha (not Shadertoy's: for the test to report). A web page's applies the term switches
// first (shaders/page_terms.glsl).
std::string main_function(bool page) {
    return std::string("\nout vec4 rt_frag_color;\nvoid main() {\n") +
           (page ? "    rt_apply_terms();\n" : "") +
           "    mainImage(rt_frag_color, gl_FragCoord.xy);\n"
           "    rt_frag_color.a = rt_first_stub >= 0 ? float(rt_first_stub) / 255.0 : 1.0;\n"
           "}\n";
}

}  // namespace

ShadertoyExport export_shadertoy(const PreparedScene& scene, RenderMode mode,
                                 const ShadertoyOptions& options) {
    if (!scene.instances.empty())
        return export_shadertoy(flatten_instances(scene, mode), mode, options);
    check_exportable(scene, mode, options.web_page);
    const fs::path students = options.student_dir.empty() ? gpu_student_dir() : options.student_dir;
    const AssembledShader shader = assemble_shader(
        source_dir() / "shaders/shadertoy.glsl", {students, gpu_sampling_dir(), gpu_path_dir()},
        gpu_defines(scene, mode));  // they decide the guarded includes
    if (!shader.error.empty()) throw GpuError(shader.error);
    const gpu::GpuScene packed = gpu::pack_scene(scene);
    ShadertoyExport out;
    out.text = "// " +
               (scene.source.empty() ? std::string("A scene") : public_scene_name(scene.source)) +
               " in mode " + to_string(mode) +
               ", exported by `rt export-shadertoy` (stages/09-gpu/README.md#publish-on-shadertoy)"
               ".\n// Paste it into Shadertoy's Image tab. The camera keeps the scene's vertical "
               "field of view; the image takes the canvas's shape.\n\n" +
               gpu_defines(scene, mode) + "\n" + gpu::shader_prelude() + scene_structs() + "\n" +
               scene_constants(scene, mode, packed, options.web_page) + "\n";
    out.line_origins.assign(std::count(out.text.begin(), out.text.end(), '\n'), "");
    for_shadertoy(shader, out.text, out.line_origins);
    out.text += stub_index_function(shader.stubs, export_lines(shader.stubs, out.line_origins));
    if (options.web_page) out.data_arrays = web_data_arrays(packed);
    out.web_page = options.web_page;
    if (out.text.size() > kMaxShadertoyBytes)
        throw GpuError((scene.source.empty() ? "the scene" : scene.source) + ": its export " +
                       "would be " + std::to_string(out.text.size() / 1024) +
                       " KB of constants and code, and an export takes at most " +
                       std::to_string(kMaxShadertoyBytes / 1024) +
                       " KB (a browser compiles it all at every load): use fewer triangles");
    out.stubs = shader.stubs;
    return out;
}

std::string wrap_shadertoy_export(const ShadertoyExport& shader) {
    if (!shader.web_page) return kShadertoyHead + shader.text + main_function(false);
    const fs::path terms = source_dir() / "shaders/page_terms.glsl";
    std::string terms_text;
    if (!read_text_if(terms, terms_text))
        throw GpuError(display_path(terms) + ": cannot read the shader file");
    return kShadertoyHead + shader.text + "\n" + terms_text + main_function(true);
}

long shadertoy_wrapper_head_lines() {
    return std::count(kShadertoyHead, kShadertoyHead + std::strlen(kShadertoyHead), '\n');
}

}  // namespace rt
