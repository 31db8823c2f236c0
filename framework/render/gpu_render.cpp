#include "render/gpu_render.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "core/not_implemented.h"
#include "core/source_dir.h"
#include "gl/compute_program.h"
#include "gpu/gpu_scene.h"
#include "image/image.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

const Color kStubColor{1, 0, 1};
constexpr int kMaxGpuLights = 64;  // visibility is a vec3[MAX_LIGHTS] per invocation

Color display_value(Color v) {
    return Color(srgb_to_linear(v.r), srgb_to_linear(v.g), srgb_to_linear(v.b));
}

// A buffer holding `data`, or 16 zero bytes for an empty array (a binding needs a buffer).
template <typename T>
GLuint upload(const GlApi& gl, int binding, const std::vector<T>& data) {
    GLuint buffer = 0;
    gl.GenBuffers(1, &buffer);
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    static const char zeros[16] = {};
    if (data.empty())
        gl.BufferData(GL_SHADER_STORAGE_BUFFER, sizeof zeros, zeros, GL_STATIC_DRAW);
    else
        gl.BufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(data.size() * sizeof(T)), data.data(),
                      GL_STATIC_DRAW);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(binding), buffer);
    return buffer;
}

void set_uniforms(const GlApi& gl, GLuint program, const Scene& scene, RenderMode mode) {
    auto at = [&](const char* name) { return gl.GetUniformLocation(program, name); };
    auto vec3 = [&](const char* name, const Vec3& v) {
        gl.Uniform3f(at(name), float(v.x), float(v.y), float(v.z));
    };
    const Camera& c = scene.camera;
    gl.Uniform1i(at("camera.projection"), c.projection == Projection::Perspective ? 0 : 1);
    vec3("camera.eye", c.eye), vec3("camera.u", c.u), vec3("camera.v", c.v);
    vec3("camera.w", c.w);
    gl.Uniform1f(at("camera.vertical_fov_degrees"), float(c.vertical_fov_degrees));
    gl.Uniform1f(at("camera.view_height"), float(c.view_height));
    gl.Uniform2i(at("image_size"), scene.image.width, scene.image.height);
    gl.Uniform4i(at("primitive_counts"), int(scene.spheres.size()), int(scene.planes.size()),
                 int(scene.triangles.size()), int(scene.boxes.size()));
    gl.Uniform1i(at("light_count"), int(scene.lights.size()));
    gl.Uniform1i(at("material_count"), int(scene.materials.size()));
    gl.Uniform3f(at("background_colour"), scene.background.r, scene.background.g,
                 scene.background.b);
    gl.Uniform3f(at("ambient_light"), scene.ambient_light.r, scene.ambient_light.g,
                 scene.ambient_light.b);
    gl.Uniform1i(at("fresnel"), scene.fresnel ? 1 : 0);
    gl.Uniform1i(at("render_mode"), int(mode));
}

void check_supported(const Scene& scene, RenderMode mode) {
    const std::string where = scene.source.empty() ? "the scene" : scene.source;
    if (mode == RenderMode::PrimitiveId || mode == RenderMode::BvhVisits)
        throw GpuError(where + ": mode \"" +
                       std::string(mode == RenderMode::PrimitiveId ? "primitive" : "bvh_visits") +
                       "\" is not in the GPU port yet; render it without --gpu");
    if (scene.features.textures || scene.features.normal_maps || scene.features.environment)
        throw GpuError(where +
                       ": textures and environment maps (stages 07-08) are not in the GPU port "
                       "yet; render it without --gpu");
    if (mode == RenderMode::Shaded && scene.features.sampled())
        throw GpuError(where +
                       ": distribution ray tracing (stage 10: several samples per pixel, area "
                       "lights, lens, shutter, glossy or indirect light) is not in the GPU port "
                       "yet; render it without --gpu");
    if (scene.lights.size() > std::size_t(kMaxGpuLights))
        throw GpuError(where + ": " + std::to_string(scene.lights.size()) +
                       " lights; the GPU port takes at most " + std::to_string(kMaxGpuLights));
    if (scene.accelerator == Accelerator::Bvh && !scene.bvh.built())
        throw GpuError(where +
                       ": the scene asks for a BVH and has none (is stage 06's build_bvh a "
                       "stub?); render it with --accelerator none");
}

// Reports each stub whose flag is set, once per process (core/not_implemented.h's message).
void report_stubs(const AssembledShader& shader, const std::uint32_t flags[4]) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<std::atomic<bool>>> reported;
    for (std::size_t k = 0; k < shader.stubs.size() && k < 128; ++k) {
        if (!(flags[k / 32] & (1u << (k % 32)))) continue;
        const ShaderStub& s = shader.stubs[k];
        std::atomic<bool>* once = nullptr;
        {
            std::lock_guard lock(mutex);
            auto& slot = reported[s.file + ":" + std::to_string(s.line)];
            if (!slot) slot = std::make_unique<std::atomic<bool>>(false);
            once = slot.get();
        }
        report_not_implemented(s.function.c_str(), s.file.c_str(), s.line, s.handout.c_str(),
                               *once);
    }
}

}  // namespace

