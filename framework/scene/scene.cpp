#include "scene/scene.h"

namespace rt {

int Scene::primitive_id(Kind kind, std::size_t index) const {
    std::size_t offset = 0;
    switch (kind) {
        case Kind::Box: offset += triangles.size(); [[fallthrough]];
        case Kind::Triangle: offset += planes.size(); [[fallthrough]];
        case Kind::Plane: offset += spheres.size(); [[fallthrough]];
        case Kind::Sphere: break;
    }
    return int(offset + index);
}

std::size_t Scene::primitive_count() const {
    return spheres.size() + planes.size() + triangles.size() + boxes.size();
}

Scene::Kind Scene::primitive_kind(int id, std::size_t& index) const {
    std::size_t i = std::size_t(id);
    if (i < spheres.size()) return index = i, Kind::Sphere;
    i -= spheres.size();
    if (i < planes.size()) return index = i, Kind::Plane;
    i -= planes.size();
    if (i < triangles.size()) return index = i, Kind::Triangle;
    i -= triangles.size();
    return index = i, Kind::Box;
}

void Scene::update_features() {
    Features f;
    f.spheres = !spheres.empty();
    f.planes = !planes.empty();
    f.triangles = !triangles.empty();
    f.boxes = !boxes.empty();
    auto nonzero = [](const Color& c) { return c.r > 0 || c.g > 0 || c.b > 0; };
    for (const Material& m : materials) {
        f.ambient |= nonzero(m.ambient) && nonzero(ambient_light);
        f.diffuse |= nonzero(m.diffuse);
        f.specular |= nonzero(m.specular);
        f.emissive |= nonzero(m.emissive);
        f.reflection |= nonzero(m.reflective);
        f.refraction |= nonzero(m.transmissive);
    }
    for (const Light& l : lights) {
        f.point_lights |= l.kind == LightKind::Point;
        f.directional_lights |= l.kind == LightKind::Directional;
    }
    f.shadows = shadows && !lights.empty();
    features = f;
}

std::string Features::describe() const {
    std::string s;
    auto add = [&s](bool on, const char* name) {
        if (!on) return;
        if (!s.empty() && s.back() != ' ') s += ' ';
        s += name;
    };
    add(spheres, "spheres"), add(planes, "planes"), add(triangles, "triangles"), add(boxes, "boxes");
    s += " |";
    add(ambient, "ambient"), add(diffuse, "diffuse"), add(specular, "specular");
    add(emissive, "emissive"), add(reflection, "reflection"), add(refraction, "refraction");
    s += " |";
    add(point_lights, "point"), add(directional_lights, "directional");
    add(shadows, "shadows");
    return s;
}

const char* to_string(RenderMode mode) {
    switch (mode) {
        case RenderMode::Directions: return "directions";
        case RenderMode::Normals: return "normals";
        case RenderMode::Depth: return "depth";
        case RenderMode::PrimitiveId: return "primitive";
        case RenderMode::Shaded: return "shaded";
    }
    return "?";
}

}  // namespace rt
