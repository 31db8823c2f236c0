#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace rt {

bool Scene::is_primitive(int id) const {
    if (id < 0) return false;
    std::size_t index = 0;
    switch (primitive_kind(id, index)) {
        case Kind::Sphere:
            return index < spheres.size();
        case Kind::Plane:
            return index < planes.size();
        case Kind::Triangle:
            return index < triangles.size();
        case Kind::Box:
            return index < boxes.size();
        case Kind::Instance:
            return index < instances.size();
    }
    return false;  // a kind this scene does not know
}

std::size_t Scene::primitive_rank(int id) const {
    std::size_t index = 0;
    std::size_t offset = 0;
    switch (primitive_kind(id, index)) {
        case Kind::Instance:
            offset += boxes.size();
            [[fallthrough]];
        case Kind::Box:
            offset += triangles.size();
            [[fallthrough]];
        case Kind::Triangle:
            offset += planes.size();
            [[fallthrough]];
        case Kind::Plane:
            offset += spheres.size();
            [[fallthrough]];
        case Kind::Sphere:
            break;
    }
    return offset + index;
}

int Scene::add_material(const Material& material, std::string name) {
    material_names.resize(materials.size());
    materials.push_back(material);
    material_names.push_back(std::move(name));
    return int(materials.size()) - 1;
}

const std::string& Scene::material_name(int m) const {
    static const std::string unnamed;
    return m >= 0 && std::size_t(m) < material_names.size() ? material_names[std::size_t(m)]
                                                            : unnamed;
}

std::size_t Scene::primitive_count() const {
    return spheres.size() + planes.size() + triangles.size() + boxes.size() + instances.size();
}

int Scene::add_texture_image(int width, int height, const std::vector<Color>& pixels) {
    texture_images.push_back(TextureImage{width, height, std::uint32_t(texels.size())});
    texels.insert(texels.end(), pixels.begin(), pixels.end());
    return int(texture_images.size()) - 1;
}

Vec3 Scene::moved_center(std::size_t i, Real time) const {
    for (const MovingSphere& m : moving_spheres)
        if (m.sphere == i) return spheres[i].center + time * m.velocity;
    return spheres[i].center;
}

Interval medium_interval(const Medium& medium, const Ray& ray, Interval range) {
    if (!medium.bounded) return range;
    for (int axis = 0; axis < 3; ++axis) {
        const Real o = ray.origin[axis], d = ray.direction[axis];
        if (d == 0) {
            if (o < medium.min[axis] || o > medium.max[axis]) return Interval{range.max, range.max};
            continue;
        }
        Real t0 = (medium.min[axis] - o) / d, t1 = (medium.max[axis] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        range.min = std::max(range.min, t0);
        range.max = std::min(range.max, t1);
    }
    if (!(range.min < range.max)) range.min = range.max;
    return range;
}

Vec3 shading_normal(const Scene& scene, std::size_t triangle, Vec2 barycentric_uv) {
    Vec3 a, b, c;
    scene.triangle_vertices(triangle, a, b, c);
    Vec3 geometric = glm::cross(b - a, c - a);
    Real geometric_length = glm::length(geometric);
    if (geometric_length > 0 && std::isfinite(geometric_length))
        geometric /= geometric_length;
    else
        geometric = Vec3(0);
    if (scene.normals.empty()) return geometric;

    const std::array<std::uint32_t, 3>& v = scene.triangles[triangle].v;
    const Vec3 n0 = scene.normals[v[0]], n1 = scene.normals[v[1]], n2 = scene.normals[v[2]];
    const Vec3 zero(0);
    if (n0 == zero || n1 == zero || n2 == zero) return geometric;
    const Real beta = barycentric_uv.x, gamma = barycentric_uv.y, alpha = 1 - beta - gamma;
    Vec3 n = alpha * n0 + beta * n1 + gamma * n2;
    Real length = glm::length(n);
    if (!(length > 0) || !std::isfinite(length)) return geometric;
    n /= length;
    return glm::dot(n, geometric) < 0 ? -n : n;
}

void triangle_vertex_uvs(const Scene& scene, std::size_t triangle, Vec2& a, Vec2& b, Vec2& c) {
    if (scene.uvs.empty()) {
        a = Vec2(0, 0);
        b = Vec2(1, 0);
        c = Vec2(0, 1);
        return;
    }
    const std::array<std::uint32_t, 3>& v = scene.triangles[triangle].v;
    a = scene.uvs[v[0]];
    b = scene.uvs[v[1]];
    c = scene.uvs[v[2]];
}

namespace {
// RenderMode's names, in the enum's order.
constexpr std::array<const char*, kRenderModeCount> kRenderModeNames = {
    "directions", "normals", "depth", "primitive", "shaded", "bvh_visits"};
}  // namespace

const char* to_string(RenderMode mode) {
    const int i = int(mode);
    return i >= 0 && i < kRenderModeCount ? kRenderModeNames[std::size_t(i)] : "?";
}

std::optional<RenderMode> parse_render_mode(std::string_view name) {
    for (int i = 0; i < kRenderModeCount; ++i)
        if (name == kRenderModeNames[std::size_t(i)]) return RenderMode(i);
    return std::nullopt;
}

std::vector<std::string> render_mode_names() {
    return {kRenderModeNames.begin(), kRenderModeNames.end()};
}

std::string join_render_mode_names(const std::string& separator) {
    std::string joined;
    for (const char* name : kRenderModeNames) joined += (joined.empty() ? "" : separator) + name;
    return joined;
}

const char* to_string(Accelerator accelerator) {
    return accelerator == Accelerator::Bvh ? "bvh" : "none";
}

const char* to_string(Scene::Kind kind) {
    switch (kind) {
        case Scene::Kind::Sphere:
            return "sphere";
        case Scene::Kind::Plane:
            return "plane";
        case Scene::Kind::Triangle:
            return "triangle";
        case Scene::Kind::Box:
            return "box";
        case Scene::Kind::Instance:
            return "instance";
    }
    return "?";
}

namespace {
// TextureLookup's names, in the enum's order.
constexpr std::array<const char*, 5> kTextureLookupNames = {"scene", "nearest", "bilinear", "oiio",
                                                            "oiio-aniso"};
static_assert(int(TextureLookup::OiioAniso) + 1 == kTextureLookupNames.size());
}  // namespace

const char* to_string(TextureLookup lookup) {
    const std::size_t i = std::size_t(lookup);
    return i < kTextureLookupNames.size() ? kTextureLookupNames[i] : "?";
}

std::optional<TextureLookup> parse_texture_lookup(std::string_view name) {
    for (std::size_t i = 0; i < kTextureLookupNames.size(); ++i)
        if (name == kTextureLookupNames[i]) return TextureLookup(i);
    return std::nullopt;
}

std::vector<std::string> texture_lookup_names() {
    return {kTextureLookupNames.begin(), kTextureLookupNames.end()};
}

}  // namespace rt
