#include "render/shade.h"

#include <algorithm>
#include <vector>

#include "render/accelerate.h"
#include "render/background.h"
#include "render/camera_ray.h"
#include "render/nearest_hit.h"
#include "render/sampled.h"
#include "render/texturing.h"
#include "stage_api/stage02.h"
#include "stage_api/stage03.h"
#include "stage_api/stage04.h"
#include "stage_api/stage05.h"
#include "stage_api/stage10.h"
#include "stage_api/stage11.h"

namespace rt {
namespace {

bool nonzero(const Color& c) {
    return c.r > 0 || c.g > 0 || c.b > 0;
}

}  // namespace

const char* to_string(RayNode::Kind kind) {
    switch (kind) {
        case RayNode::Kind::Camera:
            return "camera";
        case RayNode::Kind::Reflection:
            return "reflection";
        case RayNode::Kind::Refraction:
            return "refraction";
    }
    return "?";
}

namespace {

// One ray of the loop's stack: what recursion kept in its locals.
struct Frame {
    Ray ray;
    int depth = 0;
    Color weight{1};  // in the pixel (the debugger's; light transport never reads it)
    Color color{0};   // local light, then each branch's weighted colour as it completes
    bool recurse = false;
    SecondaryRays branches;
    int next = 0;  // the branch to trace next: 0 reflected, 1 refracted, 2 done
};

const SecondaryRay& branch(const Frame& f, int i) {
    return i == 0 ? f.branches.reflected : f.branches.refracted;
}

// Stage 04's shadows into `visibility`, one entry per scene light, for direct_light. Only the
// lights whose Blinn-Phong term is not zero get a shadow ray (a shader does the same); the
// others get 0, which their zero term ignores. With a BVH and nothing transparent, a shadow ray
// only asks whether anything is in the way: stage 06's any-hit query, which gives what
// light_transmittance would, faster.
void shadow_lights(const PreparedScene& scene, const SurfacePoint& at, const Material& material,
                   const Vec3& normal, const Vec3& to_viewer, std::vector<Color>& visibility,
                   TraceObserver* observer) {
    const bool any_hit_shadows = uses_bvh(scene) && !scene.features.refraction;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        // Light linking (link_lights): an unlinked light stays dark, a shadowless one lit.
        if (visibility[i] == Color(0) || !scene.lights[i].casts_shadows) continue;
        visibility[i] = Color(0);
        const LightSample sample = illuminate(scene.lights[i], at.point);
        if (blinn_phong(material, normal, to_viewer, sample.direction, sample.intensity) ==
            Color(0))
            continue;
        Color transmittance;
        if (any_hit_shadows) {
            const ShadowRay shadow = shadow_ray(at, sample);
            transmittance =
                Color(bvh_intersect_any(scene, shadow.ray, shadow.t_range) ? 0.0f : 1.0f);
        } else {
            transmittance = light_transmittance(scene, at, sample);
        }
        if (observer) observer->shadow(at, i, sample, transmittance);
        visibility[i] = transmittance;
    }
}

// Light linking: each light's visibility 1 where it lights the hit's material, 0 where it does
// not (Light::reach_mask); shadows then darken the linked ones.
void link_lights(const PreparedScene& scene, int material, std::vector<Color>& visibility) {
    visibility.assign(scene.lights.size(), Color(1));
    if (!scene.features.light_links) return;
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        if (!light_reaches(scene.lights[i], material)) visibility[i] = Color(0);
}

// Stage 10's fog (optional): each light's visibility from `at` times the fraction of its light
// that crosses the fog on the way (stage 10's medium_transmittance along the shadow ray).
void attenuate_by_fog(const PreparedScene& scene, const SurfacePoint& at,
                      std::vector<Color>& visibility) {
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        if (visibility[i] == Color(0)) continue;
        const ShadowRay shadow = shadow_ray(at, illuminate(scene.lights[i], at.point));
        visibility[i] *= float(medium_transmittance(scene.fog, shadow.ray, shadow.t_range));
    }
}

