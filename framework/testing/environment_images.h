// The environment images of stage 08's scenes, made procedurally (no downloaded data): a small
// HDR lat-long sky and six labelled cube faces. tools/make_environment_images.cpp writes them to
// stages/08-environment/scenes/; Stage08.EnvironmentImages.* checks the committed files still
// are this code's output.
#pragma once

#include <filesystem>

#include "image/image.h"

namespace rt::testing {

// A 64x32 sky in lat-long layout (docs/conventions.md#environment-maps), linear HDR: a blue
// gradient above the horizon (v < 0.5), dark ground below with a checker in longitude, a marker
// on the horizon at each axis (-z red, +x green, +z blue, -x yellow, 4 texels wide) and a sun of
// radiance 12 at u = 0.0625, v = 0.3 (up and to the right of -z).
Image make_latlong_sky();

// Cube face `face` (0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z), 32x32: a colour of its own, a dark
// border, its name ("+X", ...) readable in the file, an arrow pointing to row 0 and a black
// square in the top-left corner (u = 0, v = 0), so any flip or turn of a face shows.
Image make_cube_face(int face);

// Writes sky.exr and cube/{px,nx,py,ny,pz,nz}.png into `folder`.
void write_environment_images(const std::filesystem::path& folder);

}  // namespace rt::testing
