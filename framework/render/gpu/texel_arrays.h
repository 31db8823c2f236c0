// The compute shader's texel views of the scene's storage buffers (shaders/texel_arrays.glsl).
// llvmpipe loads a storage buffer's word one invocation at a time, in a loop with a branch per
// invocation, but fetches a buffer texture's texel for its 8 invocations at once; so the trace
// shader reads the scene's arrays through buffer textures over the very buffers, and the host
// rewrites the stage 09 code's `name[i]` into the accessor `name_at(i)` (web_arrays.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "gpu/gl/gl_api.h"

namespace rt {

// The arrays the trace shader with `defines` reads through accessors.
std::vector<std::string_view> texel_array_names(const std::string& defines);

// Buffer textures over `buffers` (the storage buffer of binding i at index i), each bound to
// the texture unit of its binding. The caller deletes them. Throws GpuError when an array holds
// more texels than the driver's buffer textures may.
std::vector<GLuint> create_texel_views(const GlApi& gl, const std::vector<GLuint>& buffers);

}  // namespace rt
