#include "gpu/gl/compute_program.h"

#include <algorithm>
#include <vector>

namespace rt {
namespace {

// A shader's or a program's info log: `get_iv` and `get_log` are the matching pair of GL calls.
template <typename GetIv, typename GetLog>
std::string info_log(GLuint id, GetIv get_iv, GetLog get_log) {
    GLint length = 0;
    get_iv(id, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(std::size_t(length) + 1, '\0');
    get_log(id, GLsizei(log.size()), nullptr, log.data());
    return log.data();
}

std::string shader_log(const GlApi& gl, GLuint shader) {
    return info_log(shader, gl.GetShaderiv, gl.GetShaderInfoLog);
}

std::string program_log(const GlApi& gl, GLuint program) {
    return info_log(program, gl.GetProgramiv, gl.GetProgramInfoLog);
}

// A compiled shader object, or 0 with the driver's log in `error`.
GLuint compile_stage(const GlApi& gl, GLenum kind, const std::string& source, std::string& error) {
    const GLuint object = gl.CreateShader(kind);
    const char* text = source.c_str();
    gl.ShaderSource(object, 1, &text, nullptr);
    gl.CompileShader(object);
    GLint ok = 0;
    gl.GetShaderiv(object, GL_COMPILE_STATUS, &ok);
    if (ok) return object;
    error = shader_log(gl, object);
    gl.DeleteShader(object);
    return 0;
}

// Covers the viewport with one triangle, from gl_VertexID alone (no vertex buffer).
const char* const kFullScreenTriangle =
    "#version 300 es\n"
    "void main() {\n"
    "    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n"
    "    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";

}  // namespace

std::string draw_fragment_shader(const GlApi& gl, const std::string& fragment, int width,
                                 int height, std::vector<std::uint8_t>& rgba) {
    std::string error;
    const GLuint vertex = compile_stage(gl, GL_VERTEX_SHADER, kFullScreenTriangle, error);
    if (!vertex) return "the full-screen triangle's vertex shader: " + error;
    const GLuint pixel = compile_stage(gl, GL_FRAGMENT_SHADER, fragment, error);
    if (!pixel) {
        gl.DeleteShader(vertex);
        return error;
    }
    const GLuint program = gl.CreateProgram();
    gl.AttachShader(program, vertex);
    gl.AttachShader(program, pixel);
    gl.LinkProgram(program);
    gl.DeleteShader(vertex);
    gl.DeleteShader(pixel);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        error = "the program does not link: " + program_log(gl, program);
        gl.DeleteProgram(program);
        return error;
    }
    GLuint framebuffer = 0, color = 0, vertex_array = 0;
    gl.GenRenderbuffers(1, &color);
    gl.BindRenderbuffer(GL_RENDERBUFFER, color);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl.GenFramebuffers(1, &framebuffer);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        error = "an RGBA8 framebuffer of " + std::to_string(width) + "x" + std::to_string(height) +
                " is not complete";
    gl.GenVertexArrays(1, &vertex_array);  // a core profile draws only with one bound
    gl.BindVertexArray(vertex_array);
    gl.UseProgram(program);
    // Uniforms the shader does not declare have location -1, which GL ignores.
    gl.Uniform3f(gl.GetUniformLocation(program, "iResolution"), float(width), float(height), 1.0f);
    gl.Uniform1f(gl.GetUniformLocation(program, "iTime"), 0.0f);
    gl.Uniform1i(gl.GetUniformLocation(program, "iFrame"), 0);
    gl.Viewport(0, 0, width, height);
    if (error.empty()) gl.DrawArrays(GL_TRIANGLES, 0, 3);
    std::vector<std::uint8_t> bottom_up(std::size_t(width) * std::size_t(height) * 4);
    if (error.empty())
        gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
    const GLenum status = gl.GetError();
    if (error.empty() && status != GL_NO_ERROR)
        error = "OpenGL error " + std::to_string(status) + " while drawing";
    gl.DeleteVertexArrays(1, &vertex_array);
    gl.DeleteFramebuffers(1, &framebuffer);
    gl.DeleteRenderbuffers(1, &color);
    gl.DeleteProgram(program);
    const std::size_t row = std::size_t(width) * 4;
    rgba.resize(bottom_up.size());
    for (int y = 0; y < height; ++y)  // GL's rows start at the bottom
        std::copy_n(bottom_up.begin() + long(std::size_t(height - 1 - y) * row), row,
                    rgba.begin() + long(std::size_t(y) * row));
    return error;
}

GLuint build_compute_program(const GlApi& gl, const AssembledShader& shader, std::string& error) {
    if (!shader.error.empty()) {
        error = shader.error;
        return 0;
    }
    const GLuint object = compile_stage(gl, GL_COMPUTE_SHADER, shader.text, error);
    if (!object) {
        // The driver's lines name the concatenated source: map them to the student's files.
        error = map_compile_log(error, shader.files);
        if (error.empty()) error = shader.files[0] + ": error: the shader does not compile";
        return 0;
    }
    const GLuint program = gl.CreateProgram();
    gl.AttachShader(program, object);
    gl.LinkProgram(program);
    gl.DeleteShader(object);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        error = shader.files[0] + ": error: the program does not link: " +
                map_compile_log(program_log(gl, program), shader.files);
        gl.DeleteProgram(program);
        return 0;
    }
    return program;
}

}  // namespace rt
