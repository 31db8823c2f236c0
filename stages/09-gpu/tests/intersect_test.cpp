// Stage 09's GPU unit tests: the student's intersect_sphere, _plane, _triangle and _box (GLSL)
// run on a batch of rays in a compute shader (shaders/intersect_cases.comp) and answer as stage
// 02's functions (C++) do on the same float inputs: hit or miss, t, the normal, the face. The
// two compute in float, but llvmpipe's sqrt and operation order are not the C++ library's, so
// t and the normal may differ by 1e-4 relative, and a ray grazing a silhouette or an edge may
// flip: at most 0.5 % of the cases (the conformance test's allowance for pixels).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "render/gpu/gpu_cases.h"
#include "stage_api/stage02.h"
#include "testing/random.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

using gpu_cases::GpuAnswer;

const Sphere kCaseSphere{{0.3f, -0.2f, 0.1f}, 1.3f, 0};
const Plane kCasePlane{{0, -1, 0}, normalize(Vec3(0.1f, 1, 0.2f)), 0};
const Vec3 kTri[3] = {{-1, -1, 0}, {1.5f, -0.5f, 0.2f}, {0, 1.2f, -0.3f}};
const Box kCaseBox{{-1, -0.5f, -0.8f}, {0.7f, 1, 0.6f}, 0};

struct RandomCase {
    Ray ray;
    int kind;
};

// 512 rays a kind from random origins towards random points near the primitive (about half hit).
std::vector<RandomCase> random_cases() {
    testing::Random random(20260902);
    std::vector<RandomCase> cases;
    for (int kind = 0; kind < 4; ++kind)
        for (int i = 0; i < 512; ++i) {
            const Vec3 o = random.vec(-4, 4);
            const Vec3 target = random.vec(-1.6, 1.6);
            cases.push_back({Ray(o, Vec3(glm::vec3(target - o))), kind});  // d as uploaded
        }
    return cases;
}

const Interval kRange{1e-3f, kInfinity};

gpu_cases::GpuRayCase gpu_case(const RandomCase& c) {
    switch (c.kind) {
        case gpu_cases::kSphere:
            return gpu_cases::sphere_case(c.ray, kCaseSphere, kRange);
        case gpu_cases::kPlane:
            return gpu_cases::plane_case(c.ray, kCasePlane, kRange);
        case gpu_cases::kTriangle:
            return gpu_cases::triangle_case(c.ray, kTri[0], kTri[1], kTri[2], kRange);
        default:
            return gpu_cases::box_case(c.ray, kCaseBox, kRange);
    }
}

// Stage 02's answer (C++) for one case.
bool cpu_answer(const RandomCase& c, Hit& hit) {
    switch (c.kind) {
        case gpu_cases::kSphere:
            return intersect_sphere(c.ray, kCaseSphere, kRange, hit);
        case gpu_cases::kPlane:
            return intersect_plane(c.ray, kCasePlane, kRange, hit);
        case gpu_cases::kTriangle:
            return intersect_triangle(c.ray, kTri[0], kTri[1], kTri[2], kRange, hit);
        default:
            return intersect_box(c.ray, kCaseBox, kRange, hit);
    }
}

// The GPU's answers against stage 02's (C++) for `cases`, each failure named by `name(i)`; counts
// the hits on both sides and the hit/miss flips, which the caller judges.
struct Agreement {
    int hits = 0, flips = 0;
};
template <class Name>
Agreement expect_agreement(const std::vector<RandomCase>& cases,
                           const std::vector<GpuAnswer>& answers, Name name) {
    Agreement a;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        Hit cpu;
        const bool cpu_found = cpu_answer(cases[i], cpu);
        const GpuAnswer& g = answers[i];
        if (cpu_found != g.found) {
            ++a.flips;
            continue;
        }
        if (!cpu_found) continue;
        ++a.hits;
        const float scale = std::max(1.0f, float(cpu.t));
        const std::string what = name(i);
        EXPECT_NEAR(g.t, cpu.t, 1e-4f * scale) << what;
        EXPECT_NEAR(g.normal.x, cpu.normal.x, 1e-4f) << what;
        EXPECT_NEAR(g.normal.y, cpu.normal.y, 1e-4f) << what;
        EXPECT_NEAR(g.normal.z, cpu.normal.z, 1e-4f) << what;
        EXPECT_EQ(g.front_face, cpu.front_face) << what;
        // hit.uv: a triangle's barycentrics (beta, gamma) in that order; (0, 0) on the others.
        EXPECT_NEAR(g.uv.x, cpu.uv.x, 1e-4f)
            << what << ": hit.uv.x is " << g.uv.x << ", stage 02 says " << cpu.uv.x;
        EXPECT_NEAR(g.uv.y, cpu.uv.y, 1e-4f) << what << ": hit.uv.y";
    }
    return a;
}

std::vector<GpuAnswer> answers_on_gpu(const std::vector<RandomCase>& cases) {
    std::vector<gpu_cases::GpuRayCase> gpu;
    for (const RandomCase& c : cases) gpu.push_back(gpu_case(c));
    std::vector<GpuAnswer> answers;
    std::string error;
    EXPECT_TRUE(run_gpu_cases(gpu, answers, error)) << error;
    answers.resize(cases.size());
    return answers;
}

RT_TEST_SUITE(GpuIntersect, "intersections");

TEST_F(GpuIntersect, AnswersAsStage02Does) {
    const std::vector<RandomCase> cases = random_cases();
    const Agreement a = expect_agreement(cases, answers_on_gpu(cases), [&](std::size_t i) {
        // "sphere case 17": the cases come 512 to a kind (random_cases).
        return std::string(gpu_cases::kind_name(cases[i].kind)) + " case " +
               std::to_string(i % 512);
    });
    std::printf("%zu cases, %d hits, %d hit/miss flips\n", cases.size(), a.hits, a.flips);
    EXPECT_GT(a.hits, int(cases.size() / 4)) << "the cases should hit about half the time";
    EXPECT_LE(a.flips, int(cases.size() / 200))
        << "GPU and CPU disagree on hit or miss; read stages/09-gpu/README.md#intersections";
}

// Rays whose half_b (the stable quadratic's b / 2) is exactly 0: from the sphere's centre, and
// from points of the plane through the centre across the ray. GLSL's sign(0) is 0, so
// q = -(half_b + sign(half_b) * root) comes out 0 and the hit is lost; C++'s copysign is 1.
TEST_F(GpuIntersect, StableQuadraticWhereHalfBIsZero) {
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    std::vector<RandomCase> cases;
    for (int along = 0; along < 3; ++along)
        for (const Real sign : {Real(1), Real(-1)}) {
            const Vec3 d = sign * axes[along];
            cases.push_back({Ray(kCaseSphere.center, d), gpu_cases::kSphere});
            const Vec3 across = axes[(along + 1) % 3] * Real(0.5);
            cases.push_back({Ray(kCaseSphere.center + across, d), gpu_cases::kSphere});
        }
    const Agreement a = expect_agreement(cases, answers_on_gpu(cases), [&](std::size_t i) {
        return "the ray from (" + std::to_string(cases[i].ray.origin.x) + ", " +
               std::to_string(cases[i].ray.origin.y) + ", " +
               std::to_string(cases[i].ray.origin.z) + ") inside the sphere";
    });
    EXPECT_EQ(a.flips, 0) << a.flips << " of " << cases.size()
                          << " rays from inside the sphere with half_b = 0 miss it: GLSL's sign(0) "
                             "is 0, so the stable quadratic loses its root; read "
                             "stages/09-gpu/README.md#intersections";
}

}  // namespace
}  // namespace rt
