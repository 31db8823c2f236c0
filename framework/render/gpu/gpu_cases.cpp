// The host side of stage 09's GPU unit tests (gpu_cases.h).
#include "render/gpu/gpu_cases.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>

#include "core/source_dir.h"
#include "gpu/gl/compute_program.h"
#include "gpu/gl/gl_context.h"
#include "gpu/gpu_scene.h"
#include "gpu/shader_constants.h"
#include "render/gpu/gpu_render.h"

namespace rt {

namespace {

GLuint case_buffer(const GlApi& gl, int binding, GLsizeiptr bytes, const void* data) {
    GLuint buffer = 0;
    gl.GenBuffers(1, &buffer);
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    gl.BufferData(GL_SHADER_STORAGE_BUFFER, bytes, data, GL_DYNAMIC_DRAW);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(binding), buffer);
    return buffer;
}

}  // namespace

bool run_gpu_cases(const std::vector<gpu_cases::GpuRayCase>& cases,
                   std::vector<gpu_cases::GpuAnswer>& answers, std::string& error) {
    using gpu_cases::GpuRayCase;
    const std::unique_ptr<GlContext> context = GlContext::create(GlKind::Egl, error);
    if (!context) return false;
    const GlApi& gl = context->gl();
    const std::filesystem::path root = source_dir();
    const AssembledShader shader = assemble_shader(root / "shaders/intersect_cases.comp",
                                                   {root / "shaders", gpu_student_dir()}, "");
    const GLuint program = build_compute_program(gl, shader, error);
    if (program == 0) return false;
    // The output binding (compute_io.glsl's Output): 4 words of stub flags, then the answers.
    std::vector<glm::vec4> output(1 + 4 * cases.size(), glm::vec4(0));
    const GLuint buffers[2] = {
        case_buffer(gl, gpu::kTexels, GLsizeiptr(cases.size() * sizeof(GpuRayCase)), cases.data()),
        case_buffer(gl, gpu::kOutputBinding, GLsizeiptr(output.size() * sizeof(glm::vec4)),
                    output.data())};
    gl.UseProgram(program);
    gl.Uniform1i(gl.GetUniformLocation(program, "case_count"), int(cases.size()));
    gl.DispatchCompute(GLuint((cases.size() + 63) / 64), 1, 1);
    gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(output.size() * sizeof(glm::vec4)),
                        output.data());
    const GLenum status = gl.GetError();
    gl.DeleteBuffers(2, buffers);
    gl.DeleteProgram(program);
    if (status != GL_NO_ERROR) {
        error = "OpenGL error " + std::to_string(status) + " running intersect_cases.comp";
        return false;
    }
    std::uint32_t flags[4];
    std::memcpy(flags, &output[0], sizeof flags);
    report_gpu_stubs(shader, flags);
    answers.assign(cases.size(), {});
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const glm::vec4* g = &output[1 + 4 * i];  // found, t, stub; normal, front; point; uv
        answers[i] = {g[0].x == 1, g[0].y, glm::vec3(g[1]), g[1].w == 1, glm::vec2(g[3])};
    }
    return true;
}

}  // namespace rt
