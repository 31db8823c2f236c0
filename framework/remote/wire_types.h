// The codecs of the framework's types that cannot cross as plain bytes (wire.h): those holding
// containers, pointers or bools that a test reads, and the scene, which crosses by handle.
#pragma once

#include <concepts>
#include <memory>
#include <tuple>
#include <type_traits>
#include <vector>

#include "image/image.h"
#include "remote/wire.h"
#include "render/accelerate.h"
#include "render/gpu/gpu_cases.h"
#include "render/gpu/gpu_render.h"
#include "render/gpu/shadertoy_run.h"
#include "render/ray_tree.h"
#include "render/render.h"
#include "render/shade.h"
#include "scene/prepared_scene.h"
#include "stage_api/stage03.h"
#include "stage_api/stage05.h"
#include "stage_api/stage10.h"
#include "stage_api/stage11.h"

namespace rt::remote {

// What the worker holds for a parameter of type T (remote_call.h): T itself, or, for a type
// that points into memory it does not own, T with that memory (specialized below).
template <class T>
struct StorageFor {
    using type = T;
};
template <class T>
using Storage = typename StorageFor<T>::type;
template <class T>
const T& view(const T& value) {
    return value;
}

// Structs with bools that cross per ray: as bytes, then the bools RT_WIRE_BOOLS names made 0 or 1.
#define RT_WIRE_BOOLS(Type, ...)                        \
    template <>                                         \
    inline constexpr bool kBytesWithBools<Type> = true; \
    inline auto wire_bools(Type& v) {                   \
        return std::tie(__VA_ARGS__);                   \
    }
RT_WIRE_BOOLS(Hit, v.front_face)
RT_WIRE_BOOLS(SurfacePoint, v.front_face)
RT_WIRE_BOOLS(SecondaryRays, v.reflected.valid, v.refracted.valid, v.total_internal_reflection)
RT_WIRE_BOOLS(FogEvent, v.scattered)
RT_WIRE_BOOLS(BsdfSample, v.delta)
RT_WIRE_BOOLS(Light, v.reach_rest, v.casts_shadows)
#undef RT_WIRE_BOOLS
template <class T>
requires kBytesWithBools<T>
void put(Writer& w, const T& v) {
    w.pod(v);
}
template <class T>
requires kBytesWithBools<T>
void get(Reader& r, T& v) {
    r.pod(v);
    std::apply([](auto&... b) { (normalize(b), ...); }, wire_bools(v));
}
// Types that cross field by field name their fields once, for both directions.
#define RT_WIRE_FIELDS(Type, ...)                       \
    template <>                                         \
    inline constexpr bool kFieldByField<Type> = true;   \
    template <class T>                                  \
    requires std::same_as<std::remove_const_t<T>, Type> \
    auto wire_fields(T& v) {                            \
        return std::tie(__VA_ARGS__);                   \
    }
RT_WIRE_FIELDS(Image, v.width, v.height, v.pixels)
RT_WIRE_FIELDS(Image8, v.width, v.height, v.data)
RT_WIRE_FIELDS(Bvh, v.nodes, v.primitives)
RT_WIRE_FIELDS(AccelerationReport, v.requested, v.built, v.problem, v.build_ms, v.primitives,
               v.nodes, v.depth)
RT_WIRE_FIELDS(RayNode, v.kind, v.depth, v.ray, v.ray_weight, v.weight, v.hit, v.hit_record,
               v.surface, v.local, v.contribution, v.shadows, v.children)
RT_WIRE_FIELDS(PixelTree, v.x, v.y, v.color, v.root)
RT_WIRE_FIELDS(gpu_cases::GpuAnswer, v.found, v.t, v.normal, v.front_face, v.uv)
RT_WIRE_FIELDS(ShadertoyRun, v.compile_errors, v.draw_error, v.image)
// An instanced object (Scene::objects, PreparedScene::prepared_objects): a flag for null, then
// the scene.
void put(Writer& w, const std::shared_ptr<const Scene>& v);
void get(Reader& r, std::shared_ptr<const Scene>& v);
void put(Writer& w, const std::shared_ptr<const PreparedScene>& v);
void get(Reader& r, std::shared_ptr<const PreparedScene>& v);
// Every field but the OpenImageIO texture system, which the worker makes anew from the texture
// table (worker_serve.cpp). wire_types.cpp checks the size: a new field must be added here.
RT_WIRE_FIELDS(Scene, v.source, v.camera, v.image, v.mode, v.background, v.ambient_light,
               v.max_depth, v.shadows, v.fresnel, v.accelerator, v.texture_lookup, v.spheres,
               v.planes, v.boxes, v.vertices, v.normals, v.uvs, v.triangles, v.materials,
               v.material_names, v.lights, v.area_lights, v.moving_spheres, v.sampling, v.fog,
               v.textures, v.texture_names, v.texture_images, v.texels, v.environment, v.instances,
               v.objects, v.object_names)
#undef RT_WIRE_FIELDS

template <class T>
concept Fielded = requires(T& v) {
    wire_fields(v);
};

// What a decoded value must satisfy besides its fields' own checks (none by default).
template <class T>
void check_decoded(Reader&, T&) {}
void check_decoded(Reader& r, Image& v);
void check_decoded(Reader& r, Image8& v);
void check_decoded(Reader& r, RayNode& v);
void check_decoded(Reader& r, Scene& v);

template <Fielded T>
void put(Writer& w, const T& v) {
    std::apply([&](const auto&... field) { (put(w, field), ...); }, wire_fields(v));
}
template <Fielded T>
void get(Reader& r, T& v) {
    std::apply([&](auto&... field) { (get(r, field), ...); }, wire_fields(v));
    check_decoded(r, v);
}

// A prepared scene: its description, then what prepare_scene built but the OpenImageIO texture
// system, which the worker loads anew (load_texture_system).
void put(Writer& w, const PreparedScene& v);
void get(Reader& r, PreparedScene& v);

// A render's options without its cancel flag (nothing in a test cancels across processes).
void put(Writer& w, const RenderOptions& v);
void get(Reader& r, RenderOptions& v);

// A GPU render's options without its log, timings and cancel flag (a test sets none; the judge
// refuses to send them).
void put(Writer& w, const GpuRenderOptions& v);
void get(Reader& r, GpuRenderOptions& v);

// A texture view crosses with its texels, light visibility with its per-light colours; the
// worker's copy of the view points into its own storage.
template <typename View>
struct Owned {
    std::vector<Color> data;
    View view;
};
template <typename View>
const View& view(const Owned<View>& v) {
    return v.view;
}
template <>
struct StorageFor<TextureView> {
    using type = Owned<TextureView>;
};
template <>
struct StorageFor<LightVisibility> {
    using type = Owned<LightVisibility>;
};
void put(Writer& w, const TextureView& v);
void get(Reader& r, Owned<TextureView>& v);
void put(Writer& w, const LightVisibility& v);
void get(Reader& r, Owned<LightVisibility>& v);

}  // namespace rt::remote