std::string gpu_defines(const Scene& scene, RenderMode mode) {
    std::string d;
    auto define = [&](bool on, const char* name) {
        if (on) d += std::string("#define ") + name + "\n";
    };
    define(!scene.spheres.empty(), "HAS_SPHERES");
    define(!scene.planes.empty(), "HAS_PLANES");
    define(!scene.triangles.empty(), "HAS_TRIANGLES");
    define(!scene.boxes.empty(), "HAS_BOXES");
    define(!scene.normals.empty(), "HAS_VERTEX_NORMALS");
    define(scene.accelerator == Accelerator::Bvh && scene.bvh.built(), "HAS_BVH");
    const bool shaded = mode == RenderMode::Shaded;
    define(shaded && scene.features.shadows, "HAS_SHADOWS");
    define(shaded && scene.features.reflection, "HAS_REFLECTION");
    define(shaded && scene.features.refraction, "HAS_REFRACTION");
    d += "#define MAX_LIGHTS " + std::to_string(std::max<std::size_t>(1, scene.lights.size())) +
         "\n";
    const int depth = shaded ? std::clamp(scene.max_depth, 0, 64) : 0;
    d += "#define MAX_DEPTH " + std::to_string(depth) + "\n";
    return d;
}

AssembledShader assemble_trace_shader(const Scene& scene, RenderMode mode,
                                      const fs::path& student_dir) {
    const fs::path students = student_dir.empty() ? source_dir() / "stages/09-gpu" : student_dir;
    return assemble_shader(source_dir() / "shaders/trace.comp", {students},
                           gpu_defines(scene, mode));
}

Image render_gpu(const Scene& scene, RenderMode mode, const GpuRenderOptions& options) {
    check_supported(scene, mode);
    std::string error;
    std::unique_ptr<GlContext> context = GlContext::create(options.context, error);
    if (!context) throw GpuError("rt: error: " + error);
    if (options.log) *options.log << "gpu: " << context->describe() << "\n";
    const GlApi& gl = context->gl();

    const AssembledShader shader = assemble_trace_shader(scene, mode, options.student_dir);
    const GLuint program = build_compute_program(gl, shader, error);
    if (!program) throw GpuError(error);

    const gpu::GpuScene packed = gpu::pack_scene(scene);
    std::vector<GLuint> buffers = {
        upload(gl, gpu::kSpheres, packed.spheres),
        upload(gl, gpu::kPlanes, packed.planes),
        upload(gl, gpu::kBoxes, packed.boxes),
        upload(gl, gpu::kTriangles, packed.triangles),
        upload(gl, gpu::kPositions, packed.positions),
        upload(gl, gpu::kNormals, packed.normals),
        upload(gl, gpu::kUvs, packed.uvs),
        upload(gl, gpu::kMaterials, packed.materials),
        upload(gl, gpu::kLights, packed.lights),
        upload(gl, gpu::kBvhNodes, packed.bvh_nodes),
        upload(gl, gpu::kBvhPrimitives, packed.bvh_primitives),
        upload(gl, gpu::kTextures, packed.textures),
        upload(gl, gpu::kTextureImages, packed.texture_images),
        upload(gl, gpu::kTexels, packed.texels),
        upload(gl, gpu::kEnvironment, packed.environment),
    };
    // The output: 4 words of stub flags, then one vec4 a pixel.
    const int width = scene.image.width, height = scene.image.height;
    const std::size_t pixel_count = std::size_t(width) * std::size_t(height);
    std::vector<glm::vec4> output(pixel_count + 1, glm::vec4(0));
    buffers.push_back(upload(gl, 15, output));

    gl.UseProgram(program);
    set_uniforms(gl, program, scene, mode);
    gl.DispatchCompute(GLuint((width + 7) / 8), GLuint((height + 7) / 8), 1);
    gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(output.size() * sizeof(glm::vec4)),
                        output.data());
    const GLenum status = gl.GetError();
    gl.DeleteBuffers(GLsizei(buffers.size()), buffers.data());
    gl.DeleteProgram(program);
    if (status != GL_NO_ERROR)
        throw GpuError("gpu: OpenGL error " + std::to_string(status) +
                       " while rendering; rerun with --gl osmesa, or without --gpu");

    std::uint32_t flags[4];
    std::memcpy(flags, &output[0], sizeof flags);
    report_stubs(shader, flags);

    Image image(width, height);
    float near = kInfinity, far = 0;
    for (std::size_t i = 0; i < pixel_count; ++i) {
        const glm::vec4 p = output[i + 1];
        if (p.a == -2.0f) {
            image.pixels[i] = kStubColor;
            continue;
        }
        const Color rgb(p.r, p.g, p.b);
        image.pixels[i] = mode == RenderMode::Shaded ? rgb : display_value(rgb);
        if (p.a >= 0) near = std::min(near, p.a), far = std::max(far, p.a);
    }
    if (mode == RenderMode::Depth) {  // as render.cpp's map_depth: the image's own range
        const float span = far > near ? far - near : 1.0f;
        for (std::size_t i = 0; i < pixel_count; ++i) {
            const float t = output[i + 1].a;
            if (t == -2.0f) continue;
            image.pixels[i] = t < 0 ? Color(0) : display_value(Color(1 - 0.8f * (t - near) / span));
        }
    }
    return image;
}

}  // namespace rt
