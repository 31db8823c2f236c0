// A scene made ready to render: its description (Scene) and what rendering builds from it.
// prepare_scene (render/prepare.h) is the one place that makes one, for every program; the
// renderer, the GPU port and the student functions that trace rays take a PreparedScene.
#pragma once

#include <memory>
#include <string>

#include "accel/bvh.h"
#include "scene/scene.h"

namespace rt {

// What a scene actually contains, so the renderer (and the shader) computes only that.
struct Features {
    bool spheres = false, planes = false, triangles = false, boxes = false;
    bool ambient = false, diffuse = false, specular = false, emissive = false;
    bool reflection = false, refraction = false;
    bool point_lights = false, directional_lights = false;
    bool shadows = false;      // the scene asks for shadows and has lights
    bool light_links = false;  // a light lights some materials only, or casts no shadows
    bool textures = false;     // a material has a diffuse, specular or emissive map (stage 07)
    bool normal_maps = false;  // a material has a normal map (stage 07)
    // The kinds of texture the slots use (what a shader must compile): images, the two
    // checkerboards, marble (gradient noise).
    bool image_textures = false, checker_textures = false, noise_textures = false;
    bool environment = false;  // rays that miss look up an environment map (stage 08)
    // Stage 10; any of them makes the renderer take several samples per pixel through stage 10
    // code (render/sampled.h); without them that code is never called.
    bool antialiasing = false;  // samples_per_pixel > 1
    bool area_lights = false, depth_of_field = false, motion_blur = false, glossy = false;
    bool ambient_occlusion = false, indirect_diffuse = false;
    bool fog = false;  // a medium of density > 0 (optional part of stage 10)
    // Stage 11: "integrator": "path"; every camera sample is path_radiance's (stage_api/stage11.h)
    bool path_tracing = false;

    bool sampled() const {
        return antialiasing || area_lights || depth_of_field || motion_blur || glossy ||
               ambient_occlusion || indirect_diffuse || fog || path_tracing;
    }

    std::string describe() const;  // e.g. "spheres planes | diffuse specular | point"
};

// The features of `scene`, from its primitives, materials, lights and settings.
Features scene_features(const Scene& scene);

class OiioTextures;  // render/oiio_textures.h

// Read it as the Scene it extends; the rest is filled by prepare_scene only.
struct PreparedScene : Scene {
    Features features;  // scene_features of the description, after the overrides
    Bvh bvh;            // stage 06's tree when accelerator == Bvh (build_acceleration)
    // The TextureSystem of TextureLookup::Oiio/OiioAniso (load_texture_system fills it).
    std::shared_ptr<const OiioTextures> oiio_textures;
    // Scene::objects, each prepared (build_acceleration): with the stage 06 BVH when this scene
    // has one, so the student's tree is the bottom level and this scene's tree, over the
    // instances' boxes, the top level. Shared between copies of this prepared scene.
    std::vector<std::shared_ptr<const PreparedScene>> prepared_objects;
};

// Step 3 of prepare_scene again, for a prepared scene whose settings or materials changed but not
// its geometry (the viewer's panel, its progressive passes, tests that build a scene by hand):
// the BVH and the texture system stay valid.
inline void refresh_features(PreparedScene& scene) {
    scene.features = scene_features(scene);
}

}  // namespace rt
