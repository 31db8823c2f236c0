// Stage 09, the shader machinery: a compile error names the student's file and line, a stub is
// reported once with its file and line and paints magenta, glslangValidator accepts every
// shader. These pass whatever the student's GLSL computes, so they are framework tests (label
// framework;gpu), not stage09 ones: a starter tree's stage09 tests must all fail on the stubs.
#include <gtest/gtest.h>

#include <unistd.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <regex>
#include <sstream>
#include <string>
#include <utility>

#include "core/not_implemented.h"
#include "gpu/gl/shader_source.h"
#include "gpu/shader_constants.h"
#include "release/release.h"
#include "render/accelerate.h"
#include "render/gpu/gpu_render.h"
#include "render/gpu/shadertoy_export.h"
#include "render/gpu/shadertoy_run.h"
#include "render/prepare.h"
#include "scene/scene_loader.h"
#include "student_copy.h"
#include "testing/skip.h"
#include "testing/stage_test.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

using namespace gpu_test;

PreparedScene small_scene(const std::string& relative) {
    return prepare_scene(load_scene(::rt::testing::source_dir() / "stages" / relative),
                         {.width = 32, .height = 24});
}

// A syntax error, an undeclared name and a type error each name the student's file and line first.
TEST(GpuShader, CompileErrorNamesTheStudentFileAndLine) {
    const std::pair<const char*, const char*> mistakes[] = {
        {"    float broken = ;", "syntax error"},
        {"    float broken = undeclared_thing;", "undeclared_thing"},
        {"    vec3 broken = 1.0 + ivec2(1);", "vec3"}};
    for (const auto& [code, says] : mistakes) {
        SCOPED_TRACE(code);
        StudentCopy copy("broken");
        const fs::path file = copy.dir() / "intersect.glsl";
        std::string text = read(file);
        // Break the first line of intersect_plane's body (the same line in a starter tree).
        const std::size_t at = text.find("{\n", text.find("bool intersect_plane(")) + 2;
        const int line = 1 + int(std::count(text.begin(), text.begin() + long(at), '\n'));
        write(file, text.insert(at, std::string(code) + "\n"));
        GpuRenderOptions options;
        options.student_dir = copy.dir();
        try {
            render_gpu(small_scene("02-intersections/scenes/spheres_normals.json"),
                       RenderMode::Normals, options);
            ADD_FAILURE() << "a shader with this line compiled";
        } catch (const GpuError& e) {
            const std::string message = e.what();
            const std::string where = display_path(file) + ":" + std::to_string(line) + ":";
            EXPECT_EQ(message.rfind(where, 0), 0u)
                << "expected the message to start with " << where << "\n"
                << message;
            EXPECT_NE(message.find("error"), std::string::npos) << message;
            EXPECT_NE(message.find(says), std::string::npos) << message;
        }
    }
}

