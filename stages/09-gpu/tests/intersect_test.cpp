// Stage 09's GPU unit tests: the student's intersect_sphere, _plane, _triangle and _box (GLSL)
// run on a batch of rays in a compute shader (shaders/intersect_cases.comp) and answer as stage
// 02's functions (C++) do on the same float inputs: hit or miss, t, the normal, the face. The
// two compute in float, but llvmpipe's sqrt and operation order are not the C++ library's, so
// t and the normal may differ by 1e-4 relative, and a ray grazing a silhouette or an edge may
// flip: at most 0.5 % of the cases (the conformance test's allowance for pixels).
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "render/gpu_cases.h"
#include "stage_api/stage02.h"
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
    std::mt19937_64 random(20260902);
    std::uniform_real_distribution<float> box(-4, 4), near(-1.6f, 1.6f);
    std::vector<RandomCase> cases;
    for (int kind = 0; kind < 4; ++kind)
        for (int i = 0; i < 512; ++i) {
            const Vec3 o(box(random), box(random), box(random));
            const Vec3 target(near(random), near(random), near(random));
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

RT_TEST_SUITE(GpuIntersect);

TEST_F(GpuIntersect, AnswersAsStage02Does) {
    const std::vector<RandomCase> cases = random_cases();
    std::vector<gpu_cases::GpuRayCase> gpu;
    for (const RandomCase& c : cases) gpu.push_back(gpu_case(c));
    std::vector<GpuAnswer> answers;
    std::string error;
    ASSERT_TRUE(run_gpu_cases(gpu, answers, error)) << error;

    int flips = 0, hits = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        Hit cpu;
        const bool cpu_found = cpu_answer(cases[i], cpu);
        const GpuAnswer& g = answers[i];
        if (cpu_found != g.found) {
            ++flips;
            continue;
        }
        if (!cpu_found) continue;
        ++hits;
        const float scale = std::max(1.0f, float(cpu.t));
        // "sphere case 17": the cases come 512 to a kind (random_cases).
        const std::string what =
            std::string(gpu_cases::kind_name(cases[i].kind)) + " case " + std::to_string(i % 512);
        EXPECT_NEAR(g.t, cpu.t, 1e-4f * scale) << what;
        EXPECT_NEAR(g.normal.x, cpu.normal.x, 1e-4f) << what;
        EXPECT_NEAR(g.normal.y, cpu.normal.y, 1e-4f) << what;
        EXPECT_NEAR(g.normal.z, cpu.normal.z, 1e-4f) << what;
        EXPECT_EQ(g.front_face, cpu.front_face) << what;
    }
    std::printf("%zu cases, %d hits, %d hit/miss flips\n", cases.size(), hits, flips);
    EXPECT_GT(hits, int(cases.size() / 4)) << "the cases should hit about half the time";
    EXPECT_LE(flips, int(cases.size() / 200))
        << "GPU and CPU disagree on hit or miss; read stages/09-gpu/README.md#intersections";
}

}  // namespace
}  // namespace rt
