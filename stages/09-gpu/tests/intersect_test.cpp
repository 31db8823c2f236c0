// Stage 09's GPU unit tests: the student's intersect_sphere, _plane, _triangle and _box (GLSL)
// run on a batch of rays in a compute shader (tests/intersect_cases.comp) and answer as stage
// 02's functions (C++) do on the same float inputs: hit or miss, t, the normal, the face. The
// two compute in float, but llvmpipe's sqrt and operation order are not the C++ library's, so
// t and the normal may differ by 1e-4 relative, and a ray grazing a silhouette or an edge may
// flip: at most 0.5 % of the cases (the conformance test's allowance for pixels).
#include <glm/glm.hpp>

#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gl/compute_program.h"
#include "gl/gl_context.h"
#include "gpu/gpu_scene.h"
#include "render/gpu_render.h"
#include "stage_api/stage02.h"
#include "testing/stage_test.h"

namespace rt {
namespace {

struct alignas(16) GpuRayCase {
    glm::vec4 origin_kind, direction, range, a, b, c;
};
static_assert(sizeof(GpuRayCase) == 96, "6 vec4s, as intersect_cases.comp reads them");

const Sphere kCaseSphere{{0.3f, -0.2f, 0.1f}, 1.3f, 0};
const Plane kCasePlane{{0, -1, 0}, normalize(Vec3(0.1f, 1, 0.2f)), 0};
const Vec3 kTri[3] = {{-1, -1, 0}, {1.5f, -0.5f, 0.2f}, {0, 1.2f, -0.3f}};
const Box kCaseBox{{-1, -0.5f, -0.8f}, {0.7f, 1, 0.6f}, 0};

glm::vec4 g4(const Vec3& v, float w = 0) {
    return glm::vec4(v.x, v.y, v.z, w);
}

// 512 rays a kind from random origins towards random points near the primitive (about half hit).
std::vector<GpuRayCase> intersect_cases() {
    std::mt19937_64 random(20260902);
    std::uniform_real_distribution<float> box(-4, 4), near(-1.6f, 1.6f);
    std::vector<GpuRayCase> cases;
    for (int kind = 0; kind < 4; ++kind)
        for (int i = 0; i < 512; ++i) {
            const Vec3 o(box(random), box(random), box(random));
            const Vec3 target(near(random), near(random), near(random));
            GpuRayCase c{g4(o, gpu::int_bits(kind)),
                         g4(target - o),
                         glm::vec4(1e-3f, kInfinity, 0, 0),
                         {},
                         {},
                         {}};
            if (kind == 0) c.a = g4(kCaseSphere.center, kCaseSphere.radius);
            if (kind == 1) c.a = g4(kCasePlane.point), c.b = g4(kCasePlane.normal);
            if (kind == 2) c.a = g4(kTri[0]), c.b = g4(kTri[1]), c.c = g4(kTri[2]);
            if (kind == 3) c.a = g4(kCaseBox.min), c.b = g4(kCaseBox.max);
            cases.push_back(c);
        }
    return cases;
}

// Stage 02's answer (C++) for one case.
bool cpu_answer(const GpuRayCase& c, Hit& hit) {
    const Ray ray(Vec3(c.origin_kind.x, c.origin_kind.y, c.origin_kind.z),
                  Vec3(c.direction.x, c.direction.y, c.direction.z));
    const Interval range{c.range.x, c.range.y};
    int kind;
    std::memcpy(&kind, &c.origin_kind.w, sizeof kind);
    switch (kind) {
        case 0:
            return intersect_sphere(ray, kCaseSphere, range, hit);
        case 1:
            return intersect_plane(ray, kCasePlane, range, hit);
        case 2:
            return intersect_triangle(ray, kTri[0], kTri[1], kTri[2], range, hit);
        default:
            return intersect_box(ray, kCaseBox, range, hit);
    }
}

GLuint case_buffer(const GlApi& gl, int binding, GLsizeiptr bytes, const void* data) {
    GLuint buffer = 0;
    gl.GenBuffers(1, &buffer);
    gl.BindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    gl.BufferData(GL_SHADER_STORAGE_BUFFER, bytes, data, GL_DYNAMIC_DRAW);
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(binding), buffer);
    return buffer;
}

RT_TEST_SUITE(GpuIntersect);

TEST_F(GpuIntersect, AnswersAsStage02Does) {
    std::string error;
    const std::unique_ptr<GlContext> context = GlContext::create(GlKind::Egl, error);
    ASSERT_TRUE(context) << error;
    const GlApi& gl = context->gl();
    const std::filesystem::path root = ::rt::testing::source_dir();
    const AssembledShader shader =
        assemble_shader(root / "stages/09-gpu/tests/intersect_cases.comp",
                        {root / "shaders", gpu_student_dir()}, "");
    const GLuint program = build_compute_program(gl, shader, error);
    ASSERT_NE(program, 0u) << error;
    const std::vector<GpuRayCase> cases = intersect_cases();
    // Binding 15 (compute_io.glsl's Output): 4 words of stub flags, then the answers.
    std::vector<glm::vec4> output(1 + 4 * cases.size(), glm::vec4(0));
    const GLuint buffers[2] = {
        case_buffer(gl, gpu::kTexels, GLsizeiptr(cases.size() * sizeof(GpuRayCase)), cases.data()),
        case_buffer(gl, 15, GLsizeiptr(output.size() * sizeof(glm::vec4)), output.data())};
    gl.UseProgram(program);
    gl.Uniform1i(gl.GetUniformLocation(program, "case_count"), int(cases.size()));
    gl.DispatchCompute(GLuint((cases.size() + 63) / 64), 1, 1);
    gl.MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.GetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(output.size() * sizeof(glm::vec4)),
                        output.data());
    ASSERT_EQ(gl.GetError(), GLenum(GL_NO_ERROR));
    gl.DeleteBuffers(2, buffers);
    gl.DeleteProgram(program);
    std::uint32_t flags[4];
    std::memcpy(flags, &output[0], sizeof flags);
    report_gpu_stubs(shader, flags);

    int flips = 0, hits = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        Hit cpu;
        const bool cpu_found = cpu_answer(cases[i], cpu);
        const glm::vec4* g = &output[1 + 4 * i];  // found, t, stub; normal, front; point; uv
        if (cpu_found != (g[0].x == 1)) {
            ++flips;
            continue;
        }
        if (!cpu_found) continue;
        ++hits;
        const float scale = std::max(1.0f, float(cpu.t));
        EXPECT_NEAR(g[0].y, cpu.t, 1e-4f * scale) << "case " << i;
        EXPECT_NEAR(g[1].x, cpu.normal.x, 1e-4f) << "case " << i;
        EXPECT_NEAR(g[1].y, cpu.normal.y, 1e-4f) << "case " << i;
        EXPECT_NEAR(g[1].z, cpu.normal.z, 1e-4f) << "case " << i;
        EXPECT_EQ(g[1].w == 1, cpu.front_face) << "case " << i;
    }
    std::printf("%zu cases, %d hits, %d hit/miss flips\n", cases.size(), hits, flips);
    EXPECT_GT(hits, int(cases.size() / 4)) << "the cases should hit about half the time";
    EXPECT_LE(flips, int(cases.size() / 200))
        << "GPU and CPU disagree on hit or miss; read stages/09-gpu/README.md#intersections";
}

}  // namespace
}  // namespace rt
