// A compute program built from an assembled shader, with the driver's messages in file:line form;
// and a fragment shader drawn over a whole image (the headless check of rt export-shadertoy).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gpu/gl/gl_api.h"
#include "gpu/gl/shader_source.h"

namespace rt {

// The linked program, or 0 with `error` set: the first message on its own line first (what a
// student reads), then the rest of the mapped log.
GLuint build_compute_program(const GlApi& gl, const AssembledShader& shader, std::string& error);

// Draws GLSL ES 3.00 fragment shader `fragment` (its own #version line, one vec4 output) over a
// width x height RGBA8 framebuffer with a full-screen triangle, setting Shadertoy's iResolution
// (and iTime, iFrame to 0) when it declares them. `rgba`: the pixels, top row first. "" on
// success, else the driver's log (lines of `fragment`) or the GL error.
std::string draw_fragment_shader(const GlApi& gl, const std::string& fragment, int width,
                                 int height, std::vector<std::uint8_t>& rgba);

}  // namespace rt