// Stage 10's fog (optional): the light scattered towards the viewer at `point`, inside the fog.
// One scattering: the direct light of every point and directional light there (past the
// surfaces in the way when the scene has shadows, and through the fog), scattered equally into
// every direction. A light of stage 03 intensity I gives the irradiance pi I (conventions:
// sampling), and the phase function 1 / (4 pi) turns it into the radiance I / 4; the fog's
// albedo is the part scattered. Draws no random numbers.
Color fog_scattering(const PreparedScene& scene, const Vec3& point) {
    SurfacePoint at;  // no surface: zero error and normal, so shadow rays start at the point
    at.point = point;
    Color sum(0);
    for (const Light& light : scene.lights) {
        const LightSample sample = illuminate(light, point);
        Color through = scene.features.shadows ? light_transmittance(scene, at, sample) : Color(1);
        if (through == Color(0)) continue;
        const ShadowRay shadow = shadow_ray(at, sample);
        through *= float(medium_transmittance(scene.fog, shadow.ray, shadow.t_range));
        sum += sample.intensity * through * 0.25f;
    }
    return scene.fog.albedo * sum;
}

// A hit made ready for lighting: its surface point, material (as its maps colour it here) and
// the normal it is lit with.
struct PreparedHit {
    SurfacePoint at;
    int material_index = 0;              // for light linking
    const Material* material = nullptr;  // the scene's, or `textured`
    Material textured;
    Vec3 lighting_normal{0};
    Vec3 to_viewer{0};
};

// An instance of a mesh with vertex normals is lit, like the mesh, with the object's
// interpolated normal, mapped to the world by the inverse transpose.
void instance_lighting_normal(const PreparedScene& scene, const Ray& ray, const Hit& hit,
                              Vec3& lighting_normal) {
    const ObjectView view = object_view(scene, ray, hit);
    std::size_t index = 0;
    if (!view.object || view.object->normals.empty() ||
        view.object->primitive_kind(view.hit.primitive, index) != Scene::Kind::Triangle)
        return;
    const Vec3 smooth = shading_normal(*view.object, index, hit.uv);
    if (smooth == Vec3(0)) return;
    const Vec3 world = world_normal(*view.instance, smooth);
    lighting_normal = hit.front_face ? world : -world;
}

void prepare_hit(const PreparedScene& scene, const Ray& ray, const Hit& hit,
                 const RayDifferential* rays, PreparedHit& p) {
    // A scene built in code may lack materials; an out-of-range index must not crash.
    static const Material kDefaultMaterial;
    const bool known = hit.material >= 0 && std::size_t(hit.material) < scene.materials.size();
    const Material& scene_material =
        known ? scene.materials[std::size_t(hit.material)] : kDefaultMaterial;
    p.at = surface_point(scene, ray, hit);
    p.to_viewer = -glm::normalize(ray.direction);
    // Meshes with vertex normals are lit with the interpolated normal (smooth shading); ray
    // origins and mirror directions keep the geometric one, which the offsets are built on.
    p.lighting_normal = p.at.normal;
    if (!scene.normals.empty()) {
        std::size_t index = 0;
        if (scene.primitive_kind(hit.primitive, index) == Scene::Kind::Triangle) {
            const Vec3 smooth = shading_normal(scene, index, hit.uv);
            if (smooth != Vec3(0)) p.lighting_normal = hit.front_face ? smooth : -smooth;
        }
    }
    if (!scene.instances.empty()) instance_lighting_normal(scene, ray, hit, p.lighting_normal);
    // Stage 07: the material as its maps colour it here, and the normal-mapped normal. Only
    // textured scenes pay for the copy (and run stage 07 code).
    p.material = &scene_material;
    p.material_index = known ? hit.material : 0;
    if (scene.features.textures || scene.features.normal_maps) {
        p.textured = scene_material;
        apply_textures(scene, hit, p.at, p.to_viewer, p.textured, p.lighting_normal, rays);
        p.material = &p.textured;
    }
}

