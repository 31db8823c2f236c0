// The codecs of the framework's types that cannot cross as plain bytes (wire.h): those holding
// containers, pointers or bools that a test reads, and the scene, which crosses by handle.
#pragma once

#include <vector>

#include "image/image.h"
#include "remote/wire.h"
#include "render/accelerate.h"
#include "render/ray_tree.h"
#include "render/render.h"
#include "render/shade.h"
#include "scene/scene.h"
#include "stage_api/stage03.h"
#include "stage_api/stage05.h"
#include "stage_api/stage10.h"

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

void put(Writer& w, const Hit& v);
void get(Reader& r, Hit& v);
void put(Writer& w, const SurfacePoint& v);
void get(Reader& r, SurfacePoint& v);
void put(Writer& w, const SecondaryRays& v);
void get(Reader& r, SecondaryRays& v);
void put(Writer& w, const FogEvent& v);
void get(Reader& r, FogEvent& v);
void put(Writer& w, const Image& v);
void get(Reader& r, Image& v);
void put(Writer& w, const Bvh& v);
void get(Reader& r, Bvh& v);
void put(Writer& w, const AccelerationReport& v);
void get(Reader& r, AccelerationReport& v);
void put(Writer& w, const RenderOptions& v);
void get(Reader& r, RenderOptions& v);
void put(Writer& w, const RayNode& v);
void get(Reader& r, RayNode& v);
void put(Writer& w, const PixelTree& v);
void get(Reader& r, PixelTree& v);
void put(Writer& w, const Scene& v);  // in full (a Scene& parameter)
void get(Reader& r, Scene& v);

// A texture view crosses with its texels; the worker's copy points into its own storage.
void put(Writer& w, const TextureView& v);
struct OwnedTextureView {
    std::vector<Color> texels;
    TextureView view;
};
void get(Reader& r, OwnedTextureView& v);
inline const TextureView& view(const OwnedTextureView& v) {
    return v.view;
}
template <>
struct StorageFor<TextureView> {
    using type = OwnedTextureView;
};

// Light visibility likewise, with its per-light colours.
void put(Writer& w, const LightVisibility& v);
struct OwnedLightVisibility {
    std::vector<Color> colours;
    LightVisibility view;
};
void get(Reader& r, OwnedLightVisibility& v);
inline const LightVisibility& view(const OwnedLightVisibility& v) {
    return v.view;
}
template <>
struct StorageFor<LightVisibility> {
    using type = OwnedLightVisibility;
};

}  // namespace rt::remote
