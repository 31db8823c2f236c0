// `rt render SCENE --gpu --debug-pixel X,Y`: what stage 09's shader computed for one pixel, as the
// CPU's ray tree (render/ray_tree.h) shows what the C++ computed. The shader is compiled with
// HAS_DEBUG_PIXEL (shaders/debug_pixel.glsl): the invocation of that pixel notes each ray, hit,
// shadow ray, local light and branch weight, and every rt_debug(value) a student wrote, into the
// output buffer after the image; the host reads the notes back and prints them as a tree.
#pragma once

#include <glm/vec4.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "gpu/gl/shader_source.h"
#include "gpu/shader_constants.h"
#include "render/gpu/gpu_render.h"
#include "scene/prepared_scene.h"

namespace rt {

// One note, as debug_pixel.glsl's rt_debug_put made it.
struct GpuDebugRecord {
    int kind = 0, where = 0, type = 0;  // kind: gpu::DebugNote (gpu/shader_constants.h)
    glm::vec4 value{0};
};

// What a render with a probe noted: `x`, `y` are set before it, the rest by it.
struct GpuPixelProbe {
    int x = 0, y = 0;
    std::vector<GpuDebugRecord> records;  // in the order the shader made them ...
    int made = 0;                         // ... of this many (the buffer keeps gpu::kDebugCapacity)
    AssembledShader shader;               // for rt_debug's file and line
};

// debug_pixel.glsl's kDebugCapacity, and the vec4s the notes need after the image.
constexpr int kGpuDebugCapacity = 512;
constexpr std::size_t gpu_probe_vec4s() {
    return 1 + 2 * std::size_t(kGpuDebugCapacity);
}

// The notes in `output` (the render's buffer: stub flags, `pixel_count` pixels, then the notes).
void read_gpu_probe(const std::vector<glm::vec4>& output, std::size_t pixel_count,
                    const AssembledShader& shader, GpuPixelProbe& probe);

// Renders `scene` on the GPU with pixel (x, y) probed; throws GpuError as render_gpu does.
GpuPixelProbe debug_pixel_gpu(const PreparedScene& scene, RenderMode mode, int x, int y,
                              const GpuRenderOptions& options = {});

// The notes as an indented tree, one ray, hit or value a line; each rt_debug line names the
// student's file and line and shows that line's text.
std::string gpu_pixel_text(const PreparedScene& scene, const GpuPixelProbe& probe);

}  // namespace rt
