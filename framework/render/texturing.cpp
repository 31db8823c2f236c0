#include "render/texturing.h"

#include <cmath>
#include <cstdint>

#include "scene/transform.h"
#include "stage_api/stage07.h"

namespace rt {

PlaneFrame plane_frame(const Vec3& normal) {
    // Down for every wall (t then points right as the wall is seen from the front), +z for a
    // floor or ceiling, where down is the normal itself.
    const Vec3 r = std::abs(normal.y) > Real(0.9) ? Vec3(0, 0, 1) : Vec3(0, -1, 0);
    PlaneFrame f;
    f.t = glm::normalize(glm::cross(normal, r));
    f.b = glm::cross(f.t, normal);
    return f;
}

Vec3 noise_gradient(int x, int y, int z) {
    // A fixed integer hash of the corner (no tables, no platform-dependent rand): the same
    // gradients on every machine and in GLSL.
    std::uint32_t h =
        std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(z) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    static const Real k = Real(0.70710678118654752);  // 1 / sqrt(2)
    static const Vec3 directions[12] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                        {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                        {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};
    return directions[h % 12] * k;
}

namespace {

// An instance's hit and surface point as its object sees them (object_view without the ray).
struct LocalHit {
    const PreparedScene* object = nullptr;
    const Instance* instance = nullptr;
    Hit hit;
    SurfacePoint at;
};

LocalHit local_hit(const PreparedScene& scene, std::size_t i, const Hit& hit,
                   const SurfacePoint& at) {
    LocalHit l;
    l.instance = &scene.instances[i];
    l.object = scene.prepared_objects[l.instance->object].get();
    l.hit = hit;
    l.hit.primitive = hit.object_primitive;
    l.at = at;
    l.at.point = object_point(*l.instance, at.point);
    l.at.normal = object_normal(*l.instance, at.normal);
    l.at.primitive = hit.object_primitive;
    return l;
}

}  // namespace

Vec2 surface_texcoord(const PreparedScene& scene, const Hit& hit, const SurfacePoint& at) {
    std::size_t i = 0;
    if (!scene.is_primitive(hit.primitive)) return Vec2(0);
    switch (scene.primitive_kind(hit.primitive, i)) {
        case Scene::Kind::Sphere: {
            const Sphere s = scene.sphere_at(i, at.time);
            return sphere_texcoord(glm::normalize(at.point - s.center));
        }
        case Scene::Kind::Plane:
            return plane_texcoord(scene.planes[i], at.point);
        case Scene::Kind::Box: {
            const Vec3 outward = at.front_face ? at.normal : -at.normal;
            return box_texcoord(scene.boxes[i], at.point, outward);
        }
        case Scene::Kind::Triangle: {
            Vec2 a, b, c;
            triangle_vertex_uvs(scene, i, a, b, c);
            return triangle_texcoord(a, b, c, hit.uv);
        }
        case Scene::Kind::Instance: {  // the object's own coordinates: textures move with it
            const LocalHit l = local_hit(scene, i, hit, at);
            return surface_texcoord(*l.object, l.hit, l.at);
        }
    }
    return Vec2(0);
}

namespace {

Vec3 any_perpendicular(const Vec3& n) {
    return plane_frame(n).t;
}

}  // namespace

Vec3 surface_tangent(const PreparedScene& scene, const Hit& hit, const SurfacePoint& at) {
    std::size_t i = 0;
    if (!scene.is_primitive(hit.primitive)) return any_perpendicular(at.normal);
    const Vec3 outward = at.front_face ? at.normal : -at.normal;
    switch (scene.primitive_kind(hit.primitive, i)) {
        case Scene::Kind::Sphere: {
            // u grows with phi = atan2(-z, x); the point is (cos phi, ., -sin phi) sin(theta),
            // so dP/dphi = (-sin phi, 0, -cos phi) sin(theta) = (z, 0, -x).
            const Vec3 d = outward;
            const Vec3 t(d.z, 0, -d.x);
            const Real length = glm::length(t);
            return length > Real(1e-6) ? t / length : Vec3(1, 0, 0);  // poles: any
        }
        case Scene::Kind::Plane:
            return plane_frame(scene.planes[i].normal).t;
        case Scene::Kind::Box:
            return plane_frame(outward).t;
        case Scene::Kind::Triangle: {
            Vec3 p0, p1, p2;
            scene.triangle_vertices(i, p0, p1, p2);
            Vec2 a, b, c;
            triangle_vertex_uvs(scene, i, a, b, c);
            const Vec3 e1 = p1 - p0, e2 = p2 - p0;
            const Vec2 d1 = b - a, d2 = c - a;
            const Real det = d1.x * d2.y - d2.x * d1.y;
            if (det != 0) {
                const Vec3 t = (e1 * d2.y - e2 * d1.y) / det;  // dP/du
                if (glm::length(t) > 0) return glm::normalize(t);
            }
            return any_perpendicular(at.normal);
        }
        case Scene::Kind::Instance: {  // the object's tangent, a direction: mapped by M
            const LocalHit l = local_hit(scene, i, hit, at);
            const Vec3 t = glm::mat<3, 3, Real>(l.instance->object_to_world) *
                           surface_tangent(*l.object, l.hit, l.at);
            return glm::length(t) > 0 ? glm::normalize(t) : any_perpendicular(at.normal);
        }
    }
    return any_perpendicular(at.normal);
}

namespace {

bool oiio_lookup(const PreparedScene& scene) {
    return (scene.texture_lookup == TextureLookup::Oiio ||
            scene.texture_lookup == TextureLookup::OiioAniso) &&
           scene.oiio_textures;
}

// The barycentrics (beta, gamma) of `p` (in the triangle's plane) in triangle i.
Vec2 barycentrics(const PreparedScene& scene, std::size_t i, const Vec3& p) {
    Vec3 p0, p1, p2;
    scene.triangle_vertices(i, p0, p1, p2);
    const Vec3 e1 = p1 - p0, e2 = p2 - p0, d = p - p0;
    const Real d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
    const Real det = d11 * d22 - d12 * d12;
    if (det == 0) return Vec2(0);
    const Real a = glm::dot(d, e1), b = glm::dot(d, e2);
    return Vec2((d22 * a - d12 * b) / det, (d11 * b - d12 * a) / det);
}

// uv at p', a point of the hit's tangent plane, and its difference from uv at the hit.
Vec2 texcoord_step(const PreparedScene& scene, const Hit& hit, const SurfacePoint& at, Vec2 uv,
                   const Ray& ray) {
    const Real facing = glm::dot(at.normal, ray.direction);
    if (std::abs(facing) < Real(1e-8)) return Vec2(0);
    const Real t = glm::dot(at.normal, at.point - ray.origin) / facing;
    if (!(t > 0) || !std::isfinite(t)) return Vec2(0);
    SurfacePoint moved = at;
    moved.point = ray.at(t);
    Hit moved_hit = hit;
    std::size_t i = 0;
    const bool primitive = scene.is_primitive(hit.primitive);
    const Scene::Kind kind =
        primitive ? scene.primitive_kind(hit.primitive, i) : Scene::Kind::Plane;
    if (primitive && kind == Scene::Kind::Triangle)
        moved_hit.uv = barycentrics(scene, i, moved.point);
    Vec2 step = surface_texcoord(scene, moved_hit, moved) - uv;
    // A sphere's u jumps from 1 to 0 at its seam; the footprint does not.
    if (primitive && kind == Scene::Kind::Sphere) step.x -= std::round(step.x);
    return step;
}

}  // namespace

TexcoordDerivatives texcoord_derivatives(const PreparedScene& scene, const Hit& hit,
                                         const SurfacePoint& at, const RayDifferential& rays) {
    TexcoordDerivatives d;
    d.dx = texcoord_step(scene, hit, at, at.texcoord, rays.x);
    d.dy = texcoord_step(scene, hit, at, at.texcoord, rays.y);
    return d;
}

Color evaluate_slot(const PreparedScene& scene, const TextureSlot& slot, Vec2 uv, const Vec3& point,
                    const TexcoordDerivatives& footprint) {
    if (!slot.used() || std::size_t(slot.texture) >= scene.textures.size()) return Color(1);
    const Texture& t = scene.textures[std::size_t(slot.texture)];
    const Vec2 mapped(uv.x * Real(slot.scale[0]) + Real(slot.offset[0]),
                      uv.y * Real(slot.scale[1]) + Real(slot.offset[1]));
    switch (t.kind) {
        case TextureKind::Image: {
            if (t.image < 0 || std::size_t(t.image) >= scene.texture_images.size()) return Color(1);
            if (oiio_lookup(scene)) {
                const Vec2 scale(slot.scale[0], slot.scale[1]);
                return scene.oiio_textures->lookup(
                    std::size_t(slot.texture), mapped,
                    TexcoordDerivatives{footprint.dx * scale, footprint.dy * scale});
            }
            const TextureView view = scene.texture_view(std::size_t(t.image), t.srgb);
            TextureFilter filter = t.filter;
            if (scene.texture_lookup == TextureLookup::Nearest) filter = TextureFilter::Nearest;
            if (scene.texture_lookup == TextureLookup::Bilinear) filter = TextureFilter::Bilinear;
            return filter == TextureFilter::Nearest ? sample_nearest(view, mapped, t.wrap)
                                                    : sample_bilinear(view, mapped, t.wrap);
        }
        case TextureKind::Checker2D:
            return checker_2d(mapped, t.a, t.b);
        case TextureKind::Checker3D:
            return checker_3d(point, t.a, t.b, Real(t.scale));
        case TextureKind::Marble:
            return marble(point, t.a, t.b, Real(t.scale));
    }
    return Color(1);
}

void apply_textures(const PreparedScene& scene, const Hit& hit, SurfacePoint& at,
                    const Vec3& to_viewer, Material& material, Vec3& lighting_normal,
                    const RayDifferential* rays) {
    at.texcoord = surface_texcoord(scene, hit, at);
    TexcoordDerivatives footprint;
    if (rays && oiio_lookup(scene)) footprint = texcoord_derivatives(scene, hit, at, *rays);
    if (material.diffuse_map.used()) {
        const Color c =
            evaluate_slot(scene, material.diffuse_map, at.texcoord, at.point, footprint);
        material.diffuse *= c;
        material.ambient *= c;  // ambient light lights the surface's own colour
    }
    if (material.specular_map.used())
        material.specular *=
            evaluate_slot(scene, material.specular_map, at.texcoord, at.point, footprint);
    if (material.emissive_map.used())
        material.emissive *=
            evaluate_slot(scene, material.emissive_map, at.texcoord, at.point, footprint);
    if (material.normal_map.used()) {
        // The map's stored values: a normal map is data, never sRGB-decoded (the loader marks
        // it so), so evaluate_slot returns the texel as stored.
        const Color texel =
            evaluate_slot(scene, material.normal_map, at.texcoord, at.point, footprint);
        lighting_normal =
            normal_from_map(lighting_normal, surface_tangent(scene, hit, at), texel, to_viewer);
    }
}

}  // namespace rt
