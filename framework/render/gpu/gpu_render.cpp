#include "render/gpu/gpu_render.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <vector>

#include "core/not_implemented.h"
#include "core/source_dir.h"
#include "gpu/gl/compute_program.h"
#include "gpu/gpu_scene.h"
#include "gpu/shader_constants.h"
#include "image/image.h"
#include "render/gpu/flatten_instances.h"
#include "render/gpu/gpu_debug_pixel.h"
#include "render/gpu/texel_arrays.h"
#include "render/gpu/web_arrays.h"
#include "render/render.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

const Color kStubColor{1, 0, 1};
constexpr int kMaxGpuLights = 64;             // visibility is a vec3[MAX_LIGHTS] per invocation
constexpr int kMaxGpuDepth = kMaxDepthLimit;  // the Frame stack, as deep as the CPU's
// Stage 10: the uniform block's arrays (80 bytes an area light), and the per-invocation copy of
// the spheres a scene with motion blur moves per camera sample (32 bytes a sphere).
constexpr int kMaxGpuAreaLights = 64;
constexpr int kMaxGpuMovingSpheres = 64;
constexpr int kMaxGpuSpheresWithMotion = 64;
constexpr int kDefaultSamplesPerDispatch = 4;

// A stage 10 scene drawn by the sampled path (several camera samples per pixel).
bool gpu_sampled(const PreparedScene& scene, RenderMode mode) {
    return mode == RenderMode::Shaded && scene.features.sampled();
}

// The sizes of the uniform block's arrays (MAX_AREA_LIGHTS, MAX_MOVING_SPHERES): the scene's
// counts, or the largest with --uber on a stage 10 scene.
struct SampledSlots {
    int area_lights, moving_spheres;
};
SampledSlots sampled_slots(const PreparedScene& scene, RenderMode mode, bool uber) {
    if (uber && gpu_sampled(scene, mode)) return {kMaxGpuAreaLights, kMaxGpuMovingSpheres};
    return {std::max(1, int(scene.area_lights.size())),
            std::max(1, int(scene.moving_spheres.size()))};
}

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

void set_uniforms(const GlApi& gl, GLuint program, const PreparedScene& scene, RenderMode mode) {
    auto at = [&](const char* name) { return gl.GetUniformLocation(program, name); };
    auto vec3 = [&](const char* name, const Vec3& v) {
        gl.Uniform3f(at(name), float(v.x), float(v.y), float(v.z));
    };
    const Camera& c = scene.camera;
    gl.Uniform1i(at("camera.projection"), int(c.projection));
    vec3("camera.eye", c.eye), vec3("camera.u", c.u), vec3("camera.v", c.v);
    vec3("camera.w", c.w);
    gl.Uniform1f(at("camera.vertical_fov_degrees"), float(c.vertical_fov_degrees));
    gl.Uniform1f(at("camera.view_height"), float(c.view_height));
    gl.Uniform2i(at("image_size"), scene.image.width, scene.image.height);
    gl.Uniform4i(at("primitive_counts"), int(scene.spheres.size()), int(scene.planes.size()),
                 int(scene.triangles.size()), int(scene.boxes.size()));
    gl.Uniform1i(at("light_count"), int(scene.lights.size()));
    gl.Uniform1i(at("material_count"), int(scene.materials.size()));
    gl.Uniform3f(at("background_color"), scene.background.r, scene.background.g,
                 scene.background.b);
    gl.Uniform3f(at("ambient_light"), scene.ambient_light.r, scene.ambient_light.g,
                 scene.ambient_light.b);
    gl.Uniform1i(at("fresnel"), scene.fresnel ? 1 : 0);
    gl.Uniform1i(at("render_mode"), int(mode));
    gl.Uniform1i(at("max_depth"), gpu_trace_depth(scene, mode));
    gl.Uniform1i(at("scene_features"), gpu_feature_bits(scene, mode));
    // A uniform the shader does not use (no textures) has location -1, which GL ignores.
    gl.Uniform1i(at("texture_lookup"), gpu_texture_lookup(scene));
    gl.Uniform1i(at("sample_first"), 0);
    gl.Uniform1i(at("sample_count"), 1);
}

}  // namespace

int gpu_trace_depth(const PreparedScene& scene, RenderMode mode) {
    return mode == RenderMode::Shaded ? std::clamp(scene.max_depth, 0, kMaxGpuDepth) : 0;
}