TEST(GpuShader, MissingIncludeIsOneLine) {
    StudentCopy copy("include");
    fs::remove(copy.dir() / "bvh.glsl");
    GpuRenderOptions options;
    options.student_dir = copy.dir();
    try {
        render_gpu(small_scene("02-intersections/scenes/spheres_normals.json"), RenderMode::Normals,
                   options);
        FAIL() << "rendered without bvh.glsl";
    } catch (const GpuError& e) {
        EXPECT_NE(std::string(e.what()).find("shaders/trace.glsl:"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("\"bvh.glsl\" not found"), std::string::npos)
            << e.what();
    }
}

// The starter tree's GLSL (every solution stripped) compiles, paints magenta, and names each
// stub once: "not implemented: perspective_ray (.../camera.glsl:N); read ...#camera-rays".
// The released stubs come from the course tree's solution markers, or are the starter tree's own
// files while camera.glsl is still a stub; once a student has written it there are no stubs left
// to check here (the course tree checked the released ones), and the test says so and skips.
TEST(GpuShader, StubsCompileAndAreReportedOnce) {
    StudentCopy copy("stubs");
    for (const std::string& f : student_files())
        write(copy.dir() / f, strip_solutions(read(copy.dir() / f)));
    if (read(copy.dir() / "camera.glsl").find("RT_NOT_IMPLEMENTED") == std::string::npos)
        RT_SKIP_IN_STARTER_TREE()
            << "camera.glsl has no stub and no solution markers (you have written it): "
               "the released stubs were checked in the course tree; nothing is wrong";
    GpuRenderOptions options;
    options.student_dir = copy.dir();
    const PreparedScene scene = small_scene("05-recursion/scenes/whitted.json");
    const std::uint64_t before = stub_calls_total();
    ::testing::internal::CaptureStderr();
    const Image image = render_gpu(scene, RenderMode::Shaded, options);
    render_gpu(scene, RenderMode::Shaded, options);  // reported once, not twice
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_GT(stub_calls_total(), before);
    for (const Color& c : image.pixels) ASSERT_EQ(c, Color(1, 0, 1)) << "a stub pixel is magenta";
    const std::string camera = display_path(copy.dir() / "camera.glsl");
    const std::regex once("not implemented: perspective_ray \\(" + camera +
                          ":[0-9]+\\);\\s*read stages/09-gpu/README.md#camera-rays");
    EXPECT_TRUE(std::regex_search(err, once)) << err;
    EXPECT_EQ(err.find("perspective_ray"), err.rfind("perspective_ray")) << err;
}

// glslangValidator (the Khronos reference front end) accepts the assembled shader with every
// feature on and with none, with the solutions and with a starter tree's stubs: what Mesa
// accepts is not always portable GLSL, and most scenes compile only part of the stubs.
TEST(GpuShader, GlslangValidatorAcceptsEveryVariant) {
    if (std::system("glslangValidator --version > /dev/null 2>&1") != 0)
        RT_SKIP_IN_STARTER_TREE()
            << "glslangValidator not installed (apt-get install glslang-tools)";
    const fs::path root = ::rt::testing::source_dir();
    const std::string all =
        "#define HAS_SPHERES\n#define HAS_PLANES\n#define HAS_TRIANGLES\n#define HAS_BOXES\n"
        "#define HAS_VERTEX_NORMALS\n#define HAS_BVH\n#define HAS_SHADOWS\n#define HAS_REFLECTION\n"
        "#define MAX_LIGHTS 4\n#define MAX_DEPTH 5\n";
    const std::string maps =
        "#define HAS_VERTEX_UVS\n#define HAS_TEXTURES\n#define HAS_NORMAL_MAPS\n"
        "#define HAS_IMAGE_TEXTURES\n#define HAS_CHECKER_TEXTURES\n#define HAS_NOISE_TEXTURES\n";
    const std::string variants[] = {
        all, all + "#define HAS_REFRACTION\n#define HAS_DEBUG_PIXEL\n",
        all + maps + "#define HAS_ENVIRONMENT\n",
        "#define HAS_SPHERES\n#define HAS_CHECKER_TEXTURES\n#define HAS_TEXTURES\n"
        "#define MAX_LIGHTS 1\n#define MAX_DEPTH 0\n",
        "#define HAS_ENVIRONMENT\n#define MAX_LIGHTS 1\n#define MAX_DEPTH 2\n",
        "#define MAX_LIGHTS 1\n#define MAX_DEPTH 0\n",
        // Stage 10 (sampling.glsl): everything, as --uber with moving spheres compiles it ...
        all + maps +
            "#define HAS_REFRACTION\n#define HAS_ENVIRONMENT\n#define HAS_SAMPLING\n"
            "#define HAS_AREA_LIGHTS\n#define HAS_DEPTH_OF_FIELD\n#define HAS_GLOSSY\n"
            "#define HAS_OCCLUSION\n#define HAS_INDIRECT\n#define HAS_MOTION_BLUR\n"
            "#define MAX_SPHERES 8\n#define MAX_AREA_LIGHTS 64\n"
            "#define MAX_MOVING_SPHERES 64\n#define HAS_DEBUG_PIXEL\n",
        // ... and a few scenes' own: pixel samples only, soft shadows, indirect light, motion.
        "#define HAS_SPHERES\n#define HAS_SAMPLING\n#define MAX_LIGHTS 1\n#define MAX_DEPTH 0\n",
        "#define HAS_SPHERES\n#define HAS_PLANES\n#define HAS_BOXES\n#define HAS_SAMPLING\n"
        "#define HAS_AREA_LIGHTS\n#define MAX_AREA_LIGHTS 2\n#define MAX_LIGHTS 1\n"
        "#define MAX_DEPTH 0\n",
        "#define HAS_BOXES\n#define HAS_SAMPLING\n#define HAS_AREA_LIGHTS\n#define HAS_INDIRECT\n"
        "#define MAX_LIGHTS 1\n#define MAX_DEPTH 0\n#define MAX_AREA_LIGHTS 1\n",
        "#define HAS_SPHERES\n#define HAS_TRIANGLES\n#define HAS_SHADOWS\n#define HAS_SAMPLING\n"
        "#define HAS_MOTION_BLUR\n#define MAX_SPHERES 3\n#define HAS_DEPTH_OF_FIELD\n"
        "#define HAS_GLOSSY\n#define HAS_REFLECTION\n#define HAS_OCCLUSION\n#define MAX_LIGHTS 1\n"
        "#define MAX_DEPTH 3\n",
        // Stage 11 (bsdf.glsl, path.glsl): cornell_box's and veach_mis's (with a BVH) shaders.
        "#define HAS_SPHERES\n#define HAS_BOXES\n#define HAS_REFRACTION\n#define HAS_SAMPLING\n"
        "#define HAS_AREA_LIGHTS\n#define HAS_PATH_TRACING\n#define MAX_LIGHTS 1\n"
        "#define MAX_DEPTH 8\n#define MAX_AREA_LIGHTS 1\n",
        "#define HAS_TRIANGLES\n#define HAS_BOXES\n#define HAS_BVH\n#define HAS_SAMPLING\n"
        "#define HAS_AREA_LIGHTS\n#define HAS_PATH_TRACING\n#define MAX_LIGHTS 1\n"
        "#define MAX_DEPTH 3\n#define MAX_AREA_LIGHTS 5\n#define HAS_DEBUG_PIXEL\n"};
    StudentCopy stubs("glslang");
    for (const std::string& f : student_files())
        write(stubs.dir() / f, strip_solutions(read(stubs.dir() / f)));
    write(stubs.dir() / "sampling.glsl",
          strip_solutions(read(root / "stages/10-sampling/sampling.glsl")));
    for (const char* f : {"bsdf.glsl", "path.glsl"})
        write(stubs.dir() / f, strip_solutions(read(root / "stages/11-path-tracing" / f)));
    int n = 0;
    for (const fs::path& students : {root / "stages/09-gpu", stubs.dir()})
        for (const std::string& defines : variants) {
            // Stages 10 and 11's files: the solutions beside stage 09's solutions, the stubs
            // beside stubs.
            const bool stubbed = students == stubs.dir();
            const fs::path sampling = stubbed ? stubs.dir() : root / "stages/10-sampling";
            const fs::path path = stubbed ? stubs.dir() : root / "stages/11-path-tracing";
            const AssembledShader shader = assemble_trace(defines, students, sampling, path);
            ASSERT_EQ(shader.error, "");
            const fs::path file =
                fs::temp_directory_path() /
                ("rt-stage09-" + std::to_string(getpid()) + "-" + std::to_string(n++) + ".comp");
            write(file, shader.text);
            const fs::path log = file.string() + ".log";
            const int status = std::system(
                ("glslangValidator '" + file.string() + "' > '" + log.string() + "' 2>&1").c_str());
            EXPECT_EQ(status, 0) << students << ":\n" << map_compile_log(read(log), shader.files);
            fs::remove(file);
            fs::remove(log);
        }
}

// A starter tree's GLSL of stage 10 or 11 (`folder`: its optional GPU part, stripped as
// rt-grade release does) in a temporary folder, with stage 09's solutions, rendering `scene` at
// 32 x 24 with 2 samples. Returns the stub report (stderr); every pixel must be magenta. Renders
// nothing when a file has no stub left (a starter tree its student has finished).
struct StubbedRender {
    fs::path dir;  // where the stripped files were (removed)
    std::string err;
    bool written = false;  // no stub left to render: the student has written these files
};

// The skip of a finished starter tree (StubsCompileAndAreReportedOnce says why it is no fault).
constexpr const char* kWrittenSkip =
    "no stub and no solution markers (you have written these files): the released stubs were "
    "checked in the course tree; nothing is wrong";
StubbedRender render_stubbed(const std::string& folder, std::initializer_list<const char*> files,
                             const std::string& scene_file) {
    StubbedRender r;
    r.dir = fs::temp_directory_path() / ("rt-" + folder + "-stubs-" + std::to_string(getpid()));
    fs::remove_all(r.dir);
    fs::create_directories(r.dir);
    for (const char* f : files) {
        const std::string stripped =
            strip_solutions(read(::rt::testing::source_dir() / "stages" / folder / f));
        r.written = r.written || stripped.find("RT_NOT_IMPLEMENTED") == std::string::npos;
        write(r.dir / f, stripped);
    }
    if (r.written) {
        fs::remove_all(r.dir);
        return r;
    }
    GpuRenderOptions options;
    options.student_dir = ::rt::testing::source_dir() / "stages/09-gpu";
    (folder.starts_with("10-") ? options.sampling_dir : options.path_dir) = r.dir;
    PreparedScene scene = small_scene(folder + "/scenes/" + scene_file);
    scene.sampling.samples_per_pixel = 2;
    ::testing::internal::CaptureStderr();
    const Image image = render_gpu(scene, RenderMode::Shaded, options);
    r.err = ::testing::internal::GetCapturedStderr();
    fs::remove_all(r.dir);
    for (const Color& c : image.pixels) {
        EXPECT_EQ(c, Color(1, 0, 1)) << "a stub pixel is magenta";
        if (c != Color(1, 0, 1)) break;
    }
    return r;
}

// A starter tree's sampling.glsl (stage 10's optional GPU part) with stage 09's solutions: the
// stubs compile, a stage 10 scene's pixels are magenta, and the first stub it reaches is named
// with its file, line and handout section.
TEST(GpuShader, SamplingStubsAreReported) {
    const StubbedRender r = render_stubbed("10-sampling", {"sampling.glsl"}, "soft_shadows.json");
    if (r.written) RT_SKIP_IN_STARTER_TREE() << "sampling.glsl has " << kWrittenSkip;
    const std::regex named("not implemented: stratified_sample \\(" +
                           display_path(r.dir / "sampling.glsl") +
                           ":[0-9]+\\);\\s*read stages/10-sampling/README.md#1-pixel-samples-"
                           "and-filters");
    EXPECT_TRUE(std::regex_search(r.err, named)) << r.err;
}

// A starter tree's bsdf.glsl and path.glsl (stage 11's optional GPU part) with the solutions of
// stages 09 and 10: the stubs compile, a path-traced scene's pixels are magenta, and the stub it
// reaches first, path_radiance, is named with its file, line and handout section.
TEST(GpuShader, PathStubsAreReported) {
    const StubbedRender r =
        render_stubbed("11-path-tracing", {"bsdf.glsl", "path.glsl"}, "cornell_box.json");
    if (r.written) RT_SKIP_IN_STARTER_TREE() << "bsdf.glsl or path.glsl has " << kWrittenSkip;
    const std::regex named("not implemented: path_radiance \\(" +
                           display_path(r.dir / "path.glsl") +
                           ":[0-9]+\\);\\s*read stages/11-path-tracing/README.md#6-the-path-"
                           "tracer");
    EXPECT_TRUE(std::regex_search(r.err, named)) << r.err;
    EXPECT_NE(r.err.find("sample_bsdf"), std::string::npos) << "the other stubs are named too";
}

TEST(GpuShader, WhatTheGpuCannotDrawSaysSo) {
    PreparedScene scene = small_scene("07-textures/scenes/filtering.json");
    scene.texture_lookup = TextureLookup::Oiio;
    try {
        render_gpu(scene, RenderMode::Shaded);
        FAIL();
    } catch (const GpuError& e) {
        EXPECT_NE(std::string(e.what()).find("filtering.json: --texture-filter oiio"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("has no GPU port"), std::string::npos) << e.what();
    }
    // Stage 10's optional fog is CPU only.
    PreparedScene foggy = small_scene("10-sampling/scenes/fog.json");
    try {
        render_gpu(foggy, RenderMode::Shaded);
        FAIL();
    } catch (const GpuError& e) {
        EXPECT_NE(std::string(e.what()).find("fog.json: fog"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("has no GPU port"), std::string::npos) << e.what();
    }
}

// rt export-shadertoy refuses, in one line naming the scene, what it cannot bake.
// The first line of intersect_plane's body in `file` (the same line in a starter tree) becomes
// `code`; returns that line's number.
int insert_in_intersect_plane(const fs::path& file, const std::string& code) {
    std::string text = read(file);
    const std::size_t at = text.find("{\n", text.find("bool intersect_plane(")) + 2;
    write(file, text.insert(at, code + "\n"));
    return 1 + int(std::count(text.begin(), text.begin() + long(at), '\n'));
}

// A while loop that never ends is stopped by its guard (gpu/gl/shader_source.h) and reported with its
// file and line, as a stub is, instead of llvmpipe ending it silently with wrong values.
TEST(GpuShader, EndlessLoopIsStoppedAndNamed) {
    // In the first function every pixel calls, before its stub in a starter tree.
    StudentCopy copy("loop");
    const fs::path file = copy.dir() / "camera.glsl";
    std::string text = read(file);
    const std::size_t at = text.find("{\n", text.find("Ray perspective_ray(")) + 2;
    const int line = 2 + int(std::count(text.begin(), text.begin() + long(at), '\n'));
    write(file, text.insert(at, "    int spin = 1;\n    while (spin > 0) { spin = spin | 1; }\n"));
    GpuRenderOptions options;
    options.student_dir = copy.dir();
    const std::uint64_t before = stub_calls_total();
    ::testing::internal::CaptureStderr();
    render_gpu(small_scene("02-intersections/scenes/plane_depth.json"), RenderMode::Normals,
               options);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_GT(stub_calls_total(), before) << "an endless loop must fail the test that ran it";
    const std::string where = display_path(file) + ":" + std::to_string(line) + ": this loop ran " +
                              std::to_string(gpu::kLoopLimit) +
                              " times for one pixel and was stopped";
    EXPECT_NE(err.find(where), std::string::npos) << "expected " << where << " in\n" << err;
}

// The same in the BVH traversal, a loop inside the tracer's own loops, where llvmpipe's silent
// cut comes sooner (the guard must come sooner still).
TEST(GpuShader, EndlessBvhLoopIsStoppedAndNamed) {
    StudentCopy copy("bvh-loop");
    const fs::path file = copy.dir() / "bvh.glsl";
    std::string text = read(file);
    const std::string loop = "    while (top > 0) {\n";  // the nearest-hit query's
    const std::size_t at = text.find(loop);
    bool stubs = false;  // a live stub, not one commented between solution markers
    for (const std::string& f : student_files()) {
        std::istringstream lines(read(copy.dir() / f));
        for (std::string l; std::getline(lines, l);)
            stubs |= l.find("RT_NOT_IMPLEMENTED") != std::string::npos &&
                     l.find_first_not_of(' ') != l.find("//");
    }
    if (at == std::string::npos || stubs)
        RT_SKIP_IN_STARTER_TREE()
            << "this tree's GLSL has stubs before the BVH, or no `" << loop.substr(4, 16)
            << "` in bvh.glsl (a starter tree): the course tree runs this test";
    const int line = 1 + int(std::count(text.begin(), text.begin() + long(at), '\n'));
    text.insert(at + loop.size(), "        if (top > 0) continue;  // never pops\n");
    write(file, text);
    GpuRenderOptions options;
    options.student_dir = copy.dir();
    ::testing::internal::CaptureStderr();
    render_gpu(small_scene("06-bvh/scenes/large_icosphere.json"), RenderMode::Shaded, options);
    const std::string err = ::testing::internal::GetCapturedStderr();
    const std::string where = display_path(file) + ":" + std::to_string(line) + ": this loop ran";
    EXPECT_NE(err.find(where), std::string::npos) << "expected " << where << " in\n" << err;
}

// Shadertoy's GLSL ES takes `const` on a local only with a constant initialiser; the export keeps
// the student's line as written, also a const in the middle of one, and drops the qualifier
// with a #define.
TEST(GpuShader, ShadertoyExportKeepsLocalConstAsWritten) {
    StudentCopy copy("const");
    insert_in_intersect_plane(copy.dir() / "intersect.glsl",
                              "    float st_a = ray.origin.x; const float st_b = st_a;");
    const PreparedScene scene = small_scene("02-intersections/scenes/spheres_normals.json");
    const std::string text =
        export_shadertoy(scene, RenderMode::Normals, {.student_dir = copy.dir()}).text;
    EXPECT_NE(text.find("float st_a = ray.origin.x; const float st_b = st_a;"), std::string::npos);
    // GLSL ES's preprocessor drops the qualifier, before the shader's own code.
    EXPECT_NE(text.find("\n#define const  //"), std::string::npos);
}

// A compile error in a Shadertoy export names the student's file and line, not the line of a
// temporary file the student never sees (render/gpu/shadertoy_run.cpp).
TEST(GpuShader, ShadertoyExportErrorNamesTheStudentFileAndLine) {
    StudentCopy copy("export-error");
    const fs::path file = copy.dir() / "intersect.glsl";
    const int line = insert_in_intersect_plane(file, "    float broken = undeclared_thing;");
    setenv("RT_GPU_STUDENT_DIR", copy.dir().c_str(), 1);
    const PreparedScene scene = small_scene("02-intersections/scenes/spheres_normals.json");
    const ShadertoyRun run = run_shadertoy_export(scene, RenderMode::Normals);
    unsetenv("RT_GPU_STUDENT_DIR");
    if (run.compile_errors.starts_with("glslangValidator not installed"))
        RT_SKIP_IN_STARTER_TREE() << run.compile_errors;
    const std::string where = display_path(file) + ":" + std::to_string(line) + ":";
    EXPECT_NE(run.compile_errors.find(where), std::string::npos) << "expected " << where << " in\n"
                                                                 << run.compile_errors;
    EXPECT_EQ(run.compile_errors.find(".frag"), std::string::npos) << run.compile_errors;
    // Mesa writes "FILE:LINE(COLUMN): error: ...".
    EXPECT_NE(run.draw_error.find(display_path(file) + ":" + std::to_string(line) + "("),
              std::string::npos)
        << run.draw_error;
}

TEST(GpuShader, ShadertoyExportRefuses) {
    const PreparedScene sky = small_scene("08-environment/scenes/procedural_sky.json");
    try {
        export_shadertoy(sky, sky.mode);
        FAIL() << "exported a 256-wide sky";
    } catch (const GpuError& e) {
        EXPECT_NE(std::string(e.what()).find("procedural_sky.json: its images hold"),
                  std::string::npos)
            << e.what();
    }
    const PreparedScene depth = small_scene("02-intersections/scenes/plane_depth.json");
    try {
        export_shadertoy(depth, RenderMode::Depth);
        FAIL() << "exported the depth view";
    } catch (const GpuError& e) {
        EXPECT_NE(std::string(e.what()).find("plane_depth.json: mode \"depth\""), std::string::npos)
            << e.what();
    }
}

// A starter tree's export (every stub in) is still GLSL ES 3.00 that Shadertoy compiles.
TEST(GpuShader, ShadertoyExportOfStubsCompiles) {
    if (std::system("glslangValidator --version > /dev/null 2>&1") != 0)
        RT_SKIP_IN_STARTER_TREE()
            << "glslangValidator not installed (apt-get install glslang-tools)";
    StudentCopy stubs("shadertoy");
    for (const std::string& f : student_files())
        write(stubs.dir() / f, strip_solutions(read(stubs.dir() / f)));
    const PreparedScene scene = small_scene("05-recursion/scenes/whitted.json");
    const std::string text =
        "#version 300 es\nprecision highp float;\nprecision highp int;\n"
        "uniform vec3 iResolution;\n" +
        export_shadertoy(scene, scene.mode, {.student_dir = stubs.dir()}).text +
        "out vec4 colour;\nvoid main() { mainImage(colour, gl_FragCoord.xy); }\n";
    const fs::path file =
        fs::temp_directory_path() / ("rt-stage09-toy-" + std::to_string(getpid()) + ".frag");
    write(file, text);
    const fs::path log = file.string() + ".log";
    const int status = std::system(
        ("glslangValidator '" + file.string() + "' > '" + log.string() + "' 2>&1").c_str());
    EXPECT_EQ(status, 0) << read(log);
    fs::remove(file);
    fs::remove(log);
}

}  // namespace
}  // namespace rt
