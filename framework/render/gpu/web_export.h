// rt export-web (issue 29): one self-contained HTML page that renders the scene in WebGL2 with the
// student's stage 09 GLSL. The fragment shader is the Shadertoy export in its web page form
// (shadertoy_export.h, ShadertoyOptions::web_page: the camera and the panel's settings are
// uniforms, so the page can orbit); the page's markup and scripts (render/gpu/web/) are inlined
// with the shader, the scene's camera and stubs as JSON, and the CPU render as a PNG data URL.
// Nothing is fetched.
//
// On the "calls student code" side: the GLSL it embeds is the student's.
#pragma once

#include <filesystem>
#include <string>

#include "image/image.h"
#include "scene/prepared_scene.h"

namespace rt {

// The page for `scene` drawn in `mode`; `reference` (the CPU render, empty for none) is shown
// beside the live canvas on request. Throws GpuError, one line naming the scene, for whatever
// export_shadertoy refuses (big images or meshes, depth views, stage 10).
std::string export_web_page(const PreparedScene& scene, RenderMode mode, const Image8& reference);

}  // namespace rt