int gpu_feature_bits(const PreparedScene& scene, RenderMode mode) {
    const bool shaded = mode == RenderMode::Shaded;
    const Features& f = scene.features;
    auto bit = [](bool on, gpu::FeatureBit b) { return on ? int(b) : 0; };
    return bit(scene.accelerator == Accelerator::Bvh && scene.bvh.built(), gpu::kFeatureBvh) |
           bit(shaded && f.shadows, gpu::kFeatureShadows) |
           bit(!scene.normals.empty(), gpu::kFeatureVertexNormals) |
           bit(!scene.uvs.empty(), gpu::kFeatureVertexUvs) |
           bit(shaded && f.refraction, gpu::kFeatureRefraction) |
           bit(gpu_sampled(scene, mode), gpu::kFeatureSampled) |
           bit(shaded && f.area_lights, gpu::kFeatureAreaLights) |
           bit(shaded && f.depth_of_field, gpu::kFeatureDepthOfField) |
           bit(shaded && f.glossy, gpu::kFeatureGlossy) |
           bit(shaded && f.ambient_occlusion, gpu::kFeatureOcclusion) |
           bit(shaded && f.indirect_diffuse, gpu::kFeatureIndirect) |
           bit(shaded && f.path_tracing, gpu::kFeaturePathTracing);
}

int gpu_texture_lookup(const PreparedScene& scene) {
    return scene.texture_lookup == TextureLookup::Nearest    ? gpu::kLookupNearest
           : scene.texture_lookup == TextureLookup::Bilinear ? gpu::kLookupBilinear
                                                             : gpu::kLookupPerTexture;
}

void check_gpu_supported(const PreparedScene& scene, RenderMode mode) {
    const std::string where = scene.source.empty() ? "the scene" : scene.source;
    if (mode == RenderMode::BvhVisits && scene.accelerator != Accelerator::Bvh)
        throw GpuError(where +
                       ": mode \"bvh_visits\" draws the scene's BVH, and it has none; add "
                       "\"accelerator\": \"bvh\" to \"render\" or pass --accelerator bvh");
    const bool textured = scene.features.textures || scene.features.normal_maps;
    if (textured && (scene.texture_lookup == TextureLookup::Oiio ||
                     scene.texture_lookup == TextureLookup::OiioAniso))
        throw GpuError(where +
                       ": --texture-filter oiio (OpenImageIO's mip-mapped lookups) has no GPU "
                       "port; use nearest or bilinear, or render it without --gpu");
    if (mode == RenderMode::Shaded && scene.features.fog)
        throw GpuError(where +
                       ": fog (stage 10's optional homogeneous medium) has no GPU port; render "
                       "it without --gpu");
    if (gpu_sampled(scene, mode) && scene.area_lights.size() > std::size_t(kMaxGpuAreaLights))
        throw GpuError(where + ": " + std::to_string(scene.area_lights.size()) +
                       " area lights; the GPU port takes at most " +
                       std::to_string(kMaxGpuAreaLights));
    if (gpu_sampled(scene, mode) && scene.features.motion_blur &&
        scene.spheres.size() > std::size_t(kMaxGpuSpheresWithMotion))
        throw GpuError(where + ": " + std::to_string(scene.spheres.size()) +
                       " spheres with motion blur; the GPU port moves a copy of at most " +
                       std::to_string(kMaxGpuSpheresWithMotion) +
                       " per camera sample; render it without --gpu");
    if (scene.lights.size() > std::size_t(kMaxGpuLights))
        throw GpuError(where + ": " + std::to_string(scene.lights.size()) +
                       " lights; the GPU port takes at most " + std::to_string(kMaxGpuLights));
    if (scene.accelerator == Accelerator::Bvh && !scene.bvh.built())
        throw GpuError(where +
                       ": the scene asks for a BVH and has none (is stage 06's build_bvh a "
                       "stub?); render it with --accelerator none");
}

// Reports each stub whose flag is set, once per process (core/not_implemented.h's message).
void report_gpu_stubs(const AssembledShader& shader, const std::uint32_t flags[4]) {
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
        if (s.loop)
            report_endless_loop(s.file.c_str(), s.line, gpu::kLoopLimit, *once);
        else
            report_not_implemented(s.function.c_str(), s.file.c_str(), s.line, s.handout.c_str(),
                                   *once);
    }
    // Every pixel runs the whole shader, so an early stub (a camera ray) hides the later ones
    // (shading, reflection) from the flags: name the rest of this shader's stubs too, once each,
    // so a student sees the whole to-do list of the scene, not one function a run.
    const bool any = flags[0] || flags[1] || flags[2] || flags[3];
    for (std::size_t k = 0; any && k < shader.stubs.size() && k < 128; ++k) {
        const ShaderStub& s = shader.stubs[k];
        if ((flags[k / 32] & (1u << (k % 32))) || s.loop) continue;
        {
            static std::set<std::string> named;
            std::lock_guard lock(mutex);
            if (!named.insert(s.file + ":" + std::to_string(s.line)).second) continue;
        }
        std::fprintf(stderr, "also a stub in this shader, not reached yet: %s (%s:%d); read %s\n",
                     s.function.c_str(), s.file.c_str(), s.line, s.handout.c_str());
    }
}

