#include "apps/rt_commands.h"

#include <iterator>

#include "render/prepare.h"

namespace rt {

// `rt render`'s options: what to render and write.
CLI::App* add_render_command(CLI::App& app, RenderArgs& render_args) {
    auto* render_cmd = app.add_subcommand("render", "render one scene file to an image");
    render_cmd->add_option("scene", render_args.scene, "scene file (.json)")->required();
    render_cmd->add_option("-o,--output", render_args.output, "output image (.png or .exr)");
    render_cmd->add_option("--debug-pixel", render_args.debug_pixel,
                           "print the ray tree of pixel X,Y (shaded mode; -o optional); with --gpu "
                           "what the shader computed there, and each rt_debug(value)");
    render_cmd->add_option("--debug-format", render_args.debug_format, "text (default) or json")
        ->check(CLI::IsMember({"text", "json"}));
    render_cmd->add_option("--overlay-pixel", render_args.overlay_pixel,
                           "draw the ray tree of pixel X,Y onto the image: camera red, shadow "
                           "magenta, reflection blue, refraction yellow");
    render_cmd->add_option("--mode", render_args.mode_name, "override the scene's mode")
        ->check(CLI::IsMember(render_mode_names()));
    return render_cmd;
}

// `rt render`'s overrides of what the scene file says (the viewer's toggles among them).
namespace {

// A check that takes one of `names` and gives its value: the option's type, not its text.
template <typename T>
CLI::Validator one_of(const std::vector<std::pair<std::string, T>>& names) {
    std::string list;
    for (const auto& [name, value] : names) list += (list.empty() ? "" : "|") + name;
    auto check = [names, list](std::string& input) -> std::string {
        for (const auto& [name, value] : names)
            if (input == name) {
                input = std::to_string(int(value));
                return "";
            }
        return "\"" + input + "\" is not one of " + list;
    };
    return CLI::Validator(check, list, "one of");
}

const std::vector<std::pair<std::string, bool>> kOnOff = {{"on", true}, {"off", false}};

std::vector<std::pair<std::string, TextureLookup>> texture_lookups() {
    std::vector<std::pair<std::string, TextureLookup>> names;
    for (const std::string& name : texture_lookup_names())
        names.emplace_back(name, *parse_texture_lookup(name));
    return names;
}

}  // namespace

void add_render_overrides(CLI::App* render_cmd, RenderArgs& render_args) {
    render_cmd
        ->add_option("--accelerator", render_args.accelerator,
                     "override the scene's accelerator: none (stage 02's loop) or bvh (stage 06)")
        ->transform(one_of<Accelerator>({{"none", Accelerator::None}, {"bvh", Accelerator::Bvh}}));
    render_cmd
        ->add_option("--texture-filter", render_args.texture_filter,
                     "filter every image texture nearest or bilinear (stage 07), whatever the "
                     "scene says (scene: each as the scene says); or oiio (OpenImageIO's "
                     "TextureSystem, mip-mapped, trilinear) "
                     "or oiio-aniso (anisotropic): footprints from camera-ray differentials, "
                     "none (bilinear) for reflected and refracted rays")
        ->transform(one_of(texture_lookups()));
    render_cmd->add_option("--width", render_args.width, "override the image width")
        ->check(CLI::Range(1, 16384));
    render_cmd->add_option("--height", render_args.height, "override the image height")
        ->check(CLI::Range(1, 16384));
    render_cmd->add_option("--threads", render_args.threads, "threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    render_cmd
        ->add_option("--yaw", render_args.yaw_degrees,
                     "turn the camera about its up axis by DEGREES (positive: to the right)")
        ->check(CLI::Range(-45.0, 45.0));
    render_cmd->add_flag("-q,--quiet", render_args.quiet, "no progress bar or summary");
    render_cmd->add_option("--shadows", render_args.shadows, "override the scene's shadows")
        ->transform(one_of(kOnOff));
    render_cmd
        ->add_option("--off", render_args.off,
                     "switch terms off as rt view's panel does (a comma list): ambient, diffuse, "
                     "specular, emissive, reflection or refraction zeroes that coefficient in "
                     "every material; environment drops the environment")
        ->delimiter(',')
        ->check(
            CLI::IsMember(std::vector<std::string>(std::begin(kTermNames), std::end(kTermNames))));
    render_cmd->add_option("--fresnel", render_args.fresnel, "override the scene's fresnel")
        ->transform(one_of(kOnOff));
    render_cmd
        ->add_option("--max-depth", render_args.max_depth,
                     "override the scene's bounces of reflected/refracted rays")
        ->check(CLI::Range(0, kMaxDepthLimit));
    render_cmd
        ->add_option("--spp", render_args.spp,
                     "override the scene's samples per pixel (stage 10: any value > 1 samples)")
        ->check(CLI::Range(1, 65536));
    render_cmd
        ->add_option("--seed", render_args.seed,
                     "override the scene's random seed (stage 10; 0 to 2^53)")
        ->check(CLI::Range(std::uint64_t(0), std::uint64_t(1) << 53));
}

// `rt render --gpu` and its context (stage 09).
void add_render_gpu_options(CLI::App* render_cmd, RenderArgs& render_args) {
    render_cmd->add_flag("--gpu", render_args.gpu,
                         "render with the compute shader of stage 09 (shaders/trace.comp and "
                         "stages/09-gpu/*.glsl; a stage 10 scene also "
                         "stages/10-sampling/sampling.glsl, a stage 11 one also "
                         "stages/11-path-tracing/bsdf.glsl and path.glsl)");
    render_cmd->add_option("--gl", render_args.gl, "the OpenGL context of --gpu (default: egl)")
        ->check(CLI::IsMember({"egl", "osmesa", "window"}));
    render_cmd->add_flag("--uber", render_args.uber,
                         "with --gpu: compile every feature into the shader instead of only what "
                         "the scene uses (rt-bench gpu compares the two)");
}

CLI::App* add_gallery_command(CLI::App& app, GalleryArgs& args) {
    auto* gallery_cmd = app.add_subcommand("gallery", "render every scene of every stage");
    gallery_cmd->add_option("--out", args.out, "output folder (default: ./gallery)");
    gallery_cmd->add_option("--source", args.source, "source tree holding stages/")
        ->check(CLI::ExistingDirectory);
    gallery_cmd->add_option("--threads", args.threads, "threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    return gallery_cmd;
}

CLI::App* add_compare_command(CLI::App& app, CompareArgs& args) {
    auto* compare_cmd = app.add_subcommand(
        "compare",
        "compare two images by the grader's metric (framework/image/compare.h); without "
        "threshold options, with the grader's thresholds for REFERENCE's scene when it is a "
        "graded reference_images/NN-stage/SCENE.png");
    compare_cmd->add_option("actual", args.actual, "image (.png or .exr)")->required();
    compare_cmd->add_option("reference", args.reference, "reference image")->required();
    compare_cmd->add_option("--tolerance", args.tolerance, "8-bit steps a channel may differ")
        ->check(CLI::Range(0, 255));
    compare_cmd
        ->add_option("--max-failing-percent", args.max_failing_percent,
                     "share of pixels allowed past the tolerance (stage 09's conformance: 0.5)")
        ->check(CLI::Range(0.0, 100.0));
    compare_cmd->add_flag("--neighbourhood", args.neighbourhood,
                          "forgive anti-aliased edges (3x3), as the graders do");
    compare_cmd
        ->add_option("--block", args.block,
                     "compare the means of NxN blocks (Monte Carlo images, stage 10)")
        ->check(CLI::Range(0, 256));
    compare_cmd->final_callback([compare_cmd, &args] {
        for (const char* name :
             {"--tolerance", "--max-failing-percent", "--neighbourhood", "--block"})
            args.thresholds_given = args.thresholds_given || compare_cmd->count(name) > 0;
    });
    return compare_cmd;
}

CLI::App* add_view_command(CLI::App& app, view::ViewArgs& view_args) {
    auto* view_cmd = app.add_subcommand(
        "view",
        "the lecture-demo viewer: progressive render, toggles, ray trees (needs a display)");
    view_cmd->add_option("scene", view_args.scene, "scene file (.json)")->required();
    view_cmd->add_option("--script", view_args.script,
                         "replay a session and exit (commands: framework/view/view_script.h)");
    view_cmd->add_option("--out", view_args.out, "folder for screenshots (default: .)");
    view_cmd->add_option("--threads", view_args.threads, "render threads (default: all cores)")
        ->check(CLI::Range(1, 1024));
    view_cmd->add_option("--width", view_args.width, "override the image width")
        ->check(CLI::Range(1, 4096));
    view_cmd->add_option("--height", view_args.height, "override the image height")
        ->check(CLI::Range(1, 4096));
    return view_cmd;
}

CLI::App* add_gl_info_command(CLI::App& app, GlInfoArgs& args) {
    auto* gl_cmd = app.add_subcommand("gl-info", "create an OpenGL context and describe it");
    gl_cmd
        ->add_option("--gl", args.kind,
                     "the context `rt render --gpu` would use: egl (headless, the default), "
                     "osmesa (headless) or window (GLFW, needs a display)")
        ->check(CLI::IsMember({"egl", "osmesa", "window"}));
    gl_cmd->add_flag("--window", args.window, "the same as --gl window");
    return gl_cmd;
}

namespace {

// The options both exports share: the scene, the file written (`what`) and the modes they draw
// (a Shadertoy pixel cannot know the image's range that depth and bvh_visits scale by; a page can).
void add_export_options(CLI::App* cmd, ExportArgs& args, const std::string& what,
                        bool ranged_modes) {
    cmd->add_option("scene", args.scene, "scene file (.json)")->required();
    cmd->add_option("-o,--output", args.output, "the " + what + " to write")->required();
    std::vector<std::string> modes = {"directions", "normals", "primitive", "shaded"};
    if (ranged_modes) modes.insert(modes.end(), {"depth", "bvh_visits"});
    cmd->add_option("--mode", args.mode, "override the scene's mode")->check(CLI::IsMember(modes));
}

}  // namespace

CLI::App* add_export_command(CLI::App& app, ExportArgs& args) {
    auto* export_cmd = app.add_subcommand(
        "export-shadertoy",
        "write the scene and stages/09-gpu's GLSL as one self-contained Shadertoy shader "
        "(stages/09-gpu/README.md#publish-on-shadertoy)");
    add_export_options(export_cmd, args, "shader (.glsl)", false);
    return export_cmd;
}

CLI::App* add_export_web_command(CLI::App& app, ExportWebArgs& args) {
    auto* web = app.add_subcommand(
        "export-web",
        "write one self-contained HTML page that renders the scene in WebGL2 with stages/09-gpu's "
        "GLSL (docs/viewer.md#lecture-demos-in-a-browser)");
    add_export_options(web, args, "page (.html)", true);
    web->add_option("--width", args.width, "override the image width")->check(CLI::Range(1, 4096));
    web->add_option("--height", args.height, "override the image height")
        ->check(CLI::Range(1, 4096));
    web->add_flag("--no-reference", args.no_reference,
                  "leave out the CPU render the page shows beside the live canvas");
    return web;
}

CLI::App* add_fmt_command(CLI::App& app, FmtArgs& args) {
    auto* fmt_cmd = app.add_subcommand(
        "fmt", "rewrite scene files in canonical form (docs/scene-format.md#canonical-form)");
    fmt_cmd->add_option("scenes", args.files, "scene files (.json)")->required();
    fmt_cmd->add_flag("--check", args.check,
                      "change nothing; name each file not in canonical form and exit 1 if any");
    return fmt_cmd;
}

}  // namespace rt
