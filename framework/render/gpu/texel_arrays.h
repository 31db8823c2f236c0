// The compute shader's texel views of the scene's storage buffers (shaders/texel_arrays.glsl).
// llvmpipe loads a storage buffer's word one invocation at a time, in a loop with a branch per
// invocation, but fetches a buffer texture's texel for its 8 invocations at once; so trace.comp's
// accessors name_at(i) read the scene's arrays through buffer textures over the very buffers.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "gpu/gl/gl_api.h"

namespace rt {

// Buffer textures over `buffers` (the storage buffer of binding i at index i), each bound to
// the texture unit of its binding. The caller deletes them. Throws GpuError when an array holds
// more texels than the driver's buffer textures may.
std::vector<GLuint> create_texel_views(const GlApi& gl, const std::vector<GLuint>& buffers);

}  // namespace rt
