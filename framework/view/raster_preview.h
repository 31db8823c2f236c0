// The raster preview beside the ray-traced image: the same scene and camera drawn by OpenGL with
// a per-pixel Blinn-Phong shader (no shadows, reflection, refraction or textures: what the ray
// tracer adds is what differs). A scene without lights gets a headlight. Needs the viewer's
// current GL context.
#pragma once

#include <epoxy/gl.h>

#include "scene/prepared_scene.h"

namespace rt::view {

class RasterPreview {
  public:
    // Tessellates the scene's surfaces once (spheres as icospheres, planes as large quads).
    explicit RasterPreview(const PreparedScene& scene);
    ~RasterPreview();
    RasterPreview(const RasterPreview&) = delete;
    RasterPreview& operator=(const RasterPreview&) = delete;

    // Draws the scene through `scene.camera` and its lights into the preview's texture
    // (scene.image size, row 0 at the bottom as GL stores it), restoring the default framebuffer.
    void draw(const PreparedScene& scene);
    GLuint texture() const { return color_; }
    std::size_t triangles() const { return vertex_count_ / 3; }

  private:
    GLuint program_ = 0, vao_ = 0, vbo_ = 0, fbo_ = 0, color_ = 0, depth_ = 0;
    GLsizei vertex_count_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace rt::view
