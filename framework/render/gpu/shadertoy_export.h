// rt export-shadertoy: the scene and the student's stage 09 GLSL as one self-contained fragment
// shader in Shadertoy's form (mainImage, iResolution), the scene baked in as constants and only
// the code the scene needs compiled in (the #defines of gpu_defines). Shadertoy compiles GLSL ES
// 3.00, which allows `const` only on constant initialisers: the export drops the qualifier with a
// `#define const` before the shader's code, and writes no #line directives (its editor counts
// the file's own lines). No line of a shader file is changed.
//
// On the "calls student code" side: the GLSL it writes is the student's.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "gpu/gl/shader_source.h"
#include "render/gpu/web_arrays.h"
#include "scene/prepared_scene.h"

namespace rt {

struct ShadertoyExport {
    std::string text;               // the shader, to paste into Shadertoy's Image tab
    std::vector<ShaderStub> stubs;  // by the value of rt_first_stub (stubs paint magenta)
    // For each line of `text` (index 0: line 1), the GLSL file and line it came from, as
    // "stages/09-gpu/intersect.glsl:42"; "" for the export's own lines (the scene's constants).
    std::vector<std::string> line_origins;
    // With ShadertoyOptions::web_page: the arrays the shader reads from data textures.
    std::vector<DataArray> data_arrays;
    bool web_page = false;  // made with ShadertoyOptions::web_page
};

struct ShadertoyOptions {
    std::filesystem::path student_dir{};  // the stage 09 GLSL's folder; empty: gpu_student_dir()
    // rt export-web's page: the large arrays (meshes, the BVH, images) in data textures instead
    // of constants (render/gpu/web_arrays.h), so neither size limit below applies to them; what
    // the page's panel changes (the camera, the mode, the bounces, Fresnel, the feature bits) as
    // uniforms; the materials and the environment writable, for its term switches
    // (shaders/page_terms.glsl, called first in main).
    bool web_page = false;
};

// Images are baked as constant arrays up to this many texels in all; Shadertoy cannot load the
// scene's image files, and big constant arrays compile slowly (stage 07's 64x64 image, 4096
// texels, did not draw 64x48 pixels in 5 minutes under llvmpipe).
constexpr std::size_t kMaxShadertoyTexels = 1024;
// And the whole export up to this size (a browser compiles it all at every load): stage 06's
// meshes with their BVHs come to 10-15 MB.
constexpr std::size_t kMaxShadertoyBytes = 512 * 1024;

// The export of `scene` (its BVH built when it has one) drawn in `mode`. Throws GpuError
// (render/gpu/gpu_render.h), one line naming the scene, for what it cannot export: for Shadertoy
// the depth and bvh_visits views (they scale by the whole image's range, which one pixel cannot
// know), images beyond kMaxShadertoyTexels, exports beyond kMaxShadertoyBytes and stages 10-11's
// sampled scenes (rt export-web's page takes all of those); and what render --gpu cannot draw.
ShadertoyExport export_shadertoy(const PreparedScene& scene, RenderMode mode,
                                 const ShadertoyOptions& options = {});

// The export as a whole GLSL ES 3.00 fragment shader, as Shadertoy and a WebGL2 page run it: after
// `#version 300 es` and Shadertoy's uniforms, the export, then a main calling mainImage that also
// writes the stub a pixel reached (rt_first_stub) as alpha/255 (255: none). A web page's export
// also gets shaders/page_terms.glsl, and its main applies the term switches first.
std::string wrap_shadertoy_export(const ShadertoyExport& shader);
// The lines the wrapper puts before the export (to map a compiler's line numbers back to it).
long shadertoy_wrapper_head_lines();

// The scene as a published export (a Shadertoy shader, an rt export-web page) names it: from its
// stages/ folder on ("stages/06-bvh/scenes/mesh_garden.json"), else its file name alone; never
// the folders above, which are the lecturer's machine's. "a scene" when it has no file.
std::string public_scene_name(const std::string& source);

}  // namespace rt
