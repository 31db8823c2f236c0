// `rt`'s subcommands as the command line declares them: each one's arguments and the function
// that adds it, with its options and their help, to the CLI11 app (framework/apps/rt_main.cpp
// runs what was asked for).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/source_dir.h"
#include "image/compare.h"
#include "scene/scene.h"
#include "view/view.h"

namespace rt {

struct RenderArgs {
    std::string scene;
    std::string output;
    std::optional<RenderMode> mode;
    std::string mode_name;  // --mode, as typed
    int width = 0, height = 0, threads = 0;
    bool quiet = false;
    std::string debug_pixel, overlay_pixel;  // "X,Y"
    std::string debug_format = "text";
    std::optional<Accelerator> accelerator;       // overrides the scene's
    std::optional<TextureLookup> texture_filter;  // for every image texture
    double yaw_degrees = 0;        // turns the camera about its up axis (the grader's unseen views)
    std::optional<bool> shadows;   // on or off: overrides the scene's (the viewer's toggle)
    int max_depth = -1;            // >= 0: overrides the scene's
    std::vector<std::string> off;  // --off: kTermNames switched off (the viewer's toggles)
    std::optional<bool> fresnel;   // on or off: overrides the scene's
    int spp = 0;                   // > 0: overrides the scene's samples_per_pixel (stage 10)
    std::optional<std::uint64_t> seed;  // overrides the scene's seed (stage 10)
    bool gpu = false;        // stage 09: a compute shader renders it (render/gpu/gpu_render.h)
    std::string gl = "egl";  // the context --gpu uses: egl, osmesa or window
    bool uber = false;       // --gpu with every feature compiled in
};

// `rt render`: what to render and write; the overrides of what the scene file says; --gpu.
CLI::App* add_render_command(CLI::App& app, RenderArgs& render_args);
void add_render_overrides(CLI::App* render_cmd, RenderArgs& render_args);
void add_render_gpu_options(CLI::App* render_cmd, RenderArgs& render_args);

struct GalleryArgs {
    std::filesystem::path out = "gallery";
    std::filesystem::path source = source_dir();
    int threads = 0;
};
CLI::App* add_gallery_command(CLI::App& app, GalleryArgs& args);

struct CompareArgs {
    std::string actual, reference;
    int tolerance = 2;
    double max_failing_percent = CompareOptions{}.max_failing_percent;
    bool neighbourhood = false;
    int block = 0;
    // None of the four above given: the grader's thresholds for the reference image's scene.
    bool thresholds_given = false;
};
CLI::App* add_compare_command(CLI::App& app, CompareArgs& args);

// view/view.h declares ViewArgs whether or not the viewer is built (run_view is its only code).
CLI::App* add_view_command(CLI::App& app, view::ViewArgs& view_args);

struct GlInfoArgs {
    bool window = false;
    std::string kind = "egl";
};
CLI::App* add_gl_info_command(CLI::App& app, GlInfoArgs& args);

struct ExportArgs {
    std::string scene, mode;
    std::filesystem::path output;
};
CLI::App* add_export_command(CLI::App& app, ExportArgs& args);

// `rt export-web` (docs/viewer.md#lecture-demos-in-a-browser).
struct ExportWebArgs : ExportArgs {
    int width = 0, height = 0;
    bool no_reference = false;
};
CLI::App* add_export_web_command(CLI::App& app, ExportWebArgs& args);

struct FmtArgs {
    std::vector<std::string> files;
    bool check = false;
};
CLI::App* add_fmt_command(CLI::App& app, FmtArgs& args);

}  // namespace rt
