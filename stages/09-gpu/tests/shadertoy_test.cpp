// Stage 09's export for Shadertoy (rt export-shadertoy, render/shadertoy_export.h): the shader
// compiles as Shadertoy compiles it (glslangValidator, GLSL ES 3.00, inside a wrapper declaring
// Shadertoy's uniforms and a main calling mainImage) and, drawn headless over a full-screen
// triangle, gives the CPU renderer's image under the conformance test's metric. They run the
// student's GLSL, so in a starter tree they fail on its stubs: the wrapper passes the stub a
// pixel reached out through alpha, and the test reports it as "not implemented".
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/not_implemented.h"
#include "gl/compute_program.h"
#include "gl/gl_context.h"
#include "image/compare.h"
#include "render/accelerate.h"
#include "render/gpu_render.h"
#include "render/render.h"
#include "render/shadertoy_export.h"
#include "scene/scene_loader.h"
#include "testing/stage_test.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

// What Shadertoy puts before the Image tab's code (its uniforms), and a main of our own.
const char* const kShadertoyHead =
    "#version 300 es\n"
    "precision highp float;\nprecision highp int;\nprecision mediump sampler3D;\n"
    "uniform vec3 iResolution;\nuniform float iTime;\nuniform float iTimeDelta;\n"
    "uniform float iFrameRate;\nuniform int iFrame;\nuniform float iChannelTime[4];\n"
    "uniform vec3 iChannelResolution[4];\nuniform vec4 iMouse;\nuniform vec4 iDate;\n"
    "uniform float iSampleRate;\nuniform sampler2D iChannel0;\nuniform sampler2D iChannel1;\n"
    "uniform sampler2D iChannel2;\nuniform sampler2D iChannel3;\n";
const char* const kShadertoyTail =
    "\nout vec4 rt_frag_colour;\n"
    "void main() {\n"
    "    mainImage(rt_frag_colour, gl_FragCoord.xy);\n"
    "    // Not Shadertoy's: the stub this pixel reached, for the test to report.\n"
    "    rt_frag_colour.a = rt_first_stub >= 0 ? float(rt_first_stub) / 255.0 : 1.0;\n"
    "}\n";

Scene shadertoy_scene(const std::string& relative) {
    Scene scene = load_scene(::rt::testing::source_dir() / "stages" / relative);
    scene.image.height =
        std::max(1, int(std::lround(64.0 * scene.image.height / scene.image.width)));
    scene.image.width = 64;
    // Stage 06's meshes are too big to bake (kMaxShadertoyBytes): small meshes get a BVH instead.
    if (!scene.triangles.empty()) scene.accelerator = Accelerator::Bvh;
    build_acceleration(scene);
    return scene;
}

// glslangValidator's verdict on the wrapped export: "" when it compiles.
std::string glslang_errors(const std::string& wrapped) {
    const fs::path file =
        fs::temp_directory_path() / ("rt-shadertoy-" + std::to_string(getpid()) + ".frag");
    std::ofstream(file, std::ios::binary) << wrapped;
    const fs::path log = file.string() + ".log";
    const int status = std::system(
        ("glslangValidator '" + file.string() + "' > '" + log.string() + "' 2>&1").c_str());
    std::ifstream in(log);
    std::ostringstream text;
    text << in.rdbuf();
    fs::remove(file), fs::remove(log);
    return status == 0 ? "" : text.str() + "(lines of " + file.string() + ")";
}

// Reports each stub a pixel reached, once, as the compute path does (render/gpu_render.cpp).
void report_export_stubs(const ShadertoyExport& shader, const std::vector<std::uint8_t>& rgba) {
    static std::map<std::string, std::unique_ptr<std::atomic<bool>>> reported;
    for (std::size_t i = 3; i < rgba.size(); i += 4) {
        if (rgba[i] == 255 || rgba[i] >= shader.stubs.size()) continue;
        const ShaderStub& s = shader.stubs[rgba[i]];
        auto& once = reported[s.file + ":" + std::to_string(s.line)];
        if (!once) once = std::make_unique<std::atomic<bool>>(false);
        report_not_implemented(s.function.c_str(), s.file.c_str(), s.line, s.handout.c_str(),
                               *once);
    }
}

class Shadertoy : public ::rt::testing::StageTest,
                  public ::testing::WithParamInterface<std::string> {};

TEST_P(Shadertoy, ExportCompilesAndMatchesCpu) {
    const Scene scene = shadertoy_scene(GetParam());
    const ShadertoyExport shader = export_shadertoy(scene, scene.mode);
    const std::string wrapped = kShadertoyHead + shader.text + kShadertoyTail;
    if (std::system("glslangValidator --version > /dev/null 2>&1") == 0)
        EXPECT_EQ(glslang_errors(wrapped), "") << "glslangValidator rejects the export";
    else
        ADD_FAILURE() << "glslangValidator not installed (apt-get install glslang-tools)";

    std::string error;
    const std::unique_ptr<GlContext> context = GlContext::create(GlKind::Egl, error);
    ASSERT_TRUE(context) << error;
    const int width = scene.image.width, height = scene.image.height;
    std::vector<std::uint8_t> rgba;
    error = draw_fragment_shader(context->gl(), wrapped, width, height, rgba);
    ASSERT_EQ(error, "") << "the export does not draw";
    report_export_stubs(shader, rgba);

    Image8 gpu{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 3)};
    for (std::size_t i = 0; i < gpu.data.size(); ++i) gpu.data[i] = rgba[i / 3 * 4 + i % 3];
    CompareOptions compare;  // the conformance test's metric
    compare.tolerance = 2;
    compare.max_failing_percent = 0.5;
    const CompareResult r = compare_images(gpu, to_image8(render(scene, scene.mode)), compare);
    EXPECT_TRUE(r.passed) << GetParam()
                          << " exported for Shadertoy, against the CPU: " << r.summary();
}

std::string shadertoy_case(const ::testing::TestParamInfo<std::string>& info) {
    return fs::path(info.param).stem().string();
}

// One scene of each kind the export bakes: directions, normals, primitive ids, shadows, the ray
// tree, a mesh with its BVH. Stages 07-08's scenes all hold images too big to bake:
// Framework.GpuShader.ShadertoyExportRefuses checks the message.
INSTANTIATE_TEST_SUITE_P(Scenes, Shadertoy,
                         ::testing::Values("01-camera-rays/scenes/perspective_directions.json",
                                           "02-intersections/scenes/spheres_normals.json",
                                           "02-intersections/scenes/boxes_primitive_ids.json",
                                           "04-shadows/scenes/shadows.json",
                                           "05-recursion/scenes/refraction.json",
                                           "02-intersections/scenes/triangles_normals.json"),
                         shadertoy_case);

// The largest exports that still fit (120 boxes; a 160-triangle mesh and its BVH). Not graded
// (grading.json): llvmpipe takes about 14 s of CPU to compile each one's baked arrays, in every
// grading, where the scenes above already reach every line of the student's GLSL.
INSTANTIATE_TEST_SUITE_P(Ungraded, Shadertoy,
                         ::testing::Values("05-recursion/scenes/whitted.json",
                                           "02-intersections/scenes/mesh_normals.json"),
                         shadertoy_case);

}  // namespace
}  // namespace rt
