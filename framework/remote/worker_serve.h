// The worker's side of the judge-worker split (remote_call.h).
#pragma once

#include "scene/scene.h"

namespace rt::remote {

// Serves the judge on `fd` until it closes the connection; returns the exit code.
int serve(int fd);

}  // namespace rt::remote
