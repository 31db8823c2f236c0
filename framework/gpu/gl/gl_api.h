// The OpenGL functions the GPU stage calls, as a table of pointers loaded from whichever context
// is current (EGL or OSMesa hand out their own entry points: one renderer serves both).
#pragma once

#include <GL/glcorearb.h>

#include <string>

namespace rt {

using GlProcLoader = void* (*)(const char* name);

// What the compute path relies on, read once after the context is made current.
struct GlLimits {
    int major = 0, minor = 0;
    int compute_storage_blocks = 0;  // GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS (the scene uses 16)
    int storage_bindings = 0;        // GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS
    int group_size[3] = {0, 0, 0};   // GL_MAX_COMPUTE_WORK_GROUP_SIZE
    int group_count[3] = {0, 0, 0};  // GL_MAX_COMPUTE_WORK_GROUP_COUNT
    int group_invocations = 0;       // GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS
    std::string renderer, version;

    std::string describe() const;  // one line: "llvmpipe ..., GL 4.5, 16 storage blocks, ..."
};

// OpenGL 1.1 entry points whose glcorearb.h typedefs GL/gl.h hides (OSMesa includes it first).
using GlViewportFn = void (*)(GLint, GLint, GLsizei, GLsizei);
using GlDrawArraysFn = void (*)(GLenum, GLint, GLsizei);
using GlReadPixelsFn = void (*)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);
using GlDeleteTexturesFn = void (*)(GLsizei, const GLuint*);

struct GlApi {
#define RT_GL_FUNCTIONS(X)                                           \
    X(PFNGLGETSTRINGPROC, GetString)                                 \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                             \
    X(PFNGLGETINTEGERI_VPROC, GetIntegeri_v)                         \
    X(PFNGLGETERRORPROC, GetError)                                   \
    X(PFNGLCREATESHADERPROC, CreateShader)                           \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                           \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                         \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                             \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                   \
    X(PFNGLDELETESHADERPROC, DeleteShader)                           \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                         \
    X(PFNGLATTACHSHADERPROC, AttachShader)                           \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                             \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                           \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                 \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                         \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                               \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)               \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                                 \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                                 \
    X(PFNGLUNIFORM2IPROC, Uniform2i)                                 \
    X(PFNGLUNIFORM3FPROC, Uniform3f)                                 \
    X(PFNGLUNIFORM4IPROC, Uniform4i)                                 \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                               \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                               \
    X(PFNGLBUFFERDATAPROC, BufferData)                               \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                       \
    X(PFNGLGETBUFFERSUBDATAPROC, GetBufferSubData)                   \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                         \
    X(PFNGLGETNAMEDBUFFERPARAMETERIVPROC, GetNamedBufferParameteriv) \
    X(PFNGLCREATETEXTURESPROC, CreateTextures)                       \
    X(PFNGLTEXTUREBUFFERPROC, TextureBuffer)                         \
    X(PFNGLBINDTEXTUREUNITPROC, BindTextureUnit)                     \
    X(GlDeleteTexturesFn, DeleteTextures)                            \
    X(PFNGLDISPATCHCOMPUTEPROC, DispatchCompute)                     \
    X(PFNGLMEMORYBARRIERPROC, MemoryBarrier)                         \
    X(PFNGLFINISHPROC, Finish)                                       \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                     \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                     \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)               \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                   \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                   \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)             \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)             \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)     \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)       \
    X(GlViewportFn, Viewport)                                        \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                     \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                     \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)               \
    X(GlDrawArraysFn, DrawArrays)                                    \
    X(GlReadPixelsFn, ReadPixels)
#define RT_GL_MEMBER(type, name) type name = nullptr;
    RT_GL_FUNCTIONS(RT_GL_MEMBER)
#undef RT_GL_MEMBER

    // Fills every pointer through `loader`; "" on success, else the first missing name.
    std::string load(GlProcLoader loader);
    GlLimits query_limits() const;
};

}  // namespace rt
