// rt: the renderer students and lecturers run. It links the stage code (the student files).
//   rt render SCENE.json -o OUT.png [--mode M] [--width W --height H] [--threads N]
//   rt render SCENE.json --debug-pixel X,Y [--debug-format text|json]   the ray tree of a pixel
//   rt render SCENE.json --gpu --debug-pixel X,Y     what stage 09's shader computed there
//   rt render SCENE.json -o OUT.png --overlay-pixel X,Y                 ... drawn onto the image
//   rt render SCENE.json -o OUT.png --shadows off --max-depth 1         the viewer's toggles
//   rt gallery [--out DIR]       every scene of every stage, in its own mode, and DIR/index.html
//   rt view SCENE.json [--script FILE --out DIR]   the lecture-demo viewer (framework/view/)
//   rt compare ACTUAL.png REFERENCE.png            the grader's image metric, one line
//   rt info SCENE.json           what the scene contains and which features the renderer uses
//   rt gl-info [--window]        the OpenGL context the GPU stage will use
//   rt export-shadertoy SCENE.json -o scene.glsl   stage 09's GLSL and the scene for Shadertoy
//   rt export-web SCENE.json -o demo.html          the same in one WebGL2 page
//   rt fmt [--check] SCENE.json...   rewrite scene files in canonical form (--check: only report)
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/bvh_cost.h"
#include "apps/cli_parse.h"
#include "apps/gallery_page.h"
#include "apps/rt_commands.h"
#include "core/diagnostics.h"
#include "core/seconds_since.h"
#include "core/source_dir.h"
#include "core/text_file.h"
#include "course/manifest.h"
#include "image/compare.h"
#include "image/image.h"
#include "render/accelerate.h"
#include "render/gpu/gpu_debug_pixel.h"
#include "render/gpu/gpu_render.h"
#include "render/gpu/shadertoy_export.h"
#include "render/gpu/web_export.h"
#include "render/prepare.h"
#include "render/progress.h"
#include "render/ray_tree.h"
#include "render/render.h"
#include "scene/scene_format.h"
#include "scene/scene_loader.h"

namespace fs = std::filesystem;
using namespace rt;