std::string gpu_defines(const PreparedScene& scene, RenderMode mode, bool uber) {
    std::string d;
    auto define = [&](bool on, const char* name) {
        if (on || uber) d += std::string("#define ") + name + "\n";
    };
    define(!scene.spheres.empty(), "HAS_SPHERES");
    define(!scene.planes.empty(), "HAS_PLANES");
    define(!scene.triangles.empty(), "HAS_TRIANGLES");
    define(!scene.boxes.empty(), "HAS_BOXES");
    define(!scene.normals.empty(), "HAS_VERTEX_NORMALS");
    define(scene.accelerator == Accelerator::Bvh && scene.bvh.built(), "HAS_BVH");
    const bool shaded = mode == RenderMode::Shaded;
    define(shaded && scene.features.shadows, "HAS_SHADOWS");
    define(shaded && scene.features.light_links, "HAS_LIGHT_LINKS");
    define(shaded && scene.features.reflection, "HAS_REFLECTION");
    define(shaded && scene.features.refraction, "HAS_REFRACTION");
    const Features& f = scene.features;
    define(!scene.uvs.empty(), "HAS_VERTEX_UVS");
    define(shaded && f.textures, "HAS_TEXTURES");
    define(shaded && f.normal_maps, "HAS_NORMAL_MAPS");
    define(shaded && f.image_textures, "HAS_IMAGE_TEXTURES");
    define(shaded && f.checker_textures, "HAS_CHECKER_TEXTURES");
    define(shaded && f.noise_textures, "HAS_NOISE_TEXTURES");
    define(shaded && f.environment, "HAS_ENVIRONMENT");
    // Stage 10, only for a stage 10 scene, even with --uber: compiled in, its sampled path
    // (every bounce inlined) costs llvmpipe minutes of compiling the uber shader, and every
    // scene of stages 01-09 never takes it. So --uber has two programs, with and without
    // sampling. Motion blur replaces the spheres' buffer by a per-invocation copy sized by the
    // scene (MAX_SPHERES): compiled in only for a scene with moving spheres.
    const bool sampled = gpu_sampled(scene, mode);
    auto define_sampled = [&](bool on, const char* name) {
        if (sampled && (on || uber)) d += std::string("#define ") + name + "\n";
    };
    define_sampled(true, "HAS_SAMPLING");
    define_sampled(f.area_lights, "HAS_AREA_LIGHTS");
    define_sampled(f.depth_of_field, "HAS_DEPTH_OF_FIELD");
    define_sampled(f.glossy, "HAS_GLOSSY");
    define_sampled(f.ambient_occlusion, "HAS_OCCLUSION");
    define_sampled(f.indirect_diffuse, "HAS_INDIRECT");
    // Stage 11 (bsdf.glsl, path.glsl): only for a path-traced scene, even with --uber (its loop
    // would cost every stage 10 scene's uber program compile time it never uses).
    if (sampled && f.path_tracing) d += "#define HAS_PATH_TRACING\n";
    if (sampled && f.motion_blur)
        d += "#define HAS_MOTION_BLUR\n#define MAX_SPHERES " +
             std::to_string(std::max<std::size_t>(1, scene.spheres.size())) + "\n";
    const std::size_t lights = uber ? kMaxGpuLights : std::max<std::size_t>(1, scene.lights.size());
    d += "#define MAX_LIGHTS " + std::to_string(lights) + "\n";
    const SampledSlots slots = sampled_slots(scene, mode, uber);
    d += "#define MAX_AREA_LIGHTS " + std::to_string(slots.area_lights) + "\n";
    d += "#define MAX_MOVING_SPHERES " + std::to_string(slots.moving_spheres) + "\n";
    d += "#define MAX_DEPTH " + std::to_string(uber ? kMaxGpuDepth : gpu_trace_depth(scene, mode)) +
         "\n";
    return d;
}