Color sampled_light(const PreparedScene& scene, const PreparedHit& p, SampleStream& stream,
                    bool indirect);

// The light a hit sends back along its ray, before reflected and refracted rays: direct light
// (stage 03) with stage 04's shadows when the scene has them, and with a sampler (stage 10)
// the area lights, ambient occlusion and, if `indirect`, one bounce of diffuse light, which
// replace the ambient term as the scene says.
Color local_light(const PreparedScene& scene, const PreparedHit& p, TraceObserver* observer,
                  SampleStream* stream, bool indirect) {
    const Material* material = p.material;
    Material without_ambient;
    if (stream && (scene.features.ambient_occlusion || scene.features.indirect_diffuse)) {
        without_ambient = *material;
        without_ambient.ambient = Color(0);
        material = &without_ambient;
    }
    Color local;
    if (scene.features.shadows || scene.features.fog || scene.features.light_links) {
        // One scratch array a thread: no allocation per hit once it has grown.
        thread_local std::vector<Color> visibility;
        link_lights(scene, p.material_index, visibility);
        if (scene.features.shadows)
            shadow_lights(scene, p.at, *material, p.lighting_normal, p.to_viewer, visibility,
                          observer);
        if (scene.features.fog) attenuate_by_fog(scene, p.at, visibility);
        local = direct_light(scene, *material, p.at.point, p.lighting_normal, p.to_viewer,
                             LightVisibility{visibility});
    } else {
        local = direct_light(scene, *material, p.at.point, p.lighting_normal, p.to_viewer);
    }
    if (stream) local += sampled_light(scene, p, *stream, indirect);
    return local;
}

// Stage 10's bounce: what a ray leaving a surface brings back (the local light where it lands,
// without a further bounce, or the background).
class BounceRadiance : public IncomingRadiance {
  public:
    BounceRadiance(const PreparedScene& scene, SampleStream& stream)
        : scene_(scene), stream_(stream) {}
    Color operator()(const Ray& ray) const override {
        Hit hit;
        if (!nearest_hit(scene_, ray, Interval{0, kInfinity}, hit))
            return background(scene_, ray.direction);
        PreparedHit p;
        prepare_hit(scene_, ray, hit, nullptr, p);
        return local_light(scene_, p, nullptr, &stream_, false);
    }

  private:
    const PreparedScene& scene_;
    SampleStream& stream_;
};

// Stage 10's sampled terms, each drawing its numbers from `stream` in this order: one 2D
// sample per area light, then ambient occlusion, then the indirect bounce.
Color sampled_light(const PreparedScene& scene, const PreparedHit& p, SampleStream& stream,
                    bool indirect) {
    const Material& material = *p.material;
    Color sum(0);
    for (const AreaLight& light : scene.area_lights)
        sum += area_light_estimate(scene, material, p.at, p.lighting_normal, p.to_viewer, light,
                                   stream.next2());
    if (scene.features.ambient_occlusion)
        sum += material.ambient * scene.ambient_light *
               float(ambient_occlusion(scene, p.at, p.lighting_normal,
                                       scene.sampling.occlusion_distance, stream.next2()));
    if (scene.features.indirect_diffuse && indirect)
        sum += indirect_diffuse(p.at, p.lighting_normal, material, stream.next2(),
                                BounceRadiance(scene, stream));
    return sum;
}

// Stage 10's glossy reflection: the mirror ray turned by the material's fuzz; a direction into
// the surface is absorbed (no ray).
void make_glossy(const SurfacePoint& at, Real fuzz, SecondaryRay& reflected, SampleStream& stream) {
    const Vec3 d = glossy_direction(glm::normalize(reflected.ray.direction), fuzz, stream.next2());
    if (!(glm::dot(d, at.normal) > 0) || !all_finite(d)) {
        reflected.valid = false;
        return;
    }
    reflected.ray = spawn_ray(at, at.normal, d);
}

