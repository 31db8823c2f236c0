// Stage 11's light strategies against time: see mis_strategies.h. MIS is stage 11's own
// path_radiance; BSDF sampling alone is path_radiance too, on the scene with its sphere lights made
// emissive spheres (it then samples no light and meets each at full weight); next-event estimation
// alone is this file's loop, which follows path_radiance's contract step for step and draws the
// same random numbers, so that only the light weights differ between the strategies.
#include "bench/mis_strategies.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "bench/sampling_error.h"
#include "core/parallel_for.h"
#include "core/sample_stream.h"
#include "core/source_dir.h"
#include "image/image.h"
#include "render/camera_ray.h"
#include "render/nearest_hit.h"
#include "render/prepare.h"
#include "render/render.h"
#include "scene/area_light_hit.h"
#include "scene/scene_loader.h"
#include "stage_api/stage06.h"
#include "stage_api/stage10.h"
#include "stage_api/stage11.h"

namespace rt::bench {
namespace {

const AreaLight& pick_light(const PreparedScene& scene, Real u_light) {
    const std::size_t count = scene.area_lights.size();
    return scene.area_lights[std::min(count - 1, std::size_t(u_light * Real(count)))];
}

// Next-event estimation at full weight: sample_light_mis's estimate without the power heuristic.
Color sample_light_alone(const PreparedScene& scene, const SurfacePoint& at, const Onb& frame,
                         const Material& material, const Vec3& wo, Real u_light, Vec2 u) {
    if (scene.area_lights.empty()) return Color(0);
    const AreaLight& light = pick_light(scene, u_light);
    const AreaSample a = light.kind == AreaLightKind::Rectangle
                             ? sample_rectangle(light, at.point, u)
                             : sample_sphere(light, at.point, u);
    if (!(a.pdf > 0)) return Color(0);
    const Vec3 to_light = a.point - at.point;
    const Real distance = glm::length(to_light);
    const Vec3 direction = to_light / distance;
    if (glm::dot(a.normal, direction) >= 0) return Color(0);
    const Vec3 wi = frame.to_local(direction);
    const Color f = eval_bsdf(material, wo, wi);
    if (f == Color(0)) return Color(0);
    Hit blocker;
    const Vec3 side = glm::dot(direction, at.normal) > 0 ? at.normal : -at.normal;
    if (nearest_hit(scene, spawn_ray(at, side, direction), Interval{0, distance * Real(0.9999)},
                    blocker))
        return Color(0);
    const Real p_light = a.pdf / Real(scene.area_lights.size());
    return f * light.radiance * float(std::abs(wi.z) / p_light);
}

// The scene with each sphere light an emissive sphere, black but for its emission, and no area
// lights: path_radiance then samples no light, and a bounce or camera ray that meets one counts its
// emission in full, as a light found by BSDF sampling alone. (Veach's scene has sphere lights only.)
PreparedScene lights_as_surfaces(const PreparedScene& scene) {
    PreparedScene copy = scene;
    for (const AreaLight& light : scene.area_lights) {
        if (light.kind != AreaLightKind::Sphere)
            throw std::runtime_error("the MIS lab makes sphere lights into spheres only");
        Material glow;
        glow.diffuse = Color(0);
        glow.emissive = light.radiance;
        copy.materials.push_back(glow);
        copy.spheres.push_back({light.center, light.radius, int(copy.materials.size()) - 1});
    }
    copy.area_lights.clear();
    refresh_features(copy);
    return copy;
}

// Next-event estimation alone: path_radiance's loop with the light sample at full weight and a
// light that a BSDF bounce meets counted only after the camera ray or a delta bounce, which had no
// light sample to compete with.
Color nee_radiance(const PreparedScene& scene, const Ray& camera_ray, SampleStream& stream) {
    Color radiance(0), throughput(1);
    Ray ray = camera_ray;
    bool full_weight = true;
    for (int depth = 0;; ++depth) {
        Hit hit;
        const bool found = nearest_hit(scene, ray, Interval{0, kInfinity}, hit);
        const AreaLightHit light = nearest_area_light(scene, ray, Interval{0, hit.t});
        if (light.light >= 0) {
            if (full_weight) radiance += throughput * light.radiance;
            break;
        }
        if (!found) {
            radiance += throughput * scene.background;
            break;
        }
        const SurfacePoint at = surface_point(scene, ray, hit);
        const Material& material = scene.materials[std::size_t(hit.material)];
        radiance += throughput * material.emissive;
        if (depth >= scene.max_depth) break;
        const Onb frame = onb_around(at.front_face ? at.normal : -at.normal);
        const Vec3 wo = frame.to_local(-glm::normalize(ray.direction));
        const Real u_light = stream.next();
        const Vec2 u = stream.next2();
        radiance += throughput * sample_light_alone(scene, at, frame, material, wo, u_light, u);
        const Real u_lobe = stream.next();
        const BsdfSample s = sample_bsdf(material, wo, u_lobe, stream.next2());
        if (s.weight == Color(0)) break;
        throughput *= s.weight;
        full_weight = s.delta;
        const Vec3 direction = frame.to_world(s.wi);
        ray = spawn_ray(at, glm::dot(direction, at.normal) > 0 ? at.normal : -at.normal, direction);
        if (depth >= 3) {
            const Real q =
                std::min(Real(0.95), Real(std::max({throughput.r, throughput.g, throughput.b})));
            if (stream.next() >= q) break;
            throughput /= float(q);
        }
    }
    return radiance;
}

Image8 render_strategy(const StrategyRenderer& renderer, int spp, std::uint64_t seed) {
    const PreparedScene& scene = renderer.scene;
    const int width = scene.image.width, height = scene.image.height;
    Image image(width, height);
    parallel_for(std::size_t(height), resolve_thread_count(0), [&](std::size_t row) {
        const int y = int(row);
        for (int x = 0; x < width; ++x) {
            Color sum(0);
            for (int s = 0; s < spp; ++s) {  // as render/sampled.cpp's sample_pixel
                SampleStream stream(seed, std::uint64_t(y) * std::uint64_t(width) + x,
                                    std::uint64_t(s));
                const Vec2 offset = box_filter_offset(stratified_sample(s, spp, stream.next2()));
                const Ray ray = camera_ray(scene.camera,
                                           Vec2(Real(x) + Real(0.5), Real(y) + Real(0.5)) + offset,
                                           scene.image);
                sum += renderer.radiance(ray, stream);
            }
            image.at(x, y) = sum / float(spp);
        }
    });
    return to_image8(image);
}

}  // namespace

const char* strategy_name(LightStrategy strategy) {
    switch (strategy) {
        case LightStrategy::Nee:
            return "NEE";
        case LightStrategy::Bsdf:
            return "BSDF";
        case LightStrategy::Mis:
            return "MIS";
    }
    return "?";
}

StrategyRenderer::StrategyRenderer(const PreparedScene& original, LightStrategy strategy)
    : scene(strategy == LightStrategy::Bsdf ? lights_as_surfaces(original) : original),
      strategy(strategy) {}

Color StrategyRenderer::radiance(const Ray& camera_ray, SampleStream& stream) const {
    if (strategy == LightStrategy::Nee) return nee_radiance(scene, camera_ray, stream);
    return path_radiance(scene, camera_ray, stream);
}

MisSeries measure_mis_strategies(const std::function<void(const std::string&)>& progress) {
    MisSeries series;
    series.scene = "stages/11-path-tracing/scenes/veach_mis.json";
    series.reference = "reference_images/11-path-tracing/veach_mis.png";
    series.threads = resolve_thread_count(0);
    const PreparedScene scene = prepare_scene(load_scene(source_dir() / series.scene));
    series.width = scene.image.width;
    series.height = scene.image.height;
    const Image8 reference = read_image8(source_dir() / series.reference);
    // The reference is the scene's seed at 2048 samples: another seed keeps the noise apart.
    const std::uint64_t seed = scene.sampling.seed + 1000;
    for (LightStrategy strategy : {LightStrategy::Nee, LightStrategy::Bsdf, LightStrategy::Mis}) {
        const StrategyRenderer renderer(scene, strategy);
        for (int spp = 1; spp <= 256; spp *= 4) {
            MisPoint p;
            p.strategy = strategy_name(strategy);
            p.spp = spp;
            const auto start = std::chrono::steady_clock::now();
            const Image8 image = render_strategy(renderer, spp, seed);
            p.ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count();
            p.rmse = rmse8(image, reference);
            series.points.push_back(p);
        }
        if (progress) progress(std::string("mis: ") + strategy_name(strategy));
    }
    return series;
}

}  // namespace rt::bench
