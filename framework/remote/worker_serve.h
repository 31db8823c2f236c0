// The worker's side of the judge-worker split (remote_call.h).
#pragma once

#include "scene/scene.h"

namespace rt::remote {

// Serves the judge on `fd` until it closes the connection; returns the exit code.
int serve(int fd);

// What a scene received from the judge needs before use: the OpenImageIO texture system, which
// cannot cross (wire_types.cpp).
void prepare_scene(Scene& scene);

}  // namespace rt::remote
