// Stage 08 (environment maps): the functions students write in
// stages/08-environment/environment.cpp. Handout: stages/08-environment/README.md.
// Conventions: docs/conventions.md#environment-maps (directions to lat-long (u, v), cube faces
// and their (u, v), rotation). The framework's shading driver calls environment_radiance for
// every ray that hits nothing, only when the scene has an environment (render/background.h).
#pragma once

#include "scene/scene.h"

namespace rt {

// The lat-long (equirectangular) coordinates of `direction` (y up; any non-zero length), as
// OpenImageIO's TextureSystem::environment() computes them for a y-up lat-long map, with
// d = normalize(direction):
//   u = atan2(-d.x, d.z) / (2 pi) + 1/2, and u = 1 taken as 0      (u = 0 at -z, 0.25 at +x,
//                                                                   0.5 at +z, 0.75 at -x)
//   v = acos(d.y) / pi, d.y clamped to [-1, 1]                      (v = 0 straight up, 1 down)
// So u is in [0, 1) (never exactly 1) and v in [0, 1]; image row 0 is the top (v = 0). The map
// is seen from inside: looking along -z, u grows to the right, so a photograph reads the right
// way round. (A sphere's texture, stage 07's sphere_texcoord, is seen from outside: its u runs
// the other way.)
Vec2 latlong_uv(const Vec3& direction);

// A cube-map face and the (u, v) on it.
struct CubeFaceUv {
    int face = 0;  // 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z (Environment::faces, OpenGL's order)
    Vec2 uv{0.5f};
};

// The face `direction` (any non-zero length) points at and where, following the OpenGL
// specification's table "Cube Map Texture Selection":
//   the major axis is the component of largest magnitude; on ties x wins over y, y over z
//   (so (1, 1, 0) is on +x and (0, 1, 1) on +y); its sign picks the + or - face;
//   face   sc    tc    ma        face   sc    tc    ma
//   +x    -z    -y     x         -x    +z    -y     x
//   +y    +x    +z     y         -y    +x    -z     y
//   +z    +x    -y     z         -z    -x    -y     z
//   u = (sc / |ma| + 1) / 2,  v = (tc / |ma| + 1) / 2, each clamped to [0, 1].
// v = 0 is image row 0 (the top of the face's file).
CubeFaceUv cube_face_uv(const Vec3& direction);

// The radiance arriving from `direction` (any non-zero length) out of scene.environment:
//   1. turn the direction by -rotate_y degrees about +y (the environment is turned by +rotate_y,
//      right-hand rule), so rotate_y = 90 shows at +x what is at +z (u = 0.5) unrotated;
//   2. LatLong: latlong_uv, then stage 07's sample_bilinear on its image with TextureWrap::Repeat
//      (u wraps around the seam at -z), v first clamped to the centres of the top and bottom rows so
//      the poles never blend with the other side of the image;
//      CubeMap: cube_face_uv, then sample_bilinear on that face with TextureWrap::Clamp;
//   3. multiply by intensity.
// Images are read through scene.texture_view(index, false): they are stored linear.
// A scene whose environment kind is None gets scene.background.
Color environment_radiance(const Scene& scene, const Vec3& direction);

}  // namespace rt
