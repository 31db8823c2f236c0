#include "gl/compute_program.h"

#include <vector>

namespace rt {
namespace {

std::string shader_log(const GlApi& gl, GLuint shader) {
    GLint length = 0;
    gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(std::size_t(length) + 1, '\0');
    gl.GetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    return log.data();
}

std::string program_log(const GlApi& gl, GLuint program) {
    GLint length = 0;
    gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(std::size_t(length) + 1, '\0');
    gl.GetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
    return log.data();
}

}  // namespace

GLuint build_compute_program(const GlApi& gl, const AssembledShader& shader, std::string& error) {
    if (!shader.error.empty()) {
        error = shader.error;
        return 0;
    }
    const GLuint object = gl.CreateShader(GL_COMPUTE_SHADER);
    const char* text = shader.text.c_str();
    gl.ShaderSource(object, 1, &text, nullptr);
    gl.CompileShader(object);
    GLint ok = 0;
    gl.GetShaderiv(object, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        error = map_compile_log(shader_log(gl, object), shader.files);
        if (error.empty()) error = shader.files[0] + ": error: the shader does not compile";
        gl.DeleteShader(object);
        return 0;
    }
    const GLuint program = gl.CreateProgram();
    gl.AttachShader(program, object);
    gl.LinkProgram(program);
    gl.DeleteShader(object);
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