// A frame's own work: the nearest hit, its local light, and the secondary rays (stage 05) when
// the material reflects or transmits. `rays`: the camera ray's differentials (texture filter
// footprints), null for other rays. `stream`: the camera sample's numbers (stage 10), or null.
void start_frame(const PreparedScene& scene, Frame& f, TraceObserver* observer,
                 const RayDifferential* rays = nullptr, SampleStream* stream = nullptr) {
    Hit hit;
    const bool found = nearest_hit(scene, f.ray, Interval{0, kInfinity}, hit);
    // Stage 10's fog (optional): one number per traced ray, before the hit's. A ray scattered
    // before the surface ends there (the debugger shows it as a ray without a hit).
    if (stream && scene.features.fog) {
        const FogEvent event =
            sample_fog(scene.fog, f.ray, found ? hit.t : kInfinity, stream->next());
        if (event.scattered) {
            f.color = fog_scattering(scene, f.ray.origin + event.t * f.ray.direction);
            f.recurse = false;
            if (observer) observer->miss(f.color);
            return;
        }
    }
    if (!found) {
        f.color = background(scene, f.ray.direction);
        f.recurse = false;
        if (observer) observer->miss(f.color);
        return;
    }
    thread_local PreparedHit p;  // its Material copy is not rebuilt per hit
    prepare_hit(scene, f.ray, hit, rays, p);
    const Material& material = *p.material;
    const Color local = local_light(scene, p, observer, stream, true);
    if (observer) observer->hit(hit, p.at, local);
    f.color = local;
    f.recurse = f.depth < std::min(scene.max_depth, kMaxTraceDepth) &&
                ((scene.features.reflection && nonzero(material.reflective)) ||
                 (scene.features.refraction && nonzero(material.transmissive)));
    f.next = 0;
    if (!f.recurse) return;
    f.branches = secondary_rays(f.ray, p.at, material, scene.fresnel);
    if (stream && material.fuzz > 0 && f.branches.reflected.valid)
        make_glossy(p.at, material.fuzz, f.branches.reflected, *stream);
}

// Builds the debugger's ray tree from what the loop reports.
class RayTreeRecorder : public TraceObserver {
  public:
    RayTreeRecorder(const PreparedScene& scene, RayNode& root) : scene_(scene), root_(root) {}
    void begin_ray(RayNode::Kind kind, int depth, const Ray& ray, const Color& ray_weight,
                   const Color& weight) override {
        RayNode* node = open_.empty() ? &root_ : &open_.back()->children.emplace_back();
        node->kind = kind;
        node->depth = depth;
        node->ray = ray;
        node->ray_weight = ray_weight;
        node->weight = weight;
        open_.push_back(node);
    }
    void miss(const Color& background) override {
        RayNode& n = *open_.back();
        n.local = background;
        n.contribution = n.weight * background;
    }
    void shadow(const SurfacePoint& at, std::size_t light, const LightSample& sample,
                const Color& transmittance) override {
        // The debugger also names the first surface in the way (the framework's own query).
        ShadowRecord record;
        record.light = light;
        const ShadowRay shadow = shadow_ray(at, sample);
        record.ray = shadow.ray;
        record.t_range = shadow.t_range;
        record.transmittance = transmittance;
        Hit blocker;
        if (nearest_hit(scene_, shadow.ray, shadow.t_range, blocker)) {
            record.blocked_by = blocker.primitive;
            record.blocked_t = blocker.t;
        }
        open_.back()->shadows.push_back(record);
    }
    void hit(const Hit& hit, const SurfacePoint& at, const Color& local) override {
        RayNode& n = *open_.back();
        n.hit = true;
        n.hit_record = hit;
        n.surface = at;
        n.local = local;
        n.contribution = n.weight * local;
    }
    void end_ray() override { open_.pop_back(); }

  private:
    const PreparedScene& scene_;
    RayNode& root_;
    std::vector<RayNode*> open_;  // the rays begun and not ended: a path from the root
};

}  // namespace

