#include "view/viewer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "camera/camera_moves.h"
#include "core/seconds_since.h"
#include "core/source_dir.h"
#include "render/accelerate.h"
#include "render/camera_ray.h"
#include "scene/scene_loader.h"

namespace rt::view {
namespace {

namespace fs = std::filesystem;

// How long wait-refined waits before the session fails (a stuck render must not hang CI).
constexpr double kRefineTimeoutSeconds = 300;

// stages/NN-name/scenes/X.json -> reference_images/NN-name/X.png, when that exists.
std::optional<Image8> find_reference(const fs::path& scene_file) {
    const fs::path stage = fs::absolute(scene_file).parent_path().parent_path();
    const fs::path file = source_dir() / "reference_images" / stage.filename() /
                          (scene_file.stem().string() + ".png");
    if (!fs::exists(file)) return std::nullopt;
    return read_image8(file);
}

}  // namespace

Viewer::Viewer(Scene loaded, const ViewArgs& args, std::vector<ScriptCommand> script)
    : source_(std::move(loaded)),
      scene_file_(args.scene),
      out_(args.out),
      script_file_(args.script),
      renderer_(args.threads),
      script_(std::move(script)) {
    settings = source_.initial();
    scene_ = source_.make(settings);
    up_ = settings.camera.v;
    initial_pivot_distance_ = pivot_distance_ = orbit_pivot_distance(scene_);
    reference_ = find_reference(args.scene);
    generation_ = renderer_.restart(scene_, settings.gpu);
    restarted_at_ = std::chrono::steady_clock::now();
}

void Viewer::settings_changed() {
    scene_ = source_.make(settings);
    generation_ = renderer_.restart(scene_, settings.gpu);
    restarted_at_ = std::chrono::steady_clock::now();
    if (selected_) selected_ = debug_pixel(scene_, selected_->x, selected_->y);
    display_dirty_ = true;
}

void Viewer::reset_camera() {
    settings.camera = source_.initial().camera;
    pivot_distance_ = initial_pivot_distance_;
    settings_changed();
}

void Viewer::orbit_by(Real yaw, Real pitch) {
    orbit(settings.camera, pivot_distance_, up_, yaw, pitch);
    settings_changed();
}

void Viewer::pan_by(Real right, Real up) {
    pan(settings.camera, pivot_distance_, right, up);
    settings_changed();
}

void Viewer::zoom_by(Real factor) {
    zoom(settings.camera, pivot_distance_, factor);
    settings_changed();
}

void Viewer::click(int x, int y) {
    if (x < 0 || y < 0 || x >= scene_.image.width || y >= scene_.image.height) return;
    selected_ = debug_pixel(scene_, x, y);
    display_dirty_ = true;
}

void Viewer::set_projection(Projection projection) {
    rt::set_projection(settings.camera, pivot_distance_, projection);
    settings_changed();
}

void Viewer::write_camera(const fs::path& file) {
    try {
        const std::string text = with_camera(read_scene_text(scene_file_), scene_file_,
                                             settings.camera, pivot_distance_);
        std::ofstream out(file, std::ios::binary);
        out << text;
        if (!out.flush()) throw std::runtime_error("cannot write " + file.string());
        status_ = "camera written to " + file.string();
    } catch (const std::exception& e) {
        status_ = std::string("camera not written: ") + e.what();
    }
}

void Viewer::key(char k) {
    if (k == 'Q') done_ = true;
    if (k == 'R') reset_camera();
    if (k == 'W') write_camera(scene_file_);
    if (k == 'P')
        set_projection(settings.camera.projection == Projection::Perspective
                           ? Projection::Orthographic
                           : Projection::Perspective);
    if (k == 'S') {
        // The next free number: a second session in the same folder keeps the first's.
        fs::path file;
        do {
            char name[32];
            std::snprintf(name, sizeof name, "screenshot-%03d.png", ++screenshot_count_);
            file = out_ / name;
        } while (fs::exists(file));
        screenshot_request_ = file;
    }
}

void Viewer::show(Show what) {
    if (what != Show::Render && !reference_) {
        status_ = "no reference image for this scene (reference_images/<stage>/<scene>.png)";
        return;
    }
    show_ = what;
    display_dirty_ = true;
}

bool Viewer::take_display_changed() {
    const bool changed = display_changed_;
    display_changed_ = false;
    return changed;
}

std::optional<fs::path> Viewer::take_screenshot_request() {
    return screenshot_request_;
}

std::optional<SyntheticMouse> Viewer::take_mouse() {
    if (mouse_.empty()) return std::nullopt;
    const SyntheticMouse m = mouse_.back();
    mouse_.pop_back();
    return m;
}

void Viewer::screenshot_saved() {
    status_ = "saved " + screenshot_request_->string();
    screenshot_request_.reset();
}

void Viewer::update() {
    if (std::optional<Frame> frame = renderer_.take()) {
        if (frame->generation == generation_) {
            frame_ = std::move(frame);
            report_non_finite_pixels();
            if (frame_->refined()) {
                refine_seconds_ = seconds_since(restarted_at_);
                if (scripted())  // the session's log: what a person would read off the HUD
                    std::printf(
                        "refined %dx%d %s in %.3f s after the change (full pass %.3f s, "
                        "%.2f camera Mrays/s)\n",
                        scene_.image.width, scene_.image.height, to_string(settings.mode),
                        refine_seconds_, frame_->seconds,
                        double(scene_.image.width) * scene_.image.height / frame_->seconds / 1e6);
                comparison_.reset();
                if (reference_) {
                    CompareOptions options;
                    options.neighbourhood = true;  // the graders' image_defaults
                    comparison_ = compare_images(to_image8(frame_->image), *reference_, options);
                }
            }
            display_dirty_ = true;
        }
    }
    run_script();
    if (display_dirty_) rebuild_display();
}

// NaN and infinite pixels are painted magenta, as `rt render` paints them, before the frame is
// shown, compared or saved; the status line says how many and how to debug the first.
void Viewer::report_non_finite_pixels() {
    const NonFinitePixels found = mark_non_finite_pixels(frame_->image);
    non_finite_ = found.count == 0 ? "" : found.describe(scene_file_);
    if (!non_finite_.empty() && scripted() && frame_->last)
        std::printf("%s\n", non_finite_.c_str());
}

void Viewer::rebuild_display() {
    display_dirty_ = false;
    if (show_ == Show::Reference && reference_) {
        display_ = *reference_;
    } else if (show_ == Show::Difference && comparison_ && comparison_->size_matches) {
        display_ = comparison_->heat_map;
    } else if (frame_ && frame_->error.empty()) {
        Image image = frame_->image;
        if (selected_) draw_ray_tree(scene_, *selected_, image);
        display_ = to_image8(image);
    } else {
        display_ = Image8{
            scene_.image.width, scene_.image.height,
            std::vector<std::uint8_t>(std::size_t(scene_.image.width) * scene_.image.height * 3)};
    }
    display_changed_ = true;
}

void Viewer::save_png(const Image8& image, const std::string& name) {
    const fs::path file = out_ / (name + ".png");
    write_image8(image, file);
    status_ = "saved " + file.string();
}

void Viewer::fail(const ScriptCommand& c, const std::string& message) {
    std::fprintf(stderr, "%s:%d: error: %s\n", script_file_.c_str(), c.line, message.c_str());
    exit_code_ = 1;
    done_ = true;
}

void Viewer::run_script() {
    if (script_.empty()) return;
    while (!done_ && next_command_ < script_.size()) {
        const ScriptCommand& c = script_[next_command_];
        if (!command_waiting_) command_started_ = std::chrono::steady_clock::now();
        command_waiting_ = true;
        if (!run_command(c)) return;
        command_waiting_ = false;
        ++next_command_;
    }
    // The last command done: quit once a requested screenshot is written.
    if (!screenshot_request_) done_ = true;
}

bool Viewer::run_command(const ScriptCommand& c) {
    const auto number = [&](std::size_t i) {
        return Real(std::strtod(c.args[i].c_str(), nullptr));
    };
    const std::string& n = c.name;
    if (screenshot_request_) return false;  // the window has not written the last one yet
    if (!mouse_.empty()) return false;      // nor played the last mouse gesture
    if (n == "sleep") return seconds_since(command_started_) >= double(number(0));
    if (n == "wait-refined") {
        if (frame_ && !frame_->error.empty() && frame_->generation == generation_) {
            fail(c, "the render failed: " + frame_->error);
            return true;
        }
        if (refined() && !display_dirty_) return true;
        if (seconds_since(command_started_) > kRefineTimeoutSeconds)
            fail(c, "no refined frame after " + std::to_string(int(kRefineTimeoutSeconds)) + " s");
        return done_;
    }
    if (n == "key") key(c.args[0][0]);
    if (n == "click") click(int(number(0)), int(number(1)));
    if (n == "set") {
        set_by_name(settings, c.args[0], c.args[1]);  // checked when the script was read
        settings_changed();
    }
    if (n == "toggle") {
        if (c.args[0] == "shadows") settings.shadows = !settings.shadows;
        if (c.args[0] == "bvh")
            settings.accelerator =
                settings.accelerator == Accelerator::Bvh ? Accelerator::None : Accelerator::Bvh;
        settings_changed();
    }
    if (n == "orbit") orbit_by(number(0), number(1));
    if (n == "pan") pan_by(number(0), number(1));
    if (n == "zoom") zoom_by(number(0));
    if (n == "reset-camera") reset_camera();
    if (n == "projection")
        set_projection(c.args[0] == "orthographic" ? Projection::Orthographic
                                                   : Projection::Perspective);
    if (n == "write-camera") write_camera(out_ / c.args[0]);
    if (n == "show") {
        const std::string& what = c.args[0];
        if (what != "render" && !reference_) fail(c, "this scene has no reference image");
        show(what == "render"      ? Show::Render
             : what == "reference" ? Show::Reference
                                   : Show::Difference);
    }
    if (n == "raster") raster = c.args[0] == "on";
    if (n == "screenshot") screenshot_request_ = out_ / (c.args[0] + ".png");
    if (n == "save-render") {
        if (!frame_ || !frame_->error.empty())
            fail(c, "nothing rendered yet; put wait-refined before it");
        else
            write_image(frame_->image, out_ / (c.args[0] + ".png"));
    }
    if (n == "save-display") {
        if (display_dirty_) rebuild_display();
        save_png(display_, c.args[0]);
    }
    if (n == "quit") done_ = true;
    if (n == "mouse-click" || n == "mouse-drag" || n == "mouse-wheel") queue_mouse(c);
    return true;
}

// A scripted mouse gesture as frames for the window to play, in playing order: hover, press,
// (move,) release, then one still frame.
void Viewer::queue_mouse(const ScriptCommand& c) {
    const auto number = [&](std::size_t i) {
        return float(std::strtod(c.args[i].c_str(), nullptr));
    };
    std::vector<SyntheticMouse> frames;
    const float x0 = number(0) + 0.5f, y0 = number(1) + 0.5f;
    frames.push_back({x0, y0});
    if (c.name == "mouse-wheel") {
        frames.push_back({x0, y0, false, false, number(2)});
    } else if (c.name == "mouse-click") {
        frames.push_back({x0, y0, true, false});
    } else {
        const bool left = c.args[4] == "left";
        const float x1 = number(2) + 0.5f, y1 = number(3) + 0.5f;
        for (int i = 0; i <= 10; ++i)
            frames.push_back(
                {x0 + (x1 - x0) * float(i) / 10, y0 + (y1 - y0) * float(i) / 10, left, !left});
        frames.push_back({x1, y1});
    }
    frames.push_back(frames.back());
    frames.back().left = frames.back().right = false;
    frames.back().wheel = 0;
    frames.push_back(frames.back());
    mouse_.assign(frames.rbegin(), frames.rend());
}

}  // namespace rt::view