namespace {

// The program's #defines: the scene's, and the --debug-pixel notes when asked for. A specialised
// program also has the mode and the features as constants (compute_io.glsl).
std::string program_defines(const PreparedScene& scene, RenderMode mode, bool uber, bool probe) {
    std::string d = gpu_defines(scene, mode, uber) + (probe ? "#define HAS_DEBUG_PIXEL\n" : "");
    if (!uber)
        d += "#define RENDER_MODE " + std::to_string(int(mode)) + "\n#define SCENE_FEATURES " +
             std::to_string(gpu_feature_bits(scene, mode)) + "\n";
    return d;
}

}  // namespace

AssembledShader assemble_trace(const std::string& defines, const fs::path& student_dir,
                               const fs::path& sampling_dir, const fs::path& path_dir) {
    const fs::path students = student_dir.empty() ? gpu_student_dir() : student_dir;
    const fs::path sampling = sampling_dir.empty() ? gpu_sampling_dir() : sampling_dir;
    const fs::path path = path_dir.empty() ? gpu_path_dir() : path_dir;
    // sampling.glsl is looked up after stage 09's folder: only a stage 10 or 11 scene includes
    // it; stage 11's bsdf.glsl and path.glsl after that, only for a path-traced scene.
    return assemble_shader(source_dir() / "shaders/trace.comp", {students, sampling, path},
                           defines);
}

AssembledShader assemble_trace_shader(const PreparedScene& scene, RenderMode mode,
                                      const fs::path& student_dir, bool uber,
                                      const fs::path& sampling_dir) {
    return assemble_trace(program_defines(scene, mode, uber, false), student_dir, sampling_dir);
}

struct GpuRenderer::Program {
    AssembledShader shader;  // for the stub report's names and lines
    GLuint id = 0;
};

GpuRenderer::GpuRenderer(const GpuRenderOptions& options) : options_(options) {
    std::string error;
    context_ = GlContext::create(options.context, error);
    if (!context_) throw GpuError(error);
    if (options.log) *options.log << "gpu: " << context_->describe() << "\n";
}

GpuRenderer::~GpuRenderer() {
    for (const auto& [defines, program] : programs_) context_->gl().DeleteProgram(program->id);
}

std::string GpuRenderer::describe() const {
    return context_->describe();
}

const GpuRenderer::Program& GpuRenderer::program_for(const std::string& defines,
                                                     GpuTimings& timings) {
    if (const auto it = programs_.find(defines); it != programs_.end()) return *it->second;
    const auto start = std::chrono::steady_clock::now();
    auto program = std::make_unique<Program>();
    program->shader =
        assemble_trace(defines, options_.student_dir, options_.sampling_dir, options_.path_dir);
    std::string error;
    program->id = build_compute_program(context_->gl(), program->shader, error);
    if (!program->id) throw GpuError(error);
    timings.compile_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return *(programs_[defines] = std::move(program));
}

namespace {

// Milliseconds between laps.
class Stopwatch {
  public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - start_).count();
        start_ = now;
        return ms;
    }

  private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The packed scene's storage buffers, and stage 10's uniform block sized as the program's
// defines say; the caller deletes them.
std::vector<GLuint> upload_scene(const GlApi& gl, const gpu::GpuScene& packed,
                                 const SampledSlots& slots) {
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
    const std::vector<unsigned char> block =
        gpu::sampled_block(packed, slots.area_lights, slots.moving_spheres);
    GLuint uniform_block = 0;
    gl.GenBuffers(1, &uniform_block);
    gl.BindBuffer(GL_UNIFORM_BUFFER, uniform_block);
    gl.BufferData(GL_UNIFORM_BUFFER, GLsizeiptr(block.size()), block.data(), GL_STATIC_DRAW);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, gpu::kSampledSceneBinding, uniform_block);
    buffers.push_back(uniform_block);
    return buffers;
}

// The dispatches of one render: one, or for a stage 10 scene batches of camera samples, each
// adding to the sums the last one left. False when `cancel` stopped it between batches.
bool dispatch(const GlApi& gl, GLuint program, const PreparedScene& scene, int samples,
              const GpuRenderOptions& options) {
    const int batch =
        samples == 1 ? 1
                     : std::max(1, options.samples_per_dispatch > 0 ? options.samples_per_dispatch
                                                                    : kDefaultSamplesPerDispatch);
    const GLint first_at = gl.GetUniformLocation(program, "sample_first");
    const GLint count_at = gl.GetUniformLocation(program, "sample_count");
    for (int first = 0; first < samples; first += batch) {
        if (first > 0 && options.cancel && options.cancel->load()) return false;
        gl.Uniform1i(first_at, first);
        gl.Uniform1i(count_at, std::min(batch, samples - first));
        gl.DispatchCompute(GLuint((scene.image.width + 7) / 8),
                           GLuint((scene.image.height + 7) / 8), 1);
        gl.MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        if (samples > 1) gl.Finish();  // one batch at a time: a long queue would not cancel
    }
    return true;
}

