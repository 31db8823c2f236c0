#include "scene/prepared_scene.h"

namespace rt {

Features scene_features(const Scene& scene) {
    Features f;
    f.spheres = !scene.spheres.empty();
    f.planes = !scene.planes.empty();
    f.triangles = !scene.triangles.empty();
    f.boxes = !scene.boxes.empty();
    for (const std::shared_ptr<const Scene>& object : scene.objects) {  // what instances show
        f.spheres |= !object->spheres.empty();
        f.triangles |= !object->triangles.empty();
        f.boxes |= !object->boxes.empty();
    }
    auto nonzero = [](const Color& c) { return c.r > 0 || c.g > 0 || c.b > 0; };
    for (const Material& m : scene.materials) {
        f.ambient |= nonzero(m.ambient) && nonzero(scene.ambient_light);
        f.diffuse |= nonzero(m.diffuse);
        f.specular |= nonzero(m.specular);
        f.emissive |= nonzero(m.emissive);
        f.reflection |= nonzero(m.reflective);
        f.refraction |= nonzero(m.transmissive);
        f.textures |= m.diffuse_map.used() || m.specular_map.used() || m.emissive_map.used();
        f.normal_maps |= m.normal_map.used();
        for (const TextureSlot* slot :
             {&m.diffuse_map, &m.specular_map, &m.emissive_map, &m.normal_map}) {
            if (!slot->used() || std::size_t(slot->texture) >= scene.textures.size()) continue;
            switch (scene.textures[std::size_t(slot->texture)].kind) {
                case TextureKind::Image:
                    f.image_textures = true;
                    break;
                case TextureKind::Checker2D:
                case TextureKind::Checker3D:
                    f.checker_textures = true;
                    break;
                case TextureKind::Marble:
                    f.noise_textures = true;
                    break;
            }
        }
    }
    for (const Light& l : scene.lights) {
        f.point_lights |= l.kind == LightKind::Point;
        f.directional_lights |= l.kind == LightKind::Directional;
        f.light_links |= l.reach_mask != ~std::uint32_t(0) || !l.reach_rest || !l.casts_shadows;
    }
    f.shadows = scene.shadows && !scene.lights.empty();
    f.environment = scene.environment.kind != EnvironmentKind::None;
    f.antialiasing = scene.sampling.samples_per_pixel > 1;
    f.area_lights = !scene.area_lights.empty();
    f.depth_of_field =
        scene.sampling.aperture > 0 && scene.camera.projection == Projection::Perspective;
    auto moves = [&](const Scene& s) {
        for (const MovingSphere& m : s.moving_spheres)
            f.motion_blur |=
                m.velocity != Vec3(0) && scene.sampling.shutter_close > scene.sampling.shutter_open;
    };
    moves(scene);
    for (const std::shared_ptr<const Scene>& object : scene.objects) moves(*object);
    for (const Material& m : scene.materials) f.glossy |= m.fuzz > 0 && nonzero(m.reflective);
    f.ambient_occlusion = scene.sampling.indirect == IndirectLight::Occlusion && f.ambient;
    f.indirect_diffuse = scene.sampling.indirect == IndirectLight::Diffuse;
    f.fog = scene.fog.density > 0;
    f.path_tracing = scene.sampling.integrator == Integrator::Path;
    return f;
}

std::string Features::describe() const {
    std::string s;
    auto add = [&s](bool on, const char* name) {
        if (!on) return;
        if (!s.empty() && s.back() != ' ') s += ' ';
        s += name;
    };
    add(spheres, "spheres");
    add(planes, "planes");
    add(triangles, "triangles");
    add(boxes, "boxes");
    s += " |";
    add(ambient, "ambient");
    add(diffuse, "diffuse");
    add(specular, "specular");
    add(emissive, "emissive");
    add(reflection, "reflection");
    add(refraction, "refraction");
    s += " |";
    add(point_lights, "point");
    add(directional_lights, "directional");
    add(shadows, "shadows");
    add(light_links, "linked");
    if (textures || normal_maps) {
        s += " |";
        add(textures, "textures");
        add(normal_maps, "normal-maps");
        std::string kinds;  // e.g. " (images checkers)"
        for (auto [on, name] : {std::pair{image_textures, "images"},
                                {checker_textures, "checkers"},
                                {noise_textures, "noise"}})
            if (on) kinds += std::string(kinds.empty() ? " (" : " ") + name;
        if (!kinds.empty()) s += kinds + ")";
    }
    if (environment) s += " | environment";
    if (sampled()) {
        s += " | sampled:";
        add(antialiasing, "antialiasing");
        add(area_lights, "area-lights");
        add(depth_of_field, "depth-of-field");
        add(motion_blur, "motion-blur");
        add(glossy, "glossy");
        add(ambient_occlusion, "ambient-occlusion");
        add(indirect_diffuse, "indirect-diffuse");
        add(fog, "fog");
        add(path_tracing, "path-tracing");
    }
    return s;
}

}  // namespace rt
