// A scene in flat arrays: one array per primitive kind, materials and lights referenced by index.
// Keep it flat (no pointers, no virtual functions, no per-object heap allocations): the GPU stage
// packs these arrays into std430 storage buffers with gpu::pack_scene (framework/gpu/gpu_scene.h,
// the layout GLSL sees, checked against the driver by Framework.GpuLayout.*).
// File format: docs/scene-format.md.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "camera/camera.h"
#include "scene/environment.h"
#include "scene/texture.h"

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

// Plain data, as uploaded to the GPU; a material's name is in Scene::material_names.
struct Material {
    Color ambient{0};       // k_a
    Color diffuse{0.8f};    // k_d
    Color specular{0};      // k_s
    Color emissive{0};      // k_e
    float shininess = 32;   // n_s
    Color reflective{0};    // k_r
    Color transmissive{0};  // k_t
    float ior = 1.5f;       // index of refraction of the inside
    // Stage 07: textures multiply the colour they map (k_d and k_a by diffuse_map, k_s by
    // specular_map, k_e by emissive_map); normal_map bends the shading normal.
    TextureSlot diffuse_map, specular_map, emissive_map, normal_map;
    // Stage 10: glossy reflection; 0 is a perfect mirror. The reflected direction is perturbed
    // by fuzz times a random unit vector (docs/conventions.md#sampling).
    float fuzz = 0;
    // Stage 11 (path tracing): the GGX roughness of the specular lobe, alpha = roughness^2; 0 is
    // a perfect mirror (docs/conventions.md#path-tracing). Only the path tracer reads it.
    float roughness = 0;
};

enum class LightKind { Point, Directional };

struct Light {
    LightKind kind = LightKind::Point;
    Vec3 position{0};           // point lights
    Vec3 direction{0, -1, 0};   // directional lights: unit direction the light travels
    Color intensity{1};         // I_L
    Vec3 attenuation{1, 0, 1};  // point lights: 1 / (c + l r + q r^2)
    // Light linking (a fill light that lights some surfaces only): material m < kLinkedMaterials
    // is lit when bit m of reach_mask is set, a later one when reach_rest is; casts_shadows
    // false: nothing blocks this light. The framework applies both through the visibility it
    // gives direct_light (render/shade.cpp), so no stage's code tests them.
    std::uint32_t reach_mask = ~std::uint32_t(0);
    bool reach_rest = true;
    bool casts_shadows = true;
};
inline constexpr int kLinkedMaterials = 32;  // the materials a light's "only"/"except" may name

// Whether `light` lights a surface of material `material` (light linking).
inline bool light_reaches(const Light& light, int material) {
    if (material >= kLinkedMaterials) return light.reach_rest;
    return ((light.reach_mask >> material) & 1u) != 0;
}

// Stage 10: lights with an area, sampled for soft shadows. They emit `radiance` (L_e, the same
// in every direction of their lit side) and are not surfaces: rays that miss everything else
// never see them (docs/conventions.md#sampling). A rectangle is corner + s edge_u + t edge_v,
// s and t in [0, 1], lit on the side of normalize(cross(edge_u, edge_v)); a sphere is lit all
// round.
enum class AreaLightKind { Rectangle, Sphere };

struct AreaLight {
    AreaLightKind kind = AreaLightKind::Rectangle;
    Vec3 corner{0}, edge_u{1, 0, 0}, edge_v{0, 0, 1};  // rectangles
    Vec3 center{0};                                    // spheres
    Real radius = 1;
    Color radiance{1};
};

// Stage 10: a sphere whose centre moves while the shutter is open. It is Scene::spheres[sphere]
// at time 0 and spheres[sphere].center + time * velocity at `time`: a ray of that time meets it
// there (Ray::time, Scene::sphere_at).
struct MovingSphere {
    std::size_t sphere = 0;
    Vec3 velocity{0};
};

enum class PixelFilter { Box, Tent };
// How the ambient term k_a I_a is computed: as it is, scaled by Monte Carlo ambient occlusion,
// or replaced by a one-bounce Monte Carlo estimate of diffuse indirect light (stage 10).
enum class IndirectLight { Ambient, Occlusion, Diffuse };
// What computes a camera sample's radiance: stage 05's recursive ray tracer with stage 10's
// sampled terms, or stage 11's path tracer (path_radiance, stage_api/stage11.h).
enum class Integrator { Whitted, Path };

// Stage 10's settings (docs/scene-format.md#sampling). The defaults are the renderer of
// stages 01-09: one ray through each pixel centre, a pinhole, no shutter interval.
struct SamplingSettings {
    int samples_per_pixel = 1;
    std::uint64_t seed = 0;
    PixelFilter filter = PixelFilter::Box;
    Real aperture = 0;        // diameter of the thin lens; 0 is a pinhole
    Real focus_distance = 1;  // from the eye along the view direction to the plane in focus
    Real shutter_open = 0, shutter_close = 0;
    IndirectLight indirect = IndirectLight::Ambient;
    Real occlusion_distance = kInfinity;  // ambient occlusion: farther blockers do not count
    Integrator integrator = Integrator::Whitted;  // stage 11: "path" path-traces every sample
};

