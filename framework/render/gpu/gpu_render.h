// Stage 09: the scene rendered by a compute shader (shaders/trace.comp with the student GLSL of
// stages/09-gpu/), on a headless or windowed OpenGL context (gpu/gl/gl_context.h). The result comes
// back as an Image, so every output path of the CPU renderer works unchanged.
//
// On the "calls student code" side: the GLSL it compiles is the student's.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>

#include "gpu/gl/gl_context.h"
#include "gpu/gl/shader_source.h"
#include "gpu/glsl_dirs.h"
#include "image/image.h"
#include "scene/prepared_scene.h"

namespace rt {

struct GpuPixelProbe;  // render/gpu/gpu_debug_pixel.h

// Where a GPU render's time went (rt-bench gpu): milliseconds of wall-clock time.
struct GpuTimings {
    double context_ms = 0;  // creating the OpenGL context
    double compile_ms = 0;  // assembling, compiling and linking the shader
    double trace_ms = 0;    // the dispatch, up to the pixels read back (upload excluded)
};

struct GpuRenderOptions {
    GlKind context = GlKind::Egl;
    std::filesystem::path student_dir;  // empty: $RT_GPU_STUDENT_DIR, else stages/09-gpu
    std::ostream* log = nullptr;        // "gpu: egl (surfaceless): llvmpipe ..." when set
    bool uber = false;  // compile every feature in (one shader for every scene), not the scene's
    GpuTimings* timings = nullptr;  // filled when set
    // Stage 10's sampling.glsl is read from here; empty: gpu_sampling_dir().
    std::filesystem::path sampling_dir;
    // Stage 10: camera samples per pixel added by one dispatch (0: the default, 4). The image is
    // the same for any value: each sample's numbers depend on its pixel and index only.
    int samples_per_dispatch = 0;
    // Stage 11's bsdf.glsl and path.glsl are read from here; empty: gpu_path_dir().
    std::filesystem::path path_dir;
    // Set by another thread: a stage 10 render stops after the dispatch in flight (the viewer).
    const std::atomic<bool>* cancel = nullptr;
};

// Thrown for what stops a GPU render: no context, a shader that does not compile (the message
// is "file:line:col: error: ..."), a scene the GPU port cannot draw yet.
struct GpuError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// What the shader is told besides the #defines (compute_io.glsl's uniforms; the constants of an
// export): the ray tree's depth, framework.glsl's scene_features bits, texture_lookup's code.
int gpu_trace_depth(const PreparedScene& scene, RenderMode mode);
int gpu_feature_bits(const PreparedScene& scene, RenderMode mode);
int gpu_texture_lookup(const PreparedScene& scene);

// Throws GpuError ("SCENE: ...", one line) for what the GPU port cannot draw.
void check_gpu_supported(const PreparedScene& scene, RenderMode mode);

// The #defines trace.comp is compiled with for `scene` in `mode` (one per line); `uber`: every
// feature, the largest array sizes (the shader then tests what the scene has at run time).
std::string gpu_defines(const PreparedScene& scene, RenderMode mode, bool uber = false);

// A GPU renderer that keeps its context and compiled programs between renders (the viewer, the
// benchmark): programs are cached by their #defines, i.e. by the scene's feature mask, so a
// camera change reuses the program and only uploads and traces. Lives on the thread that made
// it (an OpenGL context is current on one thread). Throws GpuError when there is no context.
class GpuRenderer {
  public:
    explicit GpuRenderer(const GpuRenderOptions& options = {});
    ~GpuRenderer();
    GpuRenderer(const GpuRenderer&) = delete;
    GpuRenderer& operator=(const GpuRenderer&) = delete;

    // As render_gpu below; `timings`, when set, gets this render's figures (compile_ms is 0
    // when the program came from the cache); `probe`, when set, gets what the shader computed
    // for its pixel (render/gpu/gpu_debug_pixel.h).
    Image render(const PreparedScene& scene, RenderMode mode, GpuTimings* timings = nullptr,
                 GpuPixelProbe* probe = nullptr);
    std::string describe() const;  // the context, as --gpu logs it
    std::size_t cached_programs() const { return programs_.size(); }

  private:
    struct Program;
    const Program& program_for(const std::string& defines, GpuTimings& timings);

    GpuRenderOptions options_;
    std::unique_ptr<GlContext> context_;
    std::map<std::string, std::unique_ptr<Program>> programs_;  // by the shader's #defines
};

// Renders like render() (render/render.h): debug modes store display values, a pixel that reached
// a stub is magenta and the stub is reported once on stderr (and counted: core/not_implemented.h).
// A stage 10 scene in mode shaded accumulates its samples_per_pixel camera samples over several
// dispatches into float sums and returns their mean.
Image render_gpu(const PreparedScene& scene, RenderMode mode, const GpuRenderOptions& options = {});

// Reports each stub whose bit is set in the shader's stub_flags (compute_io.glsl), once per
// process, as core/not_implemented.h does for C++ stubs.
void report_gpu_stubs(const AssembledShader& shader, const std::uint32_t flags[4]);

// shaders/trace.comp with `defines` and the student folders (empty: the course's): the text the
// renderer compiles, the student's files in it as written (GpuAssembly.*).
AssembledShader assemble_trace(const std::string& defines, const std::filesystem::path& student_dir,
                               const std::filesystem::path& sampling_dir,
                               const std::filesystem::path& path_dir = {});

// The shader as it would be compiled for `scene` (the offline glslangValidator check).
AssembledShader assemble_trace_shader(const PreparedScene& scene, RenderMode mode,
                                      const std::filesystem::path& student_dir = {},
                                      bool uber = false,
                                      const std::filesystem::path& sampling_dir = {});

}  // namespace rt
