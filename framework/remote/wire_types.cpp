#include "remote/wire_types.h"

#include <xxhash.h>

namespace rt::remote {

Writer::Writer(HashOnly) : hash_(XXH3_createState()) {
    XXH3_64bits_reset(static_cast<XXH3_state_t*>(hash_));
}
Writer::~Writer() {
    if (hash_) XXH3_freeState(static_cast<XXH3_state_t*>(hash_));
}
void Writer::update_hash(const void* data, std::size_t size) {
    XXH3_64bits_update(static_cast<XXH3_state_t*>(hash_), data, size);
}
std::uint64_t Writer::digest() const {
    return hash_ ? XXH3_64bits_digest(static_cast<const XXH3_state_t*>(hash_)) : 0;
}

// Structs with bools: read as bytes, then every bool made 0 or 1.
void put(Writer& w, const Hit& v) {
    w.pod(v);
}
void get(Reader& r, Hit& v) {
    r.pod(v);
    normalize(v.front_face);
}
void put(Writer& w, const SurfacePoint& v) {
    w.pod(v);
}
void get(Reader& r, SurfacePoint& v) {
    r.pod(v);
    normalize(v.front_face);
}
void put(Writer& w, const SecondaryRays& v) {
    w.pod(v);
}
void get(Reader& r, SecondaryRays& v) {
    r.pod(v);
    normalize(v.reflected.valid);
    normalize(v.refracted.valid);
    normalize(v.total_internal_reflection);
}
void put(Writer& w, const FogEvent& v) {
    w.pod(v);
}
void get(Reader& r, FogEvent& v) {
    r.pod(v);
    normalize(v.scattered);
}

void put(Writer& w, const Image& v) {
    put(w, v.width);
    put(w, v.height);
    put(w, v.pixels);
}
void get(Reader& r, Image& v) {
    get(r, v.width);
    get(r, v.height);
    get(r, v.pixels);
    if (v.width < 0 || v.height < 0 || v.pixels.size() != std::size_t(v.width) * v.height) {
        r.fail();
        v = Image();
    }
}

void put(Writer& w, const Bvh& v) {
    put(w, v.nodes);
    put(w, v.primitives);
}
void get(Reader& r, Bvh& v) {
    get(r, v.nodes);
    get(r, v.primitives);
}

void put(Writer& w, const AccelerationReport& v) {
    put(w, v.requested);
    put(w, v.built);
    put(w, v.problem);
    put(w, v.build_ms);
    put(w, v.primitives);
    put(w, v.nodes);
    put(w, v.depth);
}
void get(Reader& r, AccelerationReport& v) {
    get(r, v.requested);
    get(r, v.built);
    get(r, v.problem);
    get(r, v.build_ms);
    get(r, v.primitives);
    get(r, v.nodes);
    get(r, v.depth);
}

// A render's options without its cancel flag (nothing in a test cancels across processes).
void put(Writer& w, const RenderOptions& v) {
    put(w, v.threads);
    put(w, v.show_progress);
    put(w, v.tile_size);
}
void get(Reader& r, RenderOptions& v) {
    get(r, v.threads);
    get(r, v.show_progress);
    get(r, v.tile_size);
    v.cancel = nullptr;
}

void put(Writer& w, const RayNode& v) {
    put(w, v.kind);
    put(w, v.depth);
    put(w, v.ray);
    put(w, v.ray_weight);
    put(w, v.weight);
    put(w, v.hit);
    put(w, v.hit_record);
    put(w, v.surface);
    put(w, v.local);
    put(w, v.contribution);
    put(w, v.shadows);
    put(w, v.children);
}
void get(Reader& r, RayNode& v) {
    get(r, v.kind);
    get(r, v.depth);
    get(r, v.ray);
    get(r, v.ray_weight);
    get(r, v.weight);
    get(r, v.hit);
    get(r, v.hit_record);
    get(r, v.surface);
    get(r, v.local);
    get(r, v.contribution);
    get(r, v.shadows);
    get(r, v.children);
    if (int(v.kind) < 0 || int(v.kind) > int(RayNode::Kind::Refraction)) r.fail();
}
void put(Writer& w, const PixelTree& v) {
    put(w, v.x);
    put(w, v.y);
    put(w, v.colour);
    put(w, v.root);
}
void get(Reader& r, PixelTree& v) {
    get(r, v.x);
    get(r, v.y);
    get(r, v.colour);
    get(r, v.root);
}

void put(Writer& w, const TextureView& v) {
    put(w, v.width);
    put(w, v.height);
    put(w, v.srgb);
    const std::size_t n =
        v.texels && v.width > 0 && v.height > 0 ? std::size_t(v.width) * v.height : 0;
    w.pod(std::uint64_t(n));
    w.bytes(v.texels, n * sizeof(Color));
}
void get(Reader& r, OwnedTextureView& v) {
    get(r, v.view.width);
    get(r, v.view.height);
    get(r, v.view.srgb);
    get(r, v.texels);
    v.view.texels = v.texels.empty() ? nullptr : v.texels.data();
}

void put(Writer& w, const LightVisibility& v) {
    w.pod(std::uint64_t(v.per_light.size()));
    w.bytes(v.per_light.data(), v.per_light.size_bytes());
}
void get(Reader& r, OwnedLightVisibility& v) {
    get(r, v.colours);
    v.view.per_light = v.colours;
}

}  // namespace rt::remote

namespace rt::remote {

constexpr std::size_t kSceneSize = 768;  // sizeof(Scene) when its codec was written (float)

// Every field but the OpenImageIO texture system, which the worker makes anew from the texture
// table (worker_serve.cpp). A field added to Scene must be added here: the size check says so.
static_assert(
    sizeof(Real) != sizeof(float) || sizeof(Scene) == kSceneSize,
    "Scene changed: add its new field to put/get(Scene) in framework/remote/wire_types.cpp");

// clang-format off
#define RT_SCENE_FIELDS(F) \
    F(source) F(camera) F(image) F(mode) F(background) F(ambient_light) F(max_depth) F(shadows) \
    F(fresnel) F(accelerator) F(texture_lookup) F(spheres) F(planes) F(boxes) F(vertices) \
    F(normals) F(uvs) F(triangles) F(materials) F(material_names) F(lights) F(area_lights) \
    F(moving_spheres) F(sampling) F(fog) F(textures) F(texture_names) F(texture_images) \
    F(texels) F(environment) F(features) F(revision) F(bvh)
// clang-format on

void put(Writer& w, const Scene& s) {
#define RT_PUT_FIELD(f) put(w, s.f);
    RT_SCENE_FIELDS(RT_PUT_FIELD)
#undef RT_PUT_FIELD
}
void get(Reader& r, Scene& s) {
#define RT_GET_FIELD(f) get(r, s.f);
    RT_SCENE_FIELDS(RT_GET_FIELD)
#undef RT_GET_FIELD
    normalize(s.shadows);
    normalize(s.fresnel);
}

}  // namespace rt::remote
