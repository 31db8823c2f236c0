#include "render/background.h"

#include "stage_api/stage08.h"

namespace rt {

Color background(const PreparedScene& scene, const Vec3& direction) {
    if (!scene.features.environment) return scene.background;
    return environment_radiance(scene, direction);
}

}  // namespace rt
