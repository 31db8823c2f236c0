// The BVH benchmark's input: the mesh (an OBJ file or a procedural mesh), a camera framing it, and
// the primary, shadow and diffuse rays every back-end traces.
#include "bench/bvh_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/split_mix64.h"
#include "geometry/procedural_mesh.h"
#include "scene/obj_loader.h"
#include "scene/surface_point.h"
#include "stage_api/stage06.h"

namespace rt::bench {

BenchMesh load_bench_mesh(const BvhBenchConfig& config) {
    BenchMesh m;
    Scene s;
    if (!config.mesh_file.empty()) {
        ObjMesh obj =
            load_obj(config.mesh_file, config.mesh_file, Vec3(1), Vec3(0), std::size_t(1) << 26);
        for (const std::string& warning : obj.warnings)
            std::fprintf(stderr, "rt-bench: warning: %s\n", warning.c_str());
        s.vertices = std::move(obj.vertices);
        s.triangles.reserve(obj.triangles.size());
        for (const auto& t : obj.triangles) s.triangles.push_back(Triangle{t, 0});
        m.description = config.mesh_file;
    } else {
        TriangleMesh mesh = make_procedural_mesh(config.procedural, config.triangles, config.seed);
        s.vertices = std::move(mesh.vertices);
        s.triangles.reserve(mesh.triangles.size());
        for (const auto& t : mesh.triangles) s.triangles.push_back(Triangle{t, 0});
        m.description =
            "procedural " + config.procedural + " (seed " + std::to_string(config.seed) + ")";
    }
    s.source = m.description;
    s.materials.push_back(Material{});
    // The benchmark builds its trees itself (bvh_backends.cpp), so no prepare_scene here.
    m.scene = PreparedScene{std::move(s), {}, {}, {}, {}};
    refresh_features(m.scene);
    return m;
}

namespace {

struct Framing {
    Camera camera;
    Vec3 light{0};
};

// A perspective camera looking at the mesh from the front, a little from the right and above,
// just far enough away that all eight corners of its bounding box are in the picture; and a point
// light above, right of and in front of the mesh, outside the box.
Framing frame_mesh(const PreparedScene& scene, int width, int height) {
    Vec3 lo(kInfinity), hi(-kInfinity);
    for (const Vec3& p : scene.vertices) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const Vec3 center = (lo + hi) * Real(0.5);
    Real radius = Real(0.5) * glm::length(hi - lo);
    if (!(radius > 0)) radius = 1;
    constexpr Real fov = 40;
    const Real tan_v = std::tan(glm::radians(fov / 2));
    const Real tan_h = tan_v * Real(width) / Real(height);
    // The frame first (it does not depend on the distance), then the distance each corner needs.
    const Vec3 view = glm::normalize(Vec3(0.3, 0.25, 1));
    const Camera frame =
        make_look_at_camera(Projection::Perspective, center + view, center, Vec3(0, 1, 0), fov, 2);
    Real distance = 0;
    for (int k = 0; k < 8; ++k) {
        const Vec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
        const Vec3 c = corner - center;
        const Real depth = glm::dot(c, frame.w);  // towards the eye
        distance = std::max({distance, depth + std::abs(glm::dot(c, frame.u)) / tan_h,
                             depth + std::abs(glm::dot(c, frame.v)) / tan_v});
    }
    if (!(distance > 0)) distance = radius / tan_v;
    Framing f;
    f.camera = make_look_at_camera(Projection::Perspective, center + Real(1.02) * distance * view,
                                   center, Vec3(0, 1, 0), fov, 2);
    f.light = center + radius * Vec3(1.5, 2.5, 2.0);
    return f;
}

// Embree intersects in float. So that every back-end traces the very same rays, and none of
// them starts within float rounding of its surface, a double build (RT_DOUBLE) rounds every ray
// to float and offsets secondary origins by the error bound of float arithmetic (twice the
// double bound scaled by the ratio of the unit roundoffs, so that the rounding to float cannot
// undo it). In a float build both are no-ops.
Vec3 as_float(const Vec3& v) {
    return Vec3(glm::vec3(v));
}
#ifdef RT_DOUBLE
constexpr Real kErrorScale =
    2 * Real(std::numeric_limits<float>::epsilon()) / std::numeric_limits<double>::epsilon();
#else
constexpr Real kErrorScale = 1;
#endif

// The primary ray through the centre of pixel (i, j), as docs/conventions.md#camera defines it
// (computed here so that the benchmark does not depend on stage 01).
Ray pixel_ray(const Camera& c, int i, int j, int width, int height) {
    const Real half_height = std::tan(glm::radians(c.vertical_fov_degrees) / 2);
    const Real half_width = half_height * Real(width) / Real(height);
    const Real x = (2 * (Real(i) + Real(0.5)) / Real(width) - 1) * half_width;
    const Real y = (1 - 2 * (Real(j) + Real(0.5)) / Real(height)) * half_height;
    return Ray{as_float(c.eye), as_float(glm::normalize(x * c.u + y * c.v - c.w))};
}

Real uniform(std::uint64_t bits) {
    return Real(bits >> 40) * Real(1.0 / 16777216.0);
}  // [0, 1)

// A cosine-weighted direction about the unit vector n. The tangent frame is the branch-free
// construction of Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017).
Vec3 cosine_direction(const Vec3& n, Real u1, Real u2) {
    const Real sign = std::copysign(Real(1), n.z);
    const Real a = -1 / (sign + n.z);
    const Real b = n.x * n.y * a;
    const Vec3 t(1 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    const Vec3 s(b, sign + n.y * n.y * a, -n.y);
    const Real r = std::sqrt(u1), phi = 2 * kPi * u2;
    const Real z = std::sqrt(std::max(Real(0), 1 - u1));
    return glm::normalize(r * std::cos(phi) * t + r * std::sin(phi) * s + z * n);
}

// Primary rays, one per pixel centre; then, from each primary hit (found with the stage 06 BVH),
// one shadow ray to the light and one cosine-weighted diffuse ray, both starting at
// offset_ray_origin. Deterministic: the same for any thread count.
BenchRays make_rays(const PreparedScene& scene, const Framing& framing,
                    const BvhBenchConfig& config, int threads) {
    BenchRays out;
    RayBatch& primary = out.batch[0];
    primary.kind = RayKind::Primary;
    const std::size_t n = std::size_t(config.width) * std::size_t(config.height);
    primary.rays.resize(n);
    primary.ranges.assign(n, Interval{0, kInfinity});
    for (int j = 0; j < config.height; ++j)
        for (int i = 0; i < config.width; ++i)
            primary.rays[std::size_t(j) * std::size_t(config.width) + std::size_t(i)] =
                pixel_ray(framing.camera, i, j, config.width, config.height);

    std::vector<Hit> hits(n);
    std::vector<char> found(n, 0);
    parallel_for_chunks(n, 1024, threads, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            found[i] = bvh_intersect_nearest(scene, primary.rays[i], primary.ranges[i], hits[i]);
    });

    RayBatch& shadow = out.batch[1];
    RayBatch& diffuse = out.batch[2];
    shadow.kind = RayKind::Shadow;
    shadow.any_hit = true;
    diffuse.kind = RayKind::Diffuse;
    for (std::size_t i = 0; i < n; ++i) {
        if (!found[i]) continue;
        ++out.primary_hits;
        const SurfacePoint sp = surface_point(scene, primary.rays[i], hits[i]);

        const Vec3 error = sp.error * kErrorScale;

        const Vec3 l = as_float(glm::normalize(framing.light - sp.point));
        const Vec3 shadow_origin = as_float(offset_ray_origin(sp.point, error, sp.normal, l));
        shadow.rays.push_back(Ray{shadow_origin, l});
        shadow.ranges.push_back(Interval{0, glm::length(framing.light - shadow_origin)});

        // SplitMix64 as a hash: ray i's random numbers depend on (seed, i) only.
        const std::uint64_t key =
            SplitMix64::hash(config.seed ^ SplitMix64::hash(std::uint64_t(i)));
        const Vec3 d =
            as_float(cosine_direction(sp.normal, uniform(key), uniform(SplitMix64::hash(key))));
        diffuse.rays.push_back(Ray{as_float(offset_ray_origin(sp.point, error, sp.normal, d)), d});
        diffuse.ranges.push_back(Interval{0, kInfinity});
    }
    return out;
}

}  // namespace

BenchRays make_bench_rays(const PreparedScene& scene, const BvhBenchConfig& config, int threads) {
    return make_rays(scene, frame_mesh(scene, config.width, config.height), config, threads);
}

}  // namespace rt::bench
