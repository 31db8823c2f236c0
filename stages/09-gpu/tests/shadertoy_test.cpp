// Stage 09's export for Shadertoy (rt export-shadertoy, render/gpu/shadertoy_export.h): the shader
// compiles as Shadertoy compiles it (glslangValidator, GLSL ES 3.00, inside a wrapper declaring
// Shadertoy's uniforms and a main calling mainImage: render/gpu/shadertoy_run.h) and, drawn headless
// over a full-screen triangle, gives the CPU renderer's image under the conformance test's metric. They run the
// student's GLSL, so in a starter tree they fail on its stubs: the wrapper passes the stub a
// pixel reached out through alpha, and the test reports it as "not implemented".
#include <filesystem>
#include <string>
#include <vector>

#include "image/compare.h"
#include "render/accelerate.h"
#include "render/gpu/shadertoy_run.h"
#include "render/prepare.h"
#include "render/render.h"
#include "scene/scene_loader.h"
#include "testing/stage_test.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

PreparedScene shadertoy_scene(const std::string& relative) {
    Scene scene = load_scene(::rt::testing::source_dir() / "stages" / relative);
    const int height = std::max(1, int(std::lround(64.0 * scene.image.height / scene.image.width)));
    SceneOverrides small{.width = 64, .height = height};
    // Stage 06's meshes are too big to bake (kMaxShadertoyBytes): small meshes get a BVH instead.
    if (!scene.triangles.empty()) small.accelerator = Accelerator::Bvh;
    return prepare_scene(std::move(scene), small);
}

class Shadertoy : public ::rt::testing::StageTest,
                  public ::testing::WithParamInterface<std::string> {};

TEST_P(Shadertoy, ExportCompilesAndMatchesCpu) {
    const PreparedScene scene = shadertoy_scene(GetParam());
    const ShadertoyRun run = run_shadertoy_export(scene, scene.mode);
    EXPECT_EQ(run.compile_errors, "") << "glslangValidator rejects the export";
    ASSERT_EQ(run.draw_error, "") << "the export does not draw";
    CompareOptions compare;  // the conformance test's metric
    compare.tolerance = 2;
    compare.max_failing_percent = 0.5;
    const CompareResult r =
        compare_images(run.image, to_image8(render(scene, scene.mode)), compare);
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

// The largest exports that still fit (120 boxes; a 160-triangle mesh and its BVH), and the
// linked fill light (its lights carry their linking in float bits). Not graded (grading.json):
// llvmpipe takes about 14 s of CPU to compile each large one's baked arrays, in every grading,
// where the scenes above already reach every line of the student's GLSL.
INSTANTIATE_TEST_SUITE_P(Ungraded, Shadertoy,
                         ::testing::Values("05-recursion/scenes/whitted.json",
                                           "02-intersections/scenes/mesh_normals.json",
                                           "04-shadows/scenes/fill_light.json"),
                         shadertoy_case);

}  // namespace
}  // namespace rt
