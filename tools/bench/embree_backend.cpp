// The Embree 3 back-end of `rt-bench bvh`. Compiled in every configuration; it only talks to
// Embree when the project found it (RT_HAVE_EMBREE), otherwise it says it is not there.
#include <stdexcept>
#include <string>

#include "bench/bvh_bench.h"

#ifdef RT_HAVE_EMBREE
#include <embree3/rtcore.h>

#include <chrono>
#include <cstring>
#include <mutex>
#endif

namespace rt::bench {

#ifndef RT_HAVE_EMBREE

bool embree_built_in() {
    return false;
}

std::unique_ptr<Backend> make_embree_backend(const PreparedScene&, int) {
    throw std::runtime_error(
        "Embree was not built in: install libembree-dev (scripts/install-deps.sh) and configure "
        "again");
}

#else

bool embree_built_in() {
    return true;
}

namespace {

// Embree reports errors through a callback; the back-end collects the first one and throws it
// from the C++ side (an exception must not cross Embree's C frames).
struct ErrorSink {
    std::mutex mutex;
    std::string first;
};

void on_embree_error(void* user, RTCError code, const char* message) {
    auto* sink = static_cast<ErrorSink*>(user);
    std::lock_guard<std::mutex> lock(sink->mutex);
    if (sink->first.empty())
        sink->first = "Embree error " + std::to_string(int(code)) + ": " +
                      (message ? message : "(no message)");
}

class EmbreeBackend final : public Backend {
  public:
    EmbreeBackend(const PreparedScene& scene, int threads) : scene_(scene) {
        const std::string config = "threads=" + std::to_string(threads < 1 ? 1 : threads);
        device_ = rtcNewDevice(config.c_str());
        if (!device_)
            throw std::runtime_error("rtcNewDevice failed (error " +
                                     std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
        rtcSetDeviceErrorFunction(device_, on_embree_error, &errors_);
    }
    ~EmbreeBackend() override {
        if (scene_handle_) rtcReleaseScene(scene_handle_);
        rtcReleaseDevice(device_);
    }
    EmbreeBackend(const EmbreeBackend&) = delete;
    EmbreeBackend& operator=(const EmbreeBackend&) = delete;

    std::string name() const override { return "embree"; }

    // Timed from the scene's arrays to a committed scene: geometry creation, both buffers
    // filled (float vertices, as Embree wants them, from rt::Real), and rtcCommitScene.
    double build() override {
        if (scene_handle_) {
            rtcReleaseScene(scene_handle_);
            scene_handle_ = nullptr;
        }
        const auto start = std::chrono::steady_clock::now();
        RTCScene handle = rtcNewScene(device_);
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    3 * sizeof(float), scene_.vertices.size()));
        auto* indices = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(unsigned), scene_.triangles.size()));
        if (vertices && indices) {
            for (std::size_t i = 0; i < scene_.vertices.size(); ++i) {
                vertices[3 * i + 0] = float(scene_.vertices[i].x);
                vertices[3 * i + 1] = float(scene_.vertices[i].y);
                vertices[3 * i + 2] = float(scene_.vertices[i].z);
            }
            for (std::size_t i = 0; i < scene_.triangles.size(); ++i)
                std::memcpy(indices + 3 * i, scene_.triangles[i].v.data(), 3 * sizeof(unsigned));
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometryByID(handle, geometry, 0);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(handle);
        const auto end = std::chrono::steady_clock::now();
        scene_handle_ = handle;
        check();
        return std::chrono::duration<double, std::milli>(end - start).count();
    }

    void trace(const RayBatch& batch, std::size_t begin, std::size_t end,
               RayResult* results) const override {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        // Geometry 0 holds only triangles, so Embree's primID is the triangle's index.
        for (std::size_t i = begin; i < end; ++i) {
            const Ray& ray = batch.rays[i];
            const Interval range = batch.ranges[i];
            RTCRayHit query;
            query.ray.org_x = float(ray.origin.x);
            query.ray.org_y = float(ray.origin.y);
            query.ray.org_z = float(ray.origin.z);
            query.ray.dir_x = float(ray.direction.x);
            query.ray.dir_y = float(ray.direction.y);
            query.ray.dir_z = float(ray.direction.z);
            query.ray.tnear = float(range.min);
            query.ray.tfar = float(range.max);
            query.ray.time = 0;
            query.ray.mask = ~0u;
            query.ray.id = 0;
            query.ray.flags = 0;
            RayResult result;
            if (batch.any_hit) {
                rtcOccluded1(scene_handle_, &context, &query.ray);
                // An occluded ray comes back with tfar = -inf.
                if (query.ray.tfar < 0) result.t = 0;
            } else {
                query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                query.hit.primID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(scene_handle_, &context, &query);
                if (query.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
                    result.t = Real(query.ray.tfar);
                    result.primitive = Scene::primitive_id(Scene::Kind::Triangle, query.hit.primID);
                }
            }
            results[i] = result;
        }
    }

  private:
    void check() {
        std::lock_guard<std::mutex> lock(errors_.mutex);
        if (!errors_.first.empty()) throw std::runtime_error(errors_.first);
    }

    const PreparedScene& scene_;
    RTCDevice device_ = nullptr;
    RTCScene scene_handle_ = nullptr;
    ErrorSink errors_;
};

}  // namespace

std::unique_ptr<Backend> make_embree_backend(const PreparedScene& scene, int threads) {
    if (!scene.spheres.empty() || !scene.planes.empty() || !scene.boxes.empty())
        throw std::runtime_error("the Embree back-end handles triangle meshes only");
    return std::make_unique<EmbreeBackend>(scene, threads);
}

#endif

}  // namespace rt::bench