namespace {

Color trace(const PreparedScene& scene, const Ray& ray, int depth, const Color& weight,
            TraceObserver* observer, const RayDifferential* rays, SampleStream* stream = nullptr) {
    // Once per thread: constructing 65 frames per pixel would cost more than most pixels do.
    static thread_local Frame stack[kMaxTraceDepth + 1];
    int top = 0;
    stack[0].ray = ray;
    stack[0].depth = depth;
    stack[0].weight = weight;
    if (observer) observer->begin_ray(RayNode::Kind::Camera, depth, ray, Color(1), weight);
    start_frame(scene, stack[0], observer, rays, stream);
    for (;;) {
        Frame& f = stack[top];
        while (f.recurse && f.next < 2 && !branch(f, f.next).valid) ++f.next;
        if (f.recurse && f.next < 2 && top < kMaxTraceDepth) {
            // Descend into the next branch, as a recursive call would.
            const SecondaryRay& s = branch(f, f.next);
            Frame& child = stack[++top];
            child.ray = s.ray;
            child.depth = f.depth + 1;
            child.weight = f.weight * s.weight;
            if (observer)
                observer->begin_ray(
                    f.next == 0 ? RayNode::Kind::Reflection : RayNode::Kind::Refraction,
                    child.depth, s.ray, s.weight, child.weight);
            start_frame(scene, child, observer, nullptr, stream);
            continue;
        }
        // This ray is complete: hand its colour to its parent, weighted, like a return would.
        if (observer) observer->end_ray();
        if (top == 0) return f.color;
        Frame& parent = stack[--top];
        parent.color += branch(parent, parent.next).weight * f.color;
        ++parent.next;
    }
}

}  // namespace

Color trace_ray(const PreparedScene& scene, const Ray& ray, int depth, const Color& weight,
                TraceObserver* observer) {
    return trace(scene, ray, depth, weight, observer, nullptr);
}

Color trace_ray(const PreparedScene& scene, const Ray& ray, int depth, RayNode* node,
                const Color& weight) {
    if (!node) return trace_ray(scene, ray, depth, weight, nullptr);
    RayTreeRecorder recorder(scene, *node);
    return trace_ray(scene, ray, depth, weight, &recorder);
}

Color trace_sample(const PreparedScene& scene, const Ray& ray, SampleStream& stream,
                   TraceObserver* observer) {
    // Stage 11: a path-traced scene's samples are path_radiance's (no ray tree for the debugger).
    if (scene.features.path_tracing) return path_radiance(scene, ray, stream);
    return trace(scene, ray, 0, Color(1), observer, nullptr, &stream);
}

Color shade_pixel(const PreparedScene& scene, int x, int y, RayNode* tree) {
    // Stage 10: the debugger shows the first sample's rays (with moving spheres, the blockers
    // its shadow records name are looked up at time 0).
    if (scene.features.sampled()) {
        if (!tree) return shade_sampled_pixel(scene, x, y);
        *tree = RayNode{};
        RayTreeRecorder recorder(scene, *tree);
        return sample_pixel(scene, x, y, 0, &recorder);
    }
    const Ray ray =
        camera_ray(scene.camera, Vec2(Real(x) + Real(0.5), Real(y) + Real(0.5)), scene.image);
    if (tree) *tree = RayNode{};
    // The OpenImageIO texture lookups filter over the pixel's footprint, which the neighbouring
    // pixels' camera rays give; the other lookups need none, so skip the two rays.
    if (scene.oiio_textures && (scene.texture_lookup == TextureLookup::Oiio ||
                                scene.texture_lookup == TextureLookup::OiioAniso)) {
        const Vec2 center(Real(x) + Real(0.5), Real(y) + Real(0.5));
        const RayDifferential rays{camera_ray(scene.camera, center + Vec2(1, 0), scene.image),
                                   camera_ray(scene.camera, center + Vec2(0, 1), scene.image)};
        if (!tree) return trace(scene, ray, 0, Color(1), nullptr, &rays);
        RayTreeRecorder recorder(scene, *tree);
        return trace(scene, ray, 0, Color(1), &recorder, &rays);
    }
    return trace_ray(scene, ray, 0, tree);
}

}  // namespace rt