// The pixels of the output buffer (after its stub flags) as an image. a: the hit distance
// (depth) or the node count (bvh_visits); -2 a stub, -1 nothing. Stage 10: rgb the sum of
// `samples` samples, divided here (the CPU's mean, in float).
Image output_image(const std::vector<glm::vec4>& output, const PreparedScene& scene,
                   RenderMode mode, int samples) {
    Image image(scene.image.width, scene.image.height);
    std::vector<Real> values(image.pixels.size());
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        glm::vec4 p = output[i + 1];
        if (samples > 1 && p.a != -2.0f) p = glm::vec4(glm::vec3(p) / float(samples), 0);
        values[i] = Real(p.a);
        const Color rgb(p.r, p.g, p.b);
        image.pixels[i] = p.a == -2.0f                 ? kStubColor
                          : mode == RenderMode::Shaded ? rgb
                                                       : display_value(rgb);
    }
    if (mode == RenderMode::Depth) map_depth(values, image);
    if (mode == RenderMode::BvhVisits) map_visits(values, image);
    return image;
}

}  // namespace

Image GpuRenderer::render(const PreparedScene& scene, RenderMode mode, GpuTimings* timings_out,
                          GpuPixelProbe* probe) {
    if (!scene.instances.empty())
        return render(flatten_instances(scene, mode), mode, timings_out, probe);
    check_gpu_supported(scene, mode);
    GpuTimings timings;
    const std::string defines = program_defines(scene, mode, options_.uber, probe != nullptr);
    const bool fresh = programs_.find(defines) == programs_.end();
    const Program& program = program_for(defines, timings);
    const GlApi& gl = context_->gl();
    Stopwatch stopwatch;
    std::vector<GLuint> buffers =
        upload_scene(gl, gpu::pack_scene(scene), sampled_slots(scene, mode, options_.uber));
    // The output: 4 words of stub flags, then one vec4 a pixel (stage 10: sums of samples), then
    // --debug-pixel's notes.
    const std::size_t pixel_count =
        std::size_t(scene.image.width) * std::size_t(scene.image.height);
    std::vector<glm::vec4> output(pixel_count + 1 + (probe ? gpu_probe_vec4s() : 0), glm::vec4(0));
    buffers.push_back(upload(gl, gpu::kOutputBinding, output));
    const std::vector<GLuint> textures = create_texel_views(gl, buffers);
    gl.UseProgram(program.id);
    set_uniforms(gl, program.id, scene, mode);
    if (probe)
        gl.Uniform2i(gl.GetUniformLocation(program.id, "debug_pixel_at"), probe->x, probe->y);
    gl.Finish();  // the uploads are not the trace's time
    stopwatch.lap();
    if (timings_out && fresh) {
        // llvmpipe compiles the shader to machine code at its first dispatch: one work group
        // (its pixels are written again below) moves that into compile_ms.
        gl.DispatchCompute(1, 1, 1);
        gl.Finish();
        timings.compile_ms += stopwatch.lap();
    }
    const int samples =
        gpu_sampled(scene, mode) ? std::max(1, scene.sampling.samples_per_pixel) : 1;
    const bool finished = dispatch(gl, program.id, scene, samples, options_);
    gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(output.size() * sizeof(glm::vec4)),
                        output.data());
    timings.trace_ms = stopwatch.lap();
    if (timings_out) *timings_out = timings;
    const GLenum status = gl.GetError();
    gl.DeleteBuffers(GLsizei(buffers.size()), buffers.data());
    gl.DeleteTextures(GLsizei(textures.size()), textures.data());
    if (status != GL_NO_ERROR)
        throw GpuError("gpu: OpenGL error " + std::to_string(status) +
                       " while rendering; rerun with --gl osmesa, or without --gpu");
    std::uint32_t flags[4];
    std::memcpy(flags, &output[0], sizeof flags);
    report_gpu_stubs(program.shader, flags);
    if (probe) read_gpu_probe(output, pixel_count, program.shader, *probe);
    if (!finished) throw GpuError("gpu: render cancelled");
    return output_image(output, scene, mode, samples);
}

Image render_gpu(const PreparedScene& scene, RenderMode mode, const GpuRenderOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    GpuRenderer renderer(options);
    const double context_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    Image image = renderer.render(scene, mode, options.timings);
    if (options.timings) options.timings->context_ms = context_ms;
    return image;
}

}  // namespace rt