namespace {

// "X,Y" inside the image, or a usage error.
std::pair<int, int> parse_pixel(const std::string& text, const char* option,
                                const PreparedScene& scene) {
    int x = -1, y = -1;
    char rest = 0;
    if (std::sscanf(text.c_str(), "%d,%d%c", &x, &y, &rest) != 2 || x < 0 || y < 0 ||
        x >= scene.image.width || y >= scene.image.height)
        throw std::runtime_error(std::string("rt: error: ") + option + " \"" + text +
                                 "\" must be X,Y with 0 <= X < " +
                                 std::to_string(scene.image.width) + " and 0 <= Y < " +
                                 std::to_string(scene.image.height));
    return {x, y};
}

// --debug-pixel: the CPU's ray tree (text or JSON), or with --gpu what the shader computed.
std::string debug_pixel_text(const RenderArgs& args, const PreparedScene& scene, RenderMode mode,
                             const GpuRenderOptions& gpu, int x, int y) {
    if (args.gpu) {
        if (args.debug_format == "json")
            throw std::runtime_error(
                "rt: error: --debug-format json is the CPU ray tree's; with --gpu the values "
                "print as text (drop --debug-format)");
        return gpu_pixel_text(scene, debug_pixel_gpu(scene, mode, x, y, gpu));
    }
    const PixelTree tree = debug_pixel(scene, x, y);
    return args.debug_format == "json" ? ray_tree_json(scene, tree) + "\n"
                                       : ray_tree_text(scene, tree);
}

// The options that change the scene (CLI11 has checked each value against its list).
SceneOverrides overrides_of(const RenderArgs& args) {
    SceneOverrides o;
    o.width = args.width;
    o.height = args.height;
    o.yaw_degrees = args.yaw_degrees;
    o.accelerator = args.accelerator;
    o.texture_lookup = args.texture_filter;
    o.shadows = args.shadows;
    if (args.max_depth >= 0) o.max_depth = args.max_depth;
    for (const std::string& term : args.off) *term_switch(o.terms, term) = false;
    o.fresnel = args.fresnel;
    if (args.spp > 0) o.samples_per_pixel = args.spp;
    o.seed = args.seed;
    return o;
}

int run_render(const RenderArgs& args) {
    if (args.uber && !args.gpu)
        throw std::runtime_error("rt: error: --uber chooses the GPU shader; add --gpu");
    if (!args.output.empty()) check_image_output(args.output);
    AccelerationReport accel;
    const PreparedScene scene =
        prepare_scene(load_scene(args.scene), overrides_of(args), {}, &accel);
    const RenderMode mode = args.mode.value_or(scene.mode);
    if (accel.built && !args.quiet)
        std::printf("BVH: %zu primitives, %zu nodes, depth %d, built in %.1f ms\n",
                    accel.primitives, accel.nodes, accel.depth, accel.build_ms);
    GpuRenderOptions gpu;
    gpu.context = *parse_gl_kind(args.gl);
    gpu.log = args.quiet ? nullptr : &std::cout;
    gpu.uber = args.uber;
    if (!args.debug_pixel.empty()) {
        const auto [x, y] = parse_pixel(args.debug_pixel, "--debug-pixel", scene);
        std::fputs(debug_pixel_text(args, scene, mode, gpu, x, y).c_str(), stdout);
        if (args.output.empty()) return 0;
    }
    if (args.output.empty())
        throw std::runtime_error("rt: error: --output is required (unless --debug-pixel is given)");
    std::optional<std::pair<int, int>> overlay;
    if (!args.overlay_pixel.empty())
        overlay = parse_pixel(args.overlay_pixel, "--overlay-pixel", scene);
    const auto start = std::chrono::steady_clock::now();
    RenderOptions options;
    options.threads = args.threads;
    options.show_progress = !args.quiet && stdout_is_terminal();
    Image image = args.gpu ? render_gpu(scene, mode, gpu) : render(scene, mode, options);
    const NonFinitePixels non_finite = mark_non_finite_pixels(image);
    if (non_finite.count > 0) std::fprintf(stderr, "%s\n", non_finite.describe(args.scene).c_str());
    if (overlay) draw_ray_tree(scene, debug_pixel(scene, overlay->first, overlay->second), image);
    write_image(image, args.output);
    const std::string how = args.gpu
                                ? "GPU (" + args.gl + (args.uber ? ", uber" : "") + ")"
                                : std::to_string(resolve_thread_count(args.threads)) + " threads";
    if (!args.quiet)
        std::printf("%s: %dx%d, %s, %s, %.2f s -> %s\n", args.scene.c_str(), scene.image.width,
                    scene.image.height, to_string(mode), how.c_str(), seconds_since(start),
                    args.output.c_str());
    return 0;
}

// The thresholds the grader uses for a reference image reference_images/NN-stage/SCENE.png:
// the scene's own in stages/NN-stage/grading.json, or the stage's defaults. Nothing when the
// image is not there or the stage is not graded; `stage` names the grading.json used.
std::optional<ImageThresholds> graded_thresholds(const fs::path& reference, std::string& stage) {
    const fs::path folder = fs::weakly_canonical(reference).parent_path();
    if (folder.parent_path() != fs::weakly_canonical(source_dir() / "reference_images"))
        return std::nullopt;
    const fs::path stage_dir = source_dir() / "stages" / folder.filename();
    if (!fs::exists(stage_dir / "grading.json")) return std::nullopt;
    const StageSpec spec = load_stage_spec(source_dir(), stage_dir);
    stage = "stages/" + folder.filename().string() + "/grading.json";
    return spec.thresholds_of(reference.stem().string());
}

// The grader's metric on two image files: one line, exit 0 when they match. Without threshold
// options a graded reference image is compared as the grader compares it (full points or not).
int run_compare(const CompareArgs& args) {
    CompareOptions options;
    options.tolerance = args.tolerance;
    options.max_failing_percent = args.max_failing_percent;
    options.neighbourhood = args.neighbourhood;
    options.block = args.block;
    std::string stage;
    std::optional<ImageThresholds> graded;
    if (!args.thresholds_given) graded = graded_thresholds(args.reference, stage);
    if (graded) options = graded->compare_options();
    const CompareResult result =
        compare_images(read_image8(args.actual), read_image8(args.reference), options);
    std::printf("%s vs %s: %s\n", args.actual.c_str(), args.reference.c_str(),
                result.summary().c_str());
    if (graded)
        std::printf(
            "  (the grader's thresholds, from %s: full points up to %.2f%% of the pixels "
            "failing, none from %.2f%%)\n",
            stage.c_str(), graded->pass_percent, graded->fail_percent);
    return result.passed ? 0 : 1;
}

int run_info(const std::string& file) {
    AccelerationReport accel;
    const PreparedScene scene = prepare_scene(load_scene(file), {}, {}, &accel);
    std::printf(
        "%s\n  image %dx%d, mode %s\n  %zu spheres, %zu planes, %zu triangles (%zu "
        "vertices), %zu boxes\n  %zu materials, %zu lights\n  features: %s\n",
        file.c_str(), scene.image.width, scene.image.height, to_string(scene.mode),
        scene.spheres.size(), scene.planes.size(), scene.triangles.size(), scene.vertices.size(),
        scene.boxes.size(), scene.materials.size(), scene.lights.size(),
        scene.features.describe().c_str());
    if (!scene.instances.empty()) {
        std::size_t triangles = 0;
        for (const auto& object : scene.objects) triangles += object->triangles.size();
        std::printf("  %zu instances of %zu objects (%zu triangles in the objects)\n",
                    scene.instances.size(), scene.objects.size(), triangles);
    }
    if (scene.features.sampled())  // stage 10
        std::printf(
            "  sampling: %d samples per pixel, seed %llu, %zu area lights, %zu moving spheres\n",
            scene.sampling.samples_per_pixel, (unsigned long long)scene.sampling.seed,
            scene.area_lights.size(), scene.moving_spheres.size());
    if (accel.built)
        std::printf("  BVH: %zu primitives, %zu nodes of %zu bytes, depth %d, built in %.1f ms\n",
                    accel.primitives, accel.nodes, sizeof(BvhNode), accel.depth, accel.build_ms);
    else if (accel.requested)
        std::printf("  BVH: requested but not built (%s)\n", accel.problem.c_str());
    return 0;
}

// `rt export-shadertoy`: the scene and stages/09-gpu's GLSL as one Shadertoy fragment shader.
int run_export_shadertoy(const std::string& file, const fs::path& output,
                         std::optional<RenderMode> mode) {
    const PreparedScene scene = prepare_scene(load_scene(file));
    const ShadertoyExport shader = export_shadertoy(scene, mode.value_or(scene.mode));
    std::ofstream out(output, std::ios::binary);
    if (!(out << shader.text))
        throw std::runtime_error("rt: error: " + output.string() +
                                 ": cannot write the shader; check that its folder exists");
    std::printf("%s: %zu KB; paste it into Shadertoy's Image tab\n", output.string().c_str(),
                (shader.text.size() + 1023) / 1024);
    return 0;
}

// `rt export-web`: one self-contained WebGL2 page, the CPU render inside to compare with.
int run_export_web(const ExportWebArgs& args) {
    const PreparedScene scene =
        prepare_scene(load_scene(args.scene), {.width = args.width, .height = args.height});
    const RenderMode mode = args.mode.empty() ? scene.mode : *parse_render_mode(args.mode);
    export_shadertoy(scene, mode, {.web_page = true});  // refusals before the CPU render
    const Image8 reference = args.no_reference ? Image8{} : to_image8(render(scene, mode));
    const std::string page = export_web_page(scene, mode, reference);
    std::ofstream out(args.output, std::ios::binary);
    if (!(out << page))
        throw std::runtime_error("rt: error: " + args.output.string() +
                                 ": cannot write the page; check that its folder exists");
    std::printf("%s: %zu KB; open it in a browser with WebGL2\n", args.output.string().c_str(),
                (page.size() + 1023) / 1024);
    return 0;
}

// `rt gl-info --gl KIND`: the context the GPU stage would use, with the limits it relies on.
int run_gl_context_info(const std::string& kind) {
    std::string error;
    const auto context = GlContext::create(*parse_gl_kind(kind), error);
    if (!context) {
        std::fprintf(stderr, "rt: error: %s\n", error.c_str());
        return 1;
    }
    std::printf("%s\n", context->describe().c_str());
    return 0;
}

// Writes `text` over `file` atomically (core/text_file.h), so a failure never leaves half a scene
// behind. A symbolic link keeps pointing at the rewritten file, which keeps its permissions.
void replace_file(const fs::path& file, const std::string& text) {
    try {
        write_text_atomically(file, text, {.follow_link = true, .keep_permissions = true});
    } catch (const AtomicWriteError& e) {
        throw std::runtime_error(
            file.string() + ":1:1: error: " +
            (e.renaming ? "cannot replace the file (" + e.reason + ")"
                        : std::string("cannot write the file; check its folder's permissions")));
    }
}

// rt fmt: every file is read and checked by the scene loader, then compared with (or replaced
// by) its canonical form. A bad file is reported in the loader's one line and the others are
// still done; the exit code is 1 if any file was bad or, with --check, not canonical.
int run_fmt(const std::vector<std::string>& files, bool check) {
    int status = 0;
    for (const std::string& file : files) {
        try {
            const std::string text = read_scene_text(file);
            const std::string canonical =
                canonical_scene_text(text, file, fs::path(file).parent_path());
            if (text == canonical) continue;
            if (check) {
                std::fprintf(stderr, "%s: not in canonical form; run rt fmt %s\n", file.c_str(),
                             file.c_str());
                status = 1;
            } else {
                replace_file(file, canonical);
                std::printf("%s: rewritten in canonical form\n", file.c_str());
            }
        } catch (const std::exception& e) {
            std::fflush(stdout);
            std::fprintf(stderr, "%s\n", error_line("rt", e.what()).c_str());
            status = 1;
        }
    }
    return status;
}

// `rt view` (its arguments are declared whether or not the viewer is built).

int run_view_command(const view::ViewArgs& args) {
#ifdef RT_HAVE_VIEW
    return view::run_view(args);
#else
    (void)args;
    throw std::runtime_error(
        "rt: error: this rt was built without the viewer; install libimgui-dev "
        "(scripts/install-deps.sh) and reconfigure with -DRT_VIEWER=ON");
#endif
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rt: the course ray tracer (docs/conventions.md, docs/scene-format.md)"};
    app.require_subcommand(1);
    RenderArgs render_args;
    CLI::App* render_cmd = add_render_command(app, render_args);
    add_render_overrides(render_cmd, render_args);
    add_render_gpu_options(render_cmd, render_args);
    GalleryArgs gallery;
    CLI::App* gallery_cmd = add_gallery_command(app, gallery);
    CompareArgs compare;
    CLI::App* compare_cmd = add_compare_command(app, compare);
    view::ViewArgs view_args;
    CLI::App* view_cmd = add_view_command(app, view_args);
    std::string info_scene;
    auto* info_cmd = app.add_subcommand("info", "describe a scene file");
    info_cmd->add_option("scene", info_scene, "scene file (.json)")->required();
    GlInfoArgs gl;
    CLI::App* gl_cmd = add_gl_info_command(app, gl);
    ExportArgs exporting;
    CLI::App* export_cmd = add_export_command(app, exporting);
    ExportWebArgs web;
    CLI::App* web_cmd = add_export_web_command(app, web);
    FmtArgs fmt;
    CLI::App* fmt_cmd = add_fmt_command(app, fmt);
    // The leaderboard's traversal cost (apps/bvh_cost.h), run by rt-grade.
    std::string tree_scene, tree_file;
    auto* dump_cmd =
        app.add_subcommand("bvh-dump", "write the BVH a scene's build makes (rt-grade)");
    dump_cmd->add_option("scene", tree_scene, "scene file (.json)")->required();
    dump_cmd->add_option("-o,--output", tree_file, "the tree file to write")->required();
    auto* cost_cmd = app.add_subcommand(
        "bvh-cost", "node visits and primitive tests per primary ray through a BVH (rt-grade)");
    cost_cmd->add_option("scene", tree_scene, "scene file (.json)")->required();
    cost_cmd->add_option("--tree", tree_file, "a tree from rt bvh-dump (default: this rt's own)");
    int cost_width = 0;
    int cost_height = 0;
    cost_cmd->add_option("--width", cost_width, "rays across (default: the scene's image width)")
        ->check(CLI::Range(1, 4096));
    cost_cmd->add_option("--height", cost_height, "rays down (default: the scene's image height)")
        ->check(CLI::Range(1, 4096));
    if (const auto stop =
            parse_command_line(app, argc, argv, "rt", "`rt --help` or `rt render --help`"))
        return *stop;

    try {
        if (*render_cmd) {
            if (!render_args.mode_name.empty())
                render_args.mode = *parse_render_mode(render_args.mode_name);
            return run_render(render_args);
        }
        if (*gallery_cmd) return run_gallery(gallery.source, gallery.out, gallery.threads);
        if (*info_cmd) return run_info(info_scene);
        if (*compare_cmd) return run_compare(compare);
        if (*view_cmd) return run_view_command(view_args);
        if (*gl_cmd) return run_gl_context_info(gl.window ? "window" : gl.kind);
        if (*fmt_cmd) return run_fmt(fmt.files, fmt.check);
        if (*dump_cmd) return run_bvh_dump(tree_scene, tree_file);
        if (*cost_cmd) return run_bvh_cost(tree_scene, tree_file, cost_width, cost_height);
        if (*export_cmd)
            return run_export_shadertoy(
                exporting.scene, exporting.output,
                exporting.mode.empty() ? std::nullopt : parse_render_mode(exporting.mode));
        if (*web_cmd) return run_export_web(web);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", error_line("rt", e.what()).c_str());
        return 1;
    }
    return 0;
}
