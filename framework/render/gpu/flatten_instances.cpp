#include "render/gpu/flatten_instances.h"

#include <cmath>
#include <string>

#include "render/gpu/gpu_render.h"
#include "render/prepare.h"
#include "scene/transform.h"

namespace rt {
namespace {

Vec3 world_point(const Instance& instance, const Vec3& p) {
    return transform_point(glm::dmat4(instance.object_to_world), p);
}

// The scale of a map that turns and scales evenly (a sphere stays a sphere); 0 otherwise.
// scene/transform.h's similarity_scale asks this of the loader's double matrices to 1e-9; an
// instance keeps its map in Real, whose rounding alone is about 1e-7.
Real even_scale(const Mat4& m) {
    const Vec3 x(m[0]), y(m[1]), z(m[2]);
    const Real s = glm::length(x);
    const Real tolerance = Real(1e-4) * s;
    const bool even =
        std::abs(glm::length(y) - s) <= tolerance && std::abs(glm::length(z) - s) <= tolerance &&
        std::abs(glm::dot(x, y)) <= tolerance * s && std::abs(glm::dot(y, z)) <= tolerance * s &&
        std::abs(glm::dot(z, x)) <= tolerance * s;
    return even ? s : 0;
}

class Flattener {
  public:
    Flattener(Scene& flat, bool normals, bool uvs, bool textured, const std::string& where)
        : flat_(flat), normals_(normals), uvs_(uvs), textured_(textured), where_(where) {}

    void add(const Instance& instance, const Scene& object) {
        const int material_override = instance.material;
        auto material = [&](int own) { return material_override >= 0 ? material_override : own; };
        for (const Sphere& s : object.spheres) add_sphere(instance, s, material(s.material));
        for (const Box& b : object.boxes) add_box(instance, b, material(b.material));
        add_triangles(instance, object, material_override);
    }

  private:
    void add_sphere(const Instance& instance, const Sphere& s, int material) {
        const Real scale = even_scale(instance.object_to_world);
        if (scale == 0)
            throw GpuError(where_ +
                           ": a sphere of an instance is scaled unevenly (an "
                           "ellipsoid), which the GPU port cannot draw; render it on "
                           "the CPU (rt render without --gpu)");
        flat_.spheres.push_back({world_point(instance, s.center), s.radius * scale, material});
    }

    // A box stays a box under moves, scales and quarter turns; turned otherwise it becomes its
    // 12 triangles (the same surface; a textured one would lose the box's texture coordinates).
    void add_box(const Instance& instance, const Box& b, int material) {
        if (keeps_axes(glm::dmat4(instance.object_to_world))) {
            const Vec3 a = world_point(instance, b.min), c = world_point(instance, b.max);
            flat_.boxes.push_back({glm::min(a, c), glm::max(a, c), material});
            return;
        }
        if (textured_)
            throw GpuError(where_ +
                           ": a turned box in a textured scene, which the GPU port "
                           "draws as triangles without the box's texture coordinates; "
                           "render it on the CPU (rt render without --gpu)");
        Scene box;
        for (int corner = 0; corner < 8; ++corner)  // bit 0: x, bit 1: y, bit 2: z at max
            box.vertices.push_back(Vec3(corner & 1 ? b.max.x : b.min.x,
                                        corner & 2 ? b.max.y : b.min.y,
                                        corner & 4 ? b.max.z : b.min.z));
        // Each face counter-clockwise seen from outside: -x +x -y +y -z +z.
        static constexpr std::uint32_t kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
        for (const auto& f : kFaces) {
            box.triangles.push_back({{f[0], f[1], f[2]}, b.material});
            box.triangles.push_back({{f[0], f[2], f[3]}, b.material});
        }
        add_triangles(instance, box, material);
    }

    // The object's vertices in world space, its normals by the inverse transpose (a zero normal,
    // "use the geometric one", stays zero), and its triangles on them. A map that mirrors turns
    // the winding, so two corners swap to keep each triangle's normal where the CPU's is.
    void add_triangles(const Instance& instance, const Scene& object, int material_override) {
        const std::uint32_t base = std::uint32_t(flat_.vertices.size());
        for (const Vec3& v : object.vertices) flat_.vertices.push_back(world_point(instance, v));
        const glm::dmat3 to_world_normal = normal_matrix(glm::dmat4(instance.object_to_world));
        if (normals_)
            for (std::size_t i = 0; i < object.vertices.size(); ++i) {
                const Vec3 n = object.normals.empty() ? Vec3(0) : object.normals[i];
                flat_.normals.push_back(transform_normal(to_world_normal, n));
            }
        if (uvs_)
            for (std::size_t i = 0; i < object.vertices.size(); ++i)
                flat_.uvs.push_back(object.uvs.empty() ? Vec2(0) : object.uvs[i]);
        const bool mirrored = glm::determinant(glm::mat<3, 3, Real>(instance.object_to_world)) < 0;
        for (const Triangle& t : object.triangles) {
            Triangle placed{{base + t.v[0], base + t.v[1], base + t.v[2]},
                            material_override >= 0 ? material_override : t.material};
            if (mirrored) std::swap(placed.v[1], placed.v[2]);
            flat_.triangles.push_back(placed);
        }
    }

    Scene& flat_;
    bool normals_, uvs_;  // whether the flat scene keeps vertex normals, texture coordinates
    bool textured_;       // whether the scene has texture or normal maps
    const std::string& where_;
};

}  // namespace

PreparedScene flatten_instances(const PreparedScene& scene, RenderMode mode) {
    const std::string where = scene.source.empty() ? "the scene" : scene.source;
    if (mode == RenderMode::PrimitiveId || mode == RenderMode::BvhVisits)
        throw GpuError(where + ": mode \"" + to_string(mode) +
                       "\" shows primitives and the tree, and the GPU port draws instances as a "
                       "copy of their objects in world space: use another mode, or render it on "
                       "the CPU (rt render without --gpu)");
    Scene flat = scene;
    flat.instances.clear();
    flat.objects.clear();
    flat.object_names.clear();
    // Shading data stays parallel to the vertices: present when any object or the scene has it.
    bool normals = !scene.normals.empty(), uvs = !scene.uvs.empty();
    for (const Instance& instance : scene.instances) {
        normals |= !scene.objects[instance.object]->normals.empty();
        uvs |= !scene.objects[instance.object]->uvs.empty();
    }
    if (normals) flat.normals.resize(flat.vertices.size(), Vec3(0));
    if (uvs) flat.uvs.resize(flat.vertices.size(), Vec2(0));
    const bool textured = scene.features.textures || scene.features.normal_maps;
    Flattener flattener(flat, normals, uvs, textured, where);
    for (const Instance& instance : scene.instances)
        flattener.add(instance, *scene.objects[instance.object]);
    PreparedScene out = prepare_scene(std::move(flat));
    out.oiio_textures = scene.oiio_textures;
    return out;
}

}  // namespace rt
