// The call lists: every function a grading judge must call in the worker (framework/remote/),
// one list per stage API plus the framework functions that call student code (render/).
// Each entry is X(return type, name, (parameters), (arguments)); the parameters are those of the
// declaration in stage_api/stageNN.h or render/*.h, without default arguments. The judge's
// proxies and the worker's dispatch table are both generated from these lists, and
// Framework.Remote.EveryStageFunctionHasAProxy fails when a stage's stub defines a function that
// no list names.
#pragma once

// clang-format off
#define RT_STAGE01_CALLS(X) \
    X(Ray, perspective_ray, (const Camera& camera, Vec2 pixel, ImageSize size), (camera, pixel, size)) \
    X(Ray, orthographic_ray, (const Camera& camera, Vec2 pixel, ImageSize size), (camera, pixel, size))

#define RT_STAGE02_CALLS(X) \
    X(bool, intersect_sphere, (const Ray& ray, const Sphere& sphere, Interval t_range, Hit& hit), (ray, sphere, t_range, hit)) \
    X(bool, intersect_plane, (const Ray& ray, const Plane& plane, Interval t_range, Hit& hit), (ray, plane, t_range, hit)) \
    X(bool, intersect_triangle, (const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, Interval t_range, Hit& hit), (ray, a, b, c, t_range, hit)) \
    X(bool, intersect_box, (const Ray& ray, const Box& box, Interval t_range, Hit& hit), (ray, box, t_range, hit)) \
    X(bool, intersect_nearest, (const Ray& ray, const Scene& scene, Interval t_range, Hit& hit), (ray, scene, t_range, hit))

#define RT_STAGE03_CALLS(X) \
    X(LightSample, illuminate, (const Light& light, const Vec3& point), (light, point)) \
    X(Color, blinn_phong, (const Material& material, const Vec3& normal, const Vec3& to_viewer, const Vec3& to_light, const Color& incident), (material, normal, to_viewer, to_light, incident)) \
    X(Color, direct_light, (const Scene& scene, const Material& material, const Vec3& point, const Vec3& normal, const Vec3& to_viewer, LightVisibility visibility), (scene, material, point, normal, to_viewer, visibility))

#define RT_STAGE04_CALLS(X) \
    X(ShadowRay, shadow_ray, (const SurfacePoint& at, const LightSample& sample), (at, sample)) \
    X(Color, light_transmittance, (const PreparedScene& scene, const SurfacePoint& at, const LightSample& sample), (scene, at, sample))

#define RT_STAGE05_CALLS(X) \
    X(Vec3, reflect, (const Vec3& d, const Vec3& n), (d, n)) \
    X(bool, refract, (const Vec3& d, const Vec3& n, Real eta, Vec3& refracted), (d, n, eta, refracted)) \
    X(Real, schlick_reflectance, (Real cos_incident, Real n1, Real n2), (cos_incident, n1, n2)) \
    X(SecondaryRays, secondary_rays, (const Ray& incoming, const SurfacePoint& at, const Material& material, bool fresnel), (incoming, at, material, fresnel))

#define RT_STAGE06_CALLS(X) \
    X(SahSplit, find_sah_split, (const std::vector<BvhPrimitive>& prims, std::size_t begin, std::size_t end, const BvhBuildOptions& options), (prims, begin, end, options)) \
    X(void, build_bvh, (std::vector<BvhPrimitive> prims, const BvhBuildOptions& options, Bvh& bvh), (prims, options, bvh)) \
    X(bool, intersect_node, (const BvhNode& node, const Ray& ray, const Vec3& inv_direction, Interval t_range, Real& t_entry), (node, ray, inv_direction, t_range, t_entry)) \
    X(bool, bvh_intersect_nearest, (const PreparedScene& scene, const Ray& ray, Interval t_range, Hit& hit, BvhStats* stats), (scene, ray, t_range, hit, stats)) \
    X(bool, bvh_intersect_any, (const PreparedScene& scene, const Ray& ray, Interval t_range, BvhStats* stats), (scene, ray, t_range, stats))