// Stage 10 (optional): fog, a homogeneous participating medium (docs/scene-format.md#fog). Light
// travelling a distance s through it is scattered or absorbed with probability
// 1 - exp(-density s); of the light it takes out, the fraction `albedo` (per channel) is
// scattered, equally into every direction. It fills the whole scene, or only the box [min, max]
// when `bounded`. Density 0 is no fog.
struct Medium {
    Real density = 0;  // sigma_t, the extinction per unit distance
    Color albedo{1};   // sigma_s / sigma_t, each channel in [0, 1]
    bool bounded = false;
    Vec3 min{0}, max{0};
};

// The part of `range` in which `ray` is inside the medium: `range` itself for a medium without a
// box, else its intersection with the box's slabs (closed box). Empty (min >= max) when the ray
// misses it. Framework code, given to stage 10's fog functions.
Interval medium_interval(const Medium& medium, const Ray& ray, Interval range);

// The per-primitive, material and light records are plain data: copied to the GPU as they are
// (after packing, framework/gpu/gpu_scene.h), so no strings or pointers inside.
static_assert(std::is_trivially_copyable_v<Sphere> && std::is_trivially_copyable_v<Plane> &&
              std::is_trivially_copyable_v<Box> && std::is_trivially_copyable_v<Triangle> &&
              std::is_trivially_copyable_v<Material> && std::is_trivially_copyable_v<Light>);

// A placement of one of Scene::objects (docs/scene-format.md#transforms-and-instances): the
// object's surfaces seen through an affine map. A ray meets it as world_to_object maps the ray
// into the object's space (the same t: the map is affine); normals go back by the inverse
// transpose, transpose(world_to_object). Made by the loader for a surface of "type": "instance",
// and for a rotated box or a non-uniformly scaled sphere (shapes a transform does not keep).
using Mat4 = glm::mat<4, 4, Real>;
struct Instance {
    Mat4 object_to_world{1};
    Mat4 world_to_object{1};
    std::size_t object = 0;  // index into Scene::objects
    int material = -1;       // >= 0: every hit on it has this material; -1: the object's own
};

struct PreparedScene;  // scene/prepared_scene.h

enum class RenderMode { Directions, Normals, Depth, PrimitiveId, Shaded, BvhVisits };
inline constexpr int kRenderModeCount = int(RenderMode::BvhVisits) + 1;

// How nearest-hit queries find the surface: stage 02's loop over every primitive, or the stage 06
// BVH (built once after loading, by build_acceleration in render/accelerate.h).
enum class Accelerator { None, Bvh };

// The deepest max_depth a scene may ask for: the scene loader's limit, the CPU tracer's fixed
// stack (render/shade.h) and the GPU's (render/gpu/gpu_render.cpp) all hold this many bounces.
inline constexpr int kMaxDepthLimit = 64;

