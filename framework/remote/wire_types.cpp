#include "remote/wire_types.h"

#include <xxhash.h>

#include <stdexcept>

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

void check_decoded(Reader& r, Image& v) {
    if (v.width < 0 || v.height < 0 || v.pixels.size() != std::size_t(v.width) * v.height) {
        r.fail();
        v = Image();
    }
}

void check_decoded(Reader& r, Image8& v) {
    if (v.width < 0 || v.height < 0 || v.data.size() != std::size_t(v.width) * v.height * 3) {
        r.fail();
        v = Image8();
    }
}

void check_decoded(Reader& r, RayNode& v) {
    if (int(v.kind) < 0 || int(v.kind) > int(RayNode::Kind::Refraction)) r.fail();
}

// Every instance places an object the scene has.
void check_decoded(Reader& r, Scene& v) {
    for (const Instance& instance : v.instances)
        if (instance.object >= v.objects.size()) r.fail();
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

void put(Writer& w, const GpuRenderOptions& v) {
    if (v.log || v.timings || v.cancel)
        throw std::invalid_argument("a GPU render's log, timings or cancel flag cannot cross");
    put(w, v.context);
    put(w, v.student_dir.string());
    put(w, v.uber);
    put(w, v.sampling_dir.string());
    put(w, v.samples_per_dispatch);
    put(w, v.path_dir.string());
}
void get(Reader& r, GpuRenderOptions& v) {
    std::string student_dir, sampling_dir, path_dir;
    get(r, v.context);
    get(r, student_dir);
    get(r, v.uber);
    get(r, sampling_dir);
    get(r, v.samples_per_dispatch);
    get(r, path_dir);
    if (int(v.context) < int(GlKind::Egl) || int(v.context) > int(GlKind::Window)) r.fail();
    v.student_dir = student_dir;
    v.sampling_dir = sampling_dir;
    v.path_dir = path_dir;
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
void get(Reader& r, Owned<TextureView>& v) {
    get(r, v.view.width);
    get(r, v.view.height);
    get(r, v.view.srgb);
    get(r, v.data);
    v.view.texels = v.data.empty() ? nullptr : v.data.data();
}

void put(Writer& w, const LightVisibility& v) {
    w.pod(std::uint64_t(v.per_light.size()));
    w.bytes(v.per_light.data(), v.per_light.size_bytes());
}
void get(Reader& r, Owned<LightVisibility>& v) {
    get(r, v.data);
    v.view.per_light = v.data;
}

void put(Writer& w, const PreparedScene& v) {
    put(w, static_cast<const Scene&>(v));
    put(w, v.features);
    put(w, v.bvh);
    put(w, v.prepared_objects);
}
void get(Reader& r, PreparedScene& v) {
    get(r, static_cast<Scene&>(v));
    get(r, v.features);
    get(r, v.bvh);
    get(r, v.prepared_objects);
    // nearest_hit looks an instance's object up in prepared_objects.
    if (!v.instances.empty() && v.prepared_objects.size() != v.objects.size()) r.fail();
}

namespace {

template <class S>
void put_shared(Writer& w, const std::shared_ptr<const S>& v) {
    put(w, bool(v));
    if (v) put(w, *v);
}

// How deep the object being decoded is. An object holds surfaces only (instances are one level
// deep), so an object inside an object is refused: a sender cannot make the decoder recurse
// without bound. A null object is refused too (nothing ever sends one).
thread_local int g_object_depth = 0;

template <class S>
void get_shared(Reader& r, std::shared_ptr<const S>& v) {
    bool present = false;
    get(r, present);
    v.reset();
    if (!present || g_object_depth > 0) {
        r.fail();
        return;
    }
    ++g_object_depth;
    auto decoded = std::make_shared<S>();
    get(r, *decoded);
    --g_object_depth;
    v = std::move(decoded);
}

}  // namespace

void put(Writer& w, const std::shared_ptr<const Scene>& v) {
    put_shared(w, v);
}
void get(Reader& r, std::shared_ptr<const Scene>& v) {
    get_shared(r, v);
}
void put(Writer& w, const std::shared_ptr<const PreparedScene>& v) {
    put_shared(w, v);
}
void get(Reader& r, std::shared_ptr<const PreparedScene>& v) {
    get_shared(r, v);
}

// sizeof(Scene) and sizeof(PreparedScene) (with float) when their field lists were written.
static_assert(sizeof(Real) != sizeof(float) || sizeof(Scene) == 736,
              "Scene changed: add its new field to RT_WIRE_FIELDS(Scene) in wire_types.h");
static_assert(sizeof(Real) != sizeof(float) || sizeof(PreparedScene) == 856,
              "PreparedScene changed: add its new field to put/get(PreparedScene) above");

}  // namespace rt::remote