#define RT_STAGE07_CALLS(X) \
    X(Vec2, sphere_texcoord, (const Vec3& outward_normal), (outward_normal)) \
    X(Vec2, plane_texcoord, (const Plane& plane, const Vec3& point), (plane, point)) \
    X(Vec2, box_texcoord, (const Box& box, const Vec3& point, const Vec3& outward_normal), (box, point, outward_normal)) \
    X(Vec2, triangle_texcoord, (const Vec2& uv_a, const Vec2& uv_b, const Vec2& uv_c, Vec2 barycentric), (uv_a, uv_b, uv_c, barycentric)) \
    X(Real, srgb_to_linear_value, (Real encoded), (encoded)) \
    X(Color, decoded_texel, (const TextureView& image, int i, int j), (image, i, j)) \
    X(int, wrap_texel, (int i, int n, TextureWrap wrap), (i, n, wrap)) \
    X(Color, sample_nearest, (const TextureView& image, Vec2 uv, TextureWrap wrap), (image, uv, wrap)) \
    X(Color, sample_bilinear, (const TextureView& image, Vec2 uv, TextureWrap wrap), (image, uv, wrap)) \
    X(Color, checker_2d, (Vec2 uv, const Color& a, const Color& b), (uv, a, b)) \
    X(Color, checker_3d, (const Vec3& point, const Color& a, const Color& b, Real size), (point, a, b, size)) \
    X(Real, gradient_noise, (const Vec3& point), (point)) \
    X(Color, marble, (const Vec3& point, const Color& a, const Color& b, Real scale), (point, a, b, scale)) \
    X(Vec3, normal_from_map, (const Vec3& normal, const Vec3& tangent, const Color& texel, const Vec3& to_viewer), (normal, tangent, texel, to_viewer)) \
    X(PlaneFrame, plane_frame, (const Vec3& normal), (normal)) \
    X(Vec3, noise_gradient, (int x, int y, int z), (x, y, z))

#define RT_STAGE08_CALLS(X) \
    X(Vec2, latlong_uv, (const Vec3& direction), (direction)) \
    X(CubeFaceUv, cube_face_uv, (const Vec3& direction), (direction)) \
    X(Color, environment_radiance, (const Scene& scene, const Vec3& direction), (scene, direction))

#define RT_STAGE10_CALLS(X) \
    X(Vec2, stratified_sample, (int index, int count, Vec2 u), (index, count, u)) \
    X(Vec2, box_filter_offset, (Vec2 u), (u)) \
    X(Vec2, tent_filter_offset, (Vec2 u), (u)) \
    X(Vec2, sample_uniform_disk, (Vec2 u), (u)) \
    X(Vec3, sample_cosine_hemisphere, (Vec2 u), (u)) \
    X(Real, cosine_hemisphere_pdf, (const Vec3& direction), (direction)) \
    X(Vec3, sample_uniform_sphere, (Vec2 u), (u)) \
    X(Ray, thin_lens_ray, (const Camera& camera, const Ray& pinhole, Real aperture, Real focus_distance, Vec2 u), (camera, pinhole, aperture, focus_distance, u)) \
    X(Real, shutter_time, (Real open, Real close, Real u), (open, close, u)) \
    X(Real, sample_free_flight, (Real sigma_t, Real u), (sigma_t, u)) \
    X(AreaSample, sample_rectangle, (const AreaLight& light, const Vec3& from, Vec2 u), (light, from, u)) \
    X(Real, rectangle_pdf, (const AreaLight& light, const Vec3& from, const Vec3& direction), (light, from, direction)) \
    X(AreaSample, sample_sphere, (const AreaLight& light, const Vec3& from, Vec2 u), (light, from, u)) \
    X(Real, sphere_pdf, (const AreaLight& light, const Vec3& from, const Vec3& direction), (light, from, direction)) \
    X(LightSample, sample_area_light, (const AreaLight& light, const Vec3& point, Vec2 u), (light, point, u)) \
    X(Color, area_light_estimate, (const PreparedScene& scene, const Material& material, const SurfacePoint& at, const Vec3& normal, const Vec3& to_viewer, const AreaLight& light, Vec2 u), (scene, material, at, normal, to_viewer, light, u)) \
    X(Vec3, glossy_direction, (const Vec3& mirror, Real fuzz, Vec2 u), (mirror, fuzz, u)) \
    X(Ray, cosine_ray, (const SurfacePoint& at, const Vec3& normal, Vec2 u), (at, normal, u)) \
    X(Real, ambient_occlusion, (const PreparedScene& scene, const SurfacePoint& at, const Vec3& normal, Real max_distance, Vec2 u), (scene, at, normal, max_distance, u)) \
    X(Real, medium_transmittance, (const Medium& medium, const Ray& ray, Interval range), (medium, ray, range)) \
    X(FogEvent, sample_fog, (const Medium& medium, const Ray& ray, Real t_max, Real u), (medium, ray, t_max, u)) \
    X(Color, indirect_diffuse, (const SurfacePoint& at, const Vec3& normal, const Material& material, Vec2 u, const IncomingRadiance& incoming), (at, normal, material, u, incoming))

