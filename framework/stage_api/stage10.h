// Stage 10 (distribution ray tracing): the functions students write in
// stages/10-sampling/sampling.cpp (warping uniform numbers into distributions, the camera) and
// stages/10-sampling/lights.cpp (area lights, glossy reflection, ambient occlusion, indirect
// light). Handout: stages/10-sampling/README.md. Conventions: docs/conventions.md#sampling.
//
// Every function gets its random numbers as arguments: u components are uniform in [0, 1).
// The framework draws them (render/sampled.h, a PCG generator seeded per pixel and sample), so
// these functions are plain functions of their inputs, and the tests can check distributions.
// The framework calls them only for scenes that use a stage 10 feature (Features::sampled()).
#pragma once

#include "scene/prepared_scene.h"
#include "scene/surface_point.h"
#include "stage_api/stage03.h"

namespace rt {

// ---------------------------------------------------------------- sampling.cpp

// Stratified (jittered) sample `index` of `count` in the unit square: with n = floor(sqrt(count)),
// sample i < n*n lies in cell (i mod n, i div n) of an n x n grid, at (cell + u) / n; samples
// i >= n*n are not stratified (u itself). So the `count` samples of a pixel cover it evenly.
Vec2 stratified_sample(int index, int count, Vec2 u);

// Filter importance sampling: the offset from the pixel centre of a camera sample, for u
// uniform in the unit square. Box: uniform in [-0.5, 0.5)^2. Tent (radius 1): each axis
// independently with density 1 - |x| on (-1, 1). Every sample then weighs the same.
Vec2 box_filter_offset(Vec2 u);
Vec2 tent_filter_offset(Vec2 u);

// A point uniformly distributed on the unit disk (density 1 / pi).
Vec2 sample_uniform_disk(Vec2 u);

// A unit direction in the hemisphere z >= 0 with density cos(theta) / pi (theta from +z).
Vec3 sample_cosine_hemisphere(Vec2 u);
Real cosine_hemisphere_pdf(const Vec3& direction);  // the density of a unit direction; 0 below

// A unit direction uniformly distributed on the sphere (density 1 / (4 pi)).
Vec3 sample_uniform_sphere(Vec2 u);

// The thin-lens camera ray for the pinhole ray `pinhole` (stage 01's, from camera.eye, unit
// direction): the lens is the disk of diameter `aperture` around camera.eye in the plane
// spanned by camera.u and camera.v; the plane in focus is perpendicular to -camera.w at
// `focus_distance` from the eye. The ray starts at the lens point
// eye + aperture / 2 (d.x u + d.y v), d = sample_uniform_disk(u), and goes (unit direction)
// through the point where the pinhole ray meets the plane in focus.
Ray thin_lens_ray(const Camera& camera, const Ray& pinhole, Real aperture, Real focus_distance,
                  Vec2 u);

// The time of a camera sample, uniform over the shutter interval [open, close]. The framework
// gives it to the camera ray (Ray::time); rays spawned from its hits keep it, and every
// intersection sees a moving sphere where it is then (Scene::sphere_at).
Real shutter_time(Real open, Real close, Real u);

// Optional (fog): a free-flight distance in a medium of density sigma_t > 0, the distance a
// ray travels before it is scattered or absorbed: density sigma_t exp(-sigma_t s) on [0, inf).
Real sample_free_flight(Real sigma_t, Real u);

// ---------------------------------------------------------------- lights.cpp

// A point sampled on an area light, seen from `from`.
struct AreaSample {
    Vec3 point{0};   // on the light
    Vec3 normal{0};  // the light's unit outward normal at `point`
    Real pdf = 0;    // density of the direction from `from` to `point`, per unit solid angle
};

// A point on the rectangle corner + s edge_u + t edge_v (s, t in [0, 1]) and the solid-angle
// density of its direction from `from`: any technique whose pdf is right (uniform in area:
// pdf = distance^2 / (|cos theta_light| area)). normal = normalize(cross(edge_u, edge_v)).
AreaSample sample_rectangle(const AreaLight& light, const Vec3& from, Vec2 u);
// The density sample_rectangle gives the unit direction `direction` from `from`: 0 when the
// ray from `from` along it misses the rectangle.
Real rectangle_pdf(const AreaLight& light, const Vec3& from, const Vec3& direction);

// A point on the sphere light (light.center, light.radius) visible from `from` (outside the
// sphere), and its solid-angle density: any technique whose pdf is right (uniform in the cone
// of directions that see the sphere: pdf = 1 / (2 pi (1 - cos theta_max))).
AreaSample sample_sphere(const AreaLight& light, const Vec3& from, Vec2 u);
// The density sample_sphere gives the unit direction `direction`; 0 when it misses the sphere.
Real sphere_pdf(const AreaLight& light, const Vec3& from, const Vec3& direction);

// What one sample of an area light delivers at `point`: direction and distance to the sampled
// point, and intensity = radiance / (pi pdf), so that stage 03's blinn_phong turns it into the
// estimate of k_d / pi times the light's irradiance (docs/conventions.md#sampling). Intensity 0
// when the sample sees the back of a rectangle or pdf is 0.
LightSample sample_area_light(const AreaLight& light, const Vec3& point, Vec2 u);

// One-sample estimate of the light `light` reflects at `at` towards the viewer: the sample of
// sample_area_light, stage 03's blinn_phong, times stage 04's light_transmittance (soft
// shadows). 0 without calling light_transmittance when blinn_phong is 0.
Color area_light_estimate(const PreparedScene& scene, const Material& material,
                          const SurfacePoint& at, const Vec3& normal, const Vec3& to_viewer,
                          const AreaLight& light, Vec2 u);

// Glossy reflection: normalize(mirror + fuzz * sample_uniform_sphere(u)), `mirror` unit. (The
// framework drops a direction that points into the surface: that light is absorbed.)
Vec3 glossy_direction(const Vec3& mirror, Real fuzz, Vec2 u);

// A ray leaving `at` in a cosine-distributed direction about the unit `normal` (facing the
// viewer): sample_cosine_hemisphere turned into the frame of `normal` (geometry/onb.h), made
// with spawn_ray(at, at.normal, direction) (scene/surface_point.h).
Ray cosine_ray(const SurfacePoint& at, const Vec3& normal, Vec2 u);

// One-sample ambient occlusion: 1 when the cosine_ray meets nothing (nearest_hit,
// render/nearest_hit.h) closer than max_distance, else 0. Its average is the cosine-weighted
// fraction of the hemisphere that is open; the ambient term becomes k_a I_a times it.
Real ambient_occlusion(const PreparedScene& scene, const SurfacePoint& at, const Vec3& normal,
                       Real max_distance, Vec2 u);

// The radiance arriving at a point along a ray (the framework traces it: the direct light at
// the surface the ray meets, or the background).
class IncomingRadiance {
  public:
    virtual Color operator()(const Ray& ray) const = 0;

