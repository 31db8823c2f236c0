// A compute program built from an assembled shader, with the driver's messages in file:line form.
#pragma once

#include <string>

#include "gl/gl_api.h"
#include "gl/shader_source.h"

namespace rt {

// The linked program, or 0 with `error` set: the first message on its own line first (what a
// student reads), then the rest of the mapped log.
GLuint build_compute_program(const GlApi& gl, const AssembledShader& shader, std::string& error);

}  // namespace rt
