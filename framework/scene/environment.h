// The environment (stage 08) as plain data: what a ray that leaves the scene sees. Its images are
// entries of the scene's texture table (Scene::texture_images, Scene::texels), so the GPU stage
// uploads them with the textures. Conventions (lat-long and cube-map lookups, rotation):
// docs/conventions.md#environment-maps. File syntax: docs/scene-format.md#environment.
#pragma once

#include <cstdint>
#include <type_traits>

namespace rt {

enum class EnvironmentKind : std::int32_t {
    None,     // rays that miss see Scene::background
    LatLong,  // one equirectangular image: u = longitude, v = latitude (row 0 straight up)
    CubeMap,  // six square images of one size, in the order of kCubeFaceNames
};

// Cube faces in OpenGL's order (GL_TEXTURE_CUBE_MAP_POSITIVE_X + i).
inline constexpr int kCubeFaces = 6;
inline constexpr const char* kCubeFaceNames[kCubeFaces] = {"px", "nx", "py", "ny", "pz", "nz"};

struct Environment {
    EnvironmentKind kind = EnvironmentKind::None;
    std::int32_t image = -1;  // LatLong: index into Scene::texture_images
    std::int32_t faces[kCubeFaces] = {-1, -1, -1, -1, -1, -1};  // CubeMap: +x -x +y -y +z -z
    float intensity = 1;  // multiplies every looked-up radiance
    float rotate_y = 0;   // degrees: the environment turns about +y by this (right-hand rule)
};

static_assert(std::is_trivially_copyable_v<Environment>);

}  // namespace rt
