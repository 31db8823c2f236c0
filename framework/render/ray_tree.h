// The ray-tree debugger: `rt render SCENE --debug-pixel X,Y [--debug-format json]` and
// `--overlay-pixel X,Y`.
#pragma once

#include <optional>
#include <string>

#include "image/image.h"
#include "render/shade.h"

namespace rt {

struct PixelTree {
    int x = 0, y = 0;
    Color color{0};  // the pixel's linear colour, as the shaded render computes it
    RayNode root;
};

// "sphere 1 (id 1)", "none"; a material's name in quotes, or "#M" when it has none: as the
// tree names them (the GPU's --debug-pixel too).
std::string primitive_name(const PreparedScene& scene, int id);
std::string material_name(const PreparedScene& scene, int m);
// Light linking at a hit of `material`: "reached by lights 0, 1 (no shadows: 1); not by 2".
std::string light_links_text(const PreparedScene& scene, int material);

// Traces pixel (x, y) of the shaded render, recording every ray.
PixelTree debug_pixel(const PreparedScene& scene, int x, int y);

// The tree as indented text, one ray or shadow ray per line.
std::string ray_tree_text(const PreparedScene& scene, const PixelTree& tree);

// The same as JSON: {"pixel", "color", "max_depth", "shadows", "fresnel", "tree": {ray node}}
// where each node has "kind", "depth", "origin", "direction", "ray_weight", "weight", "hit"
// (null on a miss; else t, point, normal, front_face, primitive, primitive_kind, material,
// material_name), "local", "contribution", "shadow_rays" and "children". The contributions of
// all nodes sum to "color".
std::string ray_tree_json(const PreparedScene& scene, const PixelTree& tree);

// Where a world point lands on the image (pixel units, docs/conventions.md#pixels), or nothing
// when it is behind a perspective camera.
std::optional<Vec2> project_to_image(const PreparedScene& scene, const Vec3& point);

// Draws the tree's rays onto `image` (linear colours): camera ray red, shadow rays magenta,
// reflected rays blue, refracted rays yellow; rays that miss are drawn a long way out.
void draw_ray_tree(const PreparedScene& scene, const PixelTree& tree, Image& image);

}  // namespace rt