#define RT_STAGE11_CALLS(X) \
    X(Real, ggx_d, (const Vec3& h, Real alpha), (h, alpha)) \
    X(Real, ggx_g1, (const Vec3& v, const Vec3& h, Real alpha), (v, h, alpha)) \
    X(Vec3, sample_ggx_normal, (Real alpha, Vec2 u), (alpha, u)) \
    X(Real, ggx_normal_pdf, (const Vec3& h, Real alpha), (h, alpha)) \
    X(Color, schlick_fresnel, (const Color& f0, Real cos_theta), (f0, cos_theta)) \
    X(BsdfSample, sample_bsdf, (const Material& material, const Vec3& wo, Real u_lobe, Vec2 u), (material, wo, u_lobe, u)) \
    X(Color, eval_bsdf, (const Material& material, const Vec3& wo, const Vec3& wi), (material, wo, wi)) \
    X(Real, bsdf_pdf, (const Material& material, const Vec3& wo, const Vec3& wi), (material, wo, wi)) \
    X(Real, balance_heuristic, (Real pdf_f, Real pdf_g), (pdf_f, pdf_g)) \
    X(Real, power_heuristic, (Real pdf_f, Real pdf_g), (pdf_f, pdf_g)) \
    X(Color, sample_light_mis, (const PreparedScene& scene, const SurfacePoint& at, const Onb& frame, const Material& material, const Vec3& wo, Real u_light, Vec2 u), (scene, at, frame, material, wo, u_light, u)) \
    X(Color, path_radiance, (const PreparedScene& scene, const Ray& ray, SampleStream& stream), (scene, ray, stream))

// The framework functions of render/ that call student code and that tests call: each crosses
// as one call (a whole render, a whole BVH build), never as one call per ray.
#define RT_RENDER_CALLS(X) \
    X(PreparedScene, prepare_scene, (Scene description, const SceneOverrides& overrides, const BvhBuildOptions& bvh_options, AccelerationReport* acceleration), (description, overrides, bvh_options, acceleration)) \
    X(AccelerationReport, build_acceleration, (PreparedScene& scene, const BvhBuildOptions& options), (scene, options)) \
    X(Ray, camera_ray, (const Camera& camera, Vec2 pixel, ImageSize size), (camera, pixel, size)) \
    X(Image, render, (const PreparedScene& scene, RenderMode mode, const RenderOptions& options), (scene, mode, options)) \
    X(Color, shade_pixel, (const PreparedScene& scene, int x, int y, RayNode* tree), (scene, x, y, tree)) \
    X(Color, trace_ray, (const PreparedScene& scene, const Ray& ray, int depth, RayNode* node, const Color& weight), (scene, ray, depth, node, weight)) \
    X(PixelTree, debug_pixel, (const PreparedScene& scene, int x, int y), (scene, x, y)) \
    X(std::string, ray_tree_text, (const PreparedScene& scene, const PixelTree& tree), (scene, tree)) \
    X(std::string, ray_tree_json, (const PreparedScene& scene, const PixelTree& tree), (scene, tree)) \
    X(void, draw_ray_tree, (const PreparedScene& scene, const PixelTree& tree, Image& image), (scene, tree, image)) \
    X(Color, background, (const PreparedScene& scene, const Vec3& direction), (scene, direction)) \
    X(Vec2, surface_texcoord, (const PreparedScene& scene, const Hit& hit, const SurfacePoint& at), (scene, hit, at)) \
    X(Color, sample_pixel, (const PreparedScene& scene, int x, int y, int sample, TraceObserver* observer), (scene, x, y, sample, observer))

// Stage 09's: the framework functions that run the student's GLSL (render/gpu/gpu_render.h,
// render/gpu/gpu_cases.h, render/gpu/shadertoy_run.h). A judge sends them to the worker too, so it links
// no GPU renderer and runs no GLSL.
#define RT_GPU_CALLS(X) \
    X(Image, render_gpu, (const PreparedScene& scene, RenderMode mode, const GpuRenderOptions& options), (scene, mode, options)) \
    X(bool, run_gpu_cases, (const std::vector<gpu_cases::GpuRayCase>& cases, std::vector<gpu_cases::GpuAnswer>& answers, std::string& error), (cases, answers, error)) \
    X(ShadertoyRun, run_shadertoy_export, (const PreparedScene& scene, RenderMode mode), (scene, mode))

#define RT_ALL_CALLS(X) \
    RT_STAGE01_CALLS(X) RT_STAGE02_CALLS(X) RT_STAGE03_CALLS(X) RT_STAGE04_CALLS(X) \
    RT_STAGE05_CALLS(X) RT_STAGE06_CALLS(X) RT_STAGE07_CALLS(X) RT_STAGE08_CALLS(X) \
    RT_STAGE10_CALLS(X) RT_STAGE11_CALLS(X) RT_RENDER_CALLS(X)
// clang-format on
