// A scene in flat arrays: one array per primitive kind, materials and lights referenced by index.
// The layout maps one-to-one onto GLSL storage buffers for the GPU stage, so keep it flat:
// no pointers, no virtual functions, no per-object heap allocations.
// File format: docs/scene-format.md.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "camera/camera.h"

namespace rt {

struct Sphere {
    Vec3 center{0};
    Real radius = 1;
    int material = 0;
};

struct Plane {
    Vec3 point{0};
    Vec3 normal{0, 1, 0};  // unit length; the outward side
    int material = 0;
};

struct Box {  // axis-aligned
    Vec3 min{-1};
    Vec3 max{1};
    int material = 0;
};

// A triangle indexes three entries of Scene::vertices. Single triangles and mesh triangles live
// in the same array.
struct Triangle {
    std::array<std::uint32_t, 3> v{};
    int material = 0;
};

struct Material {
    std::string name;
    Color ambient{0};      // k_a
    Color diffuse{0.8f};   // k_d
    Color specular{0};     // k_s
    Color emissive{0};     // k_e
    float shininess = 32;  // n_s
    Color reflective{0};   // k_r
    Color transmissive{0}; // k_t
    float ior = 1.5f;      // index of refraction of the inside
};

enum class LightKind { Point, Directional };

struct Light {
    LightKind kind = LightKind::Point;
    Vec3 position{0};            // point lights
    Vec3 direction{0, -1, 0};    // directional lights: unit direction the light travels
    Color intensity{1};          // I_L
    Vec3 attenuation{1, 0, 1};   // point lights: 1 / (c + l r + q r^2)
};

// What a scene actually contains, so the renderer (and later the shader) computes only that.
struct Features {
    bool spheres = false, planes = false, triangles = false, boxes = false;
    bool ambient = false, diffuse = false, specular = false, emissive = false;
    bool reflection = false, refraction = false;
    bool point_lights = false, directional_lights = false;
    bool shadows = false;  // the scene asks for shadows and has lights

    std::string describe() const;  // e.g. "spheres planes | diffuse specular | point"
};

enum class RenderMode { Directions, Normals, Depth, PrimitiveId, Shaded };

struct Scene {
    std::string source;  // the file it was loaded from, for messages
    Camera camera;
    ImageSize image{640, 480};
    RenderMode mode = RenderMode::Normals;
    Color background{0};
    Color ambient_light{0};  // I_a
    int max_depth = 5;       // bounces of reflected/refracted rays; 0: direct light only
    bool shadows = false;    // trace shadow rays (stage 04)
    bool fresnel = false;    // Schlick-weighted reflection on transmissive materials (stage 05)

    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    std::vector<Box> boxes;
    std::vector<Vec3> vertices;
    std::vector<Triangle> triangles;
    std::vector<Material> materials;
    std::vector<Light> lights;

    Features features;  // filled by update_features()

    // Global primitive ids number spheres first, then planes, triangles and boxes.
    enum class Kind { Sphere, Plane, Triangle, Box };
    int primitive_id(Kind kind, std::size_t index) const;
    std::size_t primitive_count() const;
    // The inverse of primitive_id: the kind of primitive `id` and its index in that array.
    Kind primitive_kind(int id, std::size_t& index) const;

    void triangle_vertices(std::size_t i, Vec3& a, Vec3& b, Vec3& c) const {
        a = vertices[triangles[i].v[0]];
        b = vertices[triangles[i].v[1]];
        c = vertices[triangles[i].v[2]];
    }

    void update_features();
};

const char* to_string(RenderMode mode);

}  // namespace rt