  protected:
    ~IncomingRadiance() = default;
};

// Optional (fog, scene.fog: render/shade.cpp calls these only when Features::fog).
// The fraction of light that crosses the part of `ray` with t in `range` unscattered:
// exp(-density * s), s the distance (in world units: t times |direction|) that part travels
// inside the medium (medium_interval in scene/scene.h gives the part). 1 when it is empty.
Real medium_transmittance(const Medium& medium, const Ray& ray, Interval range);

// One free-flight sample along `ray` through the medium, up to t_max (the nearest surface, or
// infinity): the ray enters the medium at the start of its part inside it (medium_interval with
// (0, t_max)) and travels sample_free_flight(density, u) from there. When it stops before the
// part ends, the light was scattered at `t` (scattered true); else it passes (scattered false,
// probability medium_transmittance over (0, t_max)).
struct FogEvent {
    bool scattered = false;
    Real t = 0;  // the ray parameter of the scattering point, when scattered
};
FogEvent sample_fog(const Medium& medium, const Ray& ray, Real t_max, Real u);

// One-sample estimate of the diffuse light reflected at `at` from light arriving off other
// surfaces and the background: the Lambertian BRDF k_d / pi times the incoming radiance times
// cos, over the pdf of cosine_ray. It replaces the ambient term (the framework has removed
// k_a I_a: do not add it back, that light would be counted twice).
Color indirect_diffuse(const SurfacePoint& at, const Vec3& normal, const Material& material, Vec2 u,
                       const IncomingRadiance& incoming);

}  // namespace rt
