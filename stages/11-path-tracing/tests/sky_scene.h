// The scene of the Sky tests (path_test.cpp) and of their GPU twin (gpu_path_test.cpp).
#pragma once

#include <string>

#include "render/prepare.h"
#include "scene/scene_loader.h"

namespace rt {

// A Lambertian sphere (radius 1, albedo `albedo`) at the origin under a sky of radiance `sky` in
// every direction (stage 08's procedural sky, one colour, no sun), and no light.
inline PreparedScene sphere_under_sky(float albedo, float sky) {
    const std::string a = std::to_string(albedo), l = std::to_string(sky);
    const std::string colour = "[" + l + ", " + l + ", " + l + "]";
    return prepare_scene(parse_scene(
        R"({"camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0], "fov": 40},
            "image": {"width": 32, "height": 32},
            "render": {"max_depth": 4, "integrator": "path"},
            "environment": {"sky": {"zenith": )" +
            colour + R"(, "horizon": )" + colour + R"(, "ground": )" + colour +
            R"(, "sun_radius_degrees": 0, "resolution": 8}},
            "materials": [{"name": "m", "diffuse": [)" +
            a + ", " + a + ", " + a + R"(]}],
            "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})",
        "sphere_under_sky", "."));
}

}  // namespace rt
