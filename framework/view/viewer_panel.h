// The viewer's side panel: HUD, settings, ray-tree listing (Dear ImGui, inside a frame).
#pragma once

#include "view/viewer.h"

namespace rt::view {

void draw_panel(Viewer& viewer, float width, float height);

}  // namespace rt::view
