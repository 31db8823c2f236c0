// Stage 11's light strategies against time, for direct light: see mis_strategies.h. MIS is stage
// 11's own path_radiance; BSDF sampling alone is path_radiance too, on the scene with its sphere
// lights made emissive spheres (it then samples no light and meets each at full weight);
// next-event estimation alone is one light sample of stage 10's at the first surface, from the
// random numbers path_radiance draws there, so that only the light weights differ.
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
#include "stage_api/stage04.h"
#include "stage_api/stage06.h"
#include "stage_api/stage10.h"
#include "stage_api/stage11.h"

namespace rt::bench {
namespace {

// Next-event estimation at full weight, one light picked uniformly: stage 10's sample_area_light
// (whose intensity is radiance / (pi pdf), hence the pi) and stage 04's shadow test, with stage
// 11's BSDF in place of Blinn-Phong.
Color light_sample_alone(const PreparedScene& scene, const SurfacePoint& at, const Onb& frame,
                         const Material& material, const Vec3& wo, Real u_light, Vec2 u) {
    const std::size_t count = scene.area_lights.size();
    if (count == 0) return Color(0);
    const AreaLight& light =
        scene.area_lights[std::min(count - 1, std::size_t(u_light * Real(count)))];
    const LightSample sample = sample_area_light(light, at.point, u);
    if (sample.intensity == Color(0)) return Color(0);
    const Vec3 wi = frame.to_local(sample.direction);
    const Color f = eval_bsdf(material, wo, wi);
    if (f == Color(0)) return Color(0);
    const Color visible = light_transmittance(scene, at, sample);
    return f * sample.intensity * visible * float(kPi * std::abs(wi.z) * Real(count));
}

// The scene as the lab renders it: direct light only (a path ends at its second surface), as in
// Veach's experiment.
PreparedScene direct_light_only(const PreparedScene& scene) {
    PreparedScene copy = scene;
    copy.max_depth = 1;
    return copy;
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

// Direct light by next-event estimation alone: what the camera ray meets, plus one light sample
// at the surface it hits, drawn from the random numbers path_radiance draws there.
Color nee_direct(const PreparedScene& scene, const Ray& camera_ray, SampleStream& stream) {
    Hit hit;
    const bool found = nearest_hit(scene, camera_ray, Interval{0, kInfinity}, hit);
    const AreaLightHit light = nearest_area_light(scene, camera_ray, Interval{0, hit.t});
    if (light.light >= 0) return light.radiance;
    if (!found) return scene.background;
    const SurfacePoint at = surface_point(scene, camera_ray, hit);
    const Material& material = scene.materials[std::size_t(hit.material)];
    const Onb frame = onb_around(at.front_face ? at.normal : -at.normal);
    const Vec3 wo = frame.to_local(-glm::normalize(camera_ray.direction));
    const Real u_light = stream.next();
    const Vec2 u = stream.next2();
    return material.emissive + light_sample_alone(scene, at, frame, material, wo, u_light, u);
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
    : scene(direct_light_only(strategy == LightStrategy::Bsdf ? lights_as_surfaces(original)
                                                              : original)),
      strategy(strategy) {}

Color StrategyRenderer::radiance(const Ray& camera_ray, SampleStream& stream) const {
    if (strategy == LightStrategy::Nee) return nee_direct(scene, camera_ray, stream);
    return path_radiance(scene, camera_ray, stream);
}

MisSeries measure_mis_strategies(const std::function<void(const std::string&)>& progress) {
    MisSeries series;
    series.scene = "stages/11-path-tracing/scenes/veach_mis.json";
    series.reference_spp = kReferenceSamples;
    series.threads = resolve_thread_count(0);
    const PreparedScene scene = prepare_scene(load_scene(source_dir() / series.scene));
    series.width = scene.image.width;
    series.height = scene.image.height;
    // The reference is MIS's at the scene's seed (the stage's reference image has indirect light
    // too); the strategies take another seed, which keeps the noise apart.
    const Image8 reference = render_strategy(StrategyRenderer(scene, LightStrategy::Mis),
                                             kReferenceSamples, scene.sampling.seed);
    if (progress) progress("mis: reference");
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
