#include "gpu/gl/gl_api.h"

namespace rt {

std::string GlApi::load(GlProcLoader loader) {
#define RT_GL_LOAD(type, name)                         \
    name = reinterpret_cast<type>(loader("gl" #name)); \
    if (!name) return "gl" #name;
    RT_GL_FUNCTIONS(RT_GL_LOAD)
#undef RT_GL_LOAD
    return "";
}

GlLimits GlApi::query_limits() const {
    GlLimits l;
    auto text = [&](GLenum name) {
        const GLubyte* s = GetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    l.renderer = text(GL_RENDERER);
    l.version = text(GL_VERSION);
    GetIntegerv(GL_MAJOR_VERSION, &l.major);
    GetIntegerv(GL_MINOR_VERSION, &l.minor);
    if (l.major * 10 + l.minor < 43) return l;  // no compute: the limits below do not exist
    GetIntegerv(GL_MAX_COMPUTE_SHADER_STORAGE_BLOCKS, &l.compute_storage_blocks);
    GetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &l.storage_bindings);
    GetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &l.group_invocations);
    for (GLuint i = 0; i < 3; ++i) {
        GetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_SIZE, i, &l.group_size[i]);
        GetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, i, &l.group_count[i]);
    }
    return l;
}

std::string GlLimits::describe() const {
    return renderer + ", OpenGL " + std::to_string(major) + "." + std::to_string(minor) + ", " +
           std::to_string(compute_storage_blocks) + " storage blocks in a compute shader (" +
           std::to_string(storage_bindings) + " bindings), work groups up to " +
           std::to_string(group_size[0]) + "x" + std::to_string(group_size[1]) + "x" +
           std::to_string(group_size[2]) + " (" + std::to_string(group_invocations) +
           " invocations)";
}

}  // namespace rt
