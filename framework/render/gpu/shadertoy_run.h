// An export for Shadertoy (render/gpu/shadertoy_export.h) run as Shadertoy runs it: inside a wrapper
// that declares Shadertoy's uniforms and a main calling mainImage, compiled by glslangValidator
// as GLSL ES 3.00, and drawn headless over a full-screen triangle (stage 09's Shadertoy tests).
//
// On the "calls student code" side: the GLSL it draws is the student's, so in grading it is a
// call the judge sends to the worker (stage_api/calls.h, RT_GPU_CALLS).
#pragma once

#include <string>

#include "image/image.h"
#include "scene/prepared_scene.h"

namespace rt {

struct ShadertoyRun {
    // glslangValidator's complaints ("" when it accepts the export), or that it is missing.
    std::string compile_errors;
    std::string draw_error;  // "" when the export drew
    Image8 image;            // what it drew (RGB, top row first)
};

// Exports `scene` in `mode`, checks and draws it; each stub a pixel reached is reported once
// (core/not_implemented.h), as render_gpu reports them. Throws GpuError for what cannot be
// exported (export_shadertoy).
ShadertoyRun run_shadertoy_export(const PreparedScene& scene, RenderMode mode);

}  // namespace rt