// A scene as its file describes it (scene/scene_loader.h), or as a program or test builds it.
// Rendering needs more, built from it in one place: prepare_scene (render/prepare.h) makes a
// PreparedScene (scene/prepared_scene.h) with the features, the BVH and the texture system.
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
    Accelerator accelerator = Accelerator::None;
    TextureLookup texture_lookup = TextureLookup::PerTexture;  // stage 07

    std::vector<Sphere> spheres;
    std::vector<Plane> planes;
    std::vector<Box> boxes;
    std::vector<Vec3> vertices;
    // Per-vertex shading data, each either empty (no surface in the scene has any) or parallel
    // to `vertices`. A vertex without a normal (single triangles, meshes without normals) holds
    // the zero vector, which shading_normal reads as "use the geometric normal"; a vertex
    // without texture coordinates holds uv (0, 0). Read them through shading_normal and
    // triangle_vertex_uvs below.
    std::vector<Vec3> normals;
    std::vector<Vec2> uvs;
    std::vector<Triangle> triangles;
    std::vector<Material> materials;
    // Parallel to `materials` (may be shorter for scenes built in code): what the scene file or
    // the MTL library called each material, "" when unnamed. Kept out of Material so that every
    // struct the GPU receives is plain data.
    std::vector<std::string> material_names;
    std::vector<Light> lights;
    // Stage 10: area lights, moving spheres and the sampling settings.
    std::vector<AreaLight> area_lights;
    std::vector<MovingSphere> moving_spheres;
    SamplingSettings sampling;
    Medium fog;  // stage 10, optional: density 0 (the default) is no fog
    // Stage 07's texture table (scene/texture.h): textures referenced by material slots, the
    // images they read and all image texels in one array. texture_names parallels `textures`.
    std::vector<Texture> textures;
    std::vector<std::string> texture_names;
    std::vector<TextureImage> texture_images;
    std::vector<Color> texels;
    // Stage 08: what rays that hit nothing see when it is more than `background`. Its images are
    // entries of texture_images, stored linear (8-bit files decoded from sRGB on loading).
    Environment environment;
    // Named objects and their instances (docs/scene-format.md#transforms-and-instances). Each
    // object is the description of a scene of its own (its surfaces only, in its own space; its
    // materials index this scene's table), shared between copies of this scene. prepare_scene
    // prepares each (PreparedScene::prepared_objects). The GPU port draws a copy with each
    // instance's object in world space (render/gpu/flatten_instances.h).
    std::vector<Instance> instances;
    std::vector<std::shared_ptr<const Scene>> objects;
    std::vector<std::string> object_names;  // parallel to `objects`; "" for a shape's own

    // Global primitive ids: the kind in the top 4 bits, the index in its array below, so adding
    // a kind renumbers nothing (and a shader decodes an id with a shift and a mask). Ids of one
    // kind are ordered by index and kinds in this order, so sorting ids sorts as before.
    enum class Kind { Sphere, Plane, Triangle, Box, Instance };
    static constexpr int kKindShift = 28;
    static constexpr std::size_t kMaxPrimitivesOfAKind = std::size_t(1) << kKindShift;
    static constexpr int primitive_id(Kind kind, std::size_t index) {
        return int(kind) << kKindShift | int(index);
    }
    // The inverse of primitive_id (no bounds check: see is_primitive). Inline: every BVH leaf
    // test goes through it.
    static Kind primitive_kind(int id, std::size_t& index) {
        index = std::size_t(id) & (kMaxPrimitivesOfAKind - 1);
        return Kind(id >> kKindShift);
    }
    // True when `id` names a primitive of this scene.
    bool is_primitive(int id) const;
    std::size_t primitive_count() const;
    // Appends an image's texels to the texture table (texture_images, texels); returns its index.
    // `pixels`: width * height values, row 0 at the top.
    int add_texture_image(int width, int height, const std::vector<Color>& pixels);
    // Appends a material and its name; returns its index.
    int add_material(const Material& material, std::string name = "");
    // The name of material `m`, or "" (unnamed, or out of range).
    const std::string& material_name(int m) const;
    // The position of `id` when every primitive is listed spheres first, then planes, triangles,
    // boxes and instances: the number debug colours are made from (the primitive-id view).
    std::size_t primitive_rank(int id) const;

    // Sphere i as a ray of time `time` meets it: moved along its velocity when it is one of the
    // moving_spheres (stage 10's motion blur), else as stored. Every sphere test reads spheres
    // through it; without moving spheres it is spheres[i].
    Sphere sphere_at(std::size_t i, Real time) const {
        Sphere s = spheres[i];
        if (!moving_spheres.empty()) s.center = moved_center(i, time);
        return s;
    }

    void triangle_vertices(std::size_t i, Vec3& a, Vec3& b, Vec3& c) const {
        a = vertices[triangles[i].v[0]];
        b = vertices[triangles[i].v[1]];
        c = vertices[triangles[i].v[2]];
    }

    // The centre of sphere i at `time` (sphere_at, when the scene has moving spheres).
    Vec3 moved_center(std::size_t i, Real time) const;
    // The texels of texture_images[i] (no bounds check).
    TextureView texture_view(std::size_t image, bool srgb) const {
        const TextureImage& t = texture_images[image];
        return TextureView{texels.data() + t.first, t.width, t.height, srgb};
    }
};

// The unit shading normal of triangle `triangle` at barycentric coordinates `barycentric_uv`
// = (beta, gamma) (Hit::uv): its vertex normals interpolated and normalised, turned if needed
// to the side of the geometric normal normalize(cross(b - a, c - a)), so it can stand in for
// the outward normal. It is the geometric normal when the scene has no vertex normals, a corner
// has none (zero) or the interpolation cancels out; the zero vector for a degenerate triangle
// without vertex normals.
Vec3 shading_normal(const Scene& scene, std::size_t triangle, Vec2 barycentric_uv);

// The texture coordinates of the three corners of triangle `triangle`
// (docs/conventions.md#texture-coordinates): its vertex uvs; when no surface of the scene has
// any, (0, 0), (1, 0) and (0, 1), so that a texture spans each triangle; a vertex without uvs
// in a scene that has some holds (0, 0).
void triangle_vertex_uvs(const Scene& scene, std::size_t triangle, Vec2& a, Vec2& b, Vec2& c);

// A mode's name in scene files, on the command line and in the viewer: "directions", "normals",
// "depth", "primitive", "shaded", "bvh_visits" (one table, scene.cpp).
const char* to_string(RenderMode mode);
std::optional<RenderMode> parse_render_mode(std::string_view name);  // nullopt: no such mode
std::vector<std::string> render_mode_names();                        // in RenderMode's order
std::string join_render_mode_names(const std::string& separator);  // e.g. "directions|normals|…"
const char* to_string(Accelerator accelerator);
// A primitive kind's name in messages, the ray tree and the viewer: "sphere", "plane", ...
const char* to_string(Scene::Kind kind);
// A texture lookup's name on the command line (--texture-filter) and in the viewer: "scene"
// (each texture's own filter), "nearest", "bilinear", "oiio", "oiio-aniso" (one table, scene.cpp).
const char* to_string(TextureLookup lookup);
std::optional<TextureLookup> parse_texture_lookup(std::string_view name);  // nullopt: no such one
std::vector<std::string> texture_lookup_names();                           // in the enum's order

}  // namespace rt
