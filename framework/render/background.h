// What a ray that hits nothing sees. Here, in render/, because with an environment it runs
// student code (stage 08), which the trusted scene/ folder must not call.
#pragma once

#include "scene/prepared_scene.h"

namespace rt {

// Looking along `direction` (unit or not): the scene's environment map (stage 08's
// environment_radiance) when it has one, else its one background colour. A scene without an
// environment never calls stage 08 code, so stages 01-07 render the same with it stubbed.
Color background(const PreparedScene& scene, const Vec3& direction);

}  // namespace rt
