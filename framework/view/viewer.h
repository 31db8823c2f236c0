// The viewer's state and everything it does short of drawing the window: settings to scenes,
// progressive frames to the displayed image, clicks to ray trees, the scripted session.
// viewer_window.cpp draws it (GLFW, OpenGL, Dear ImGui) and feeds it mouse and keys.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/compare.h"
#include "render/ray_tree.h"
#include "view/progressive.h"
#include "view/view.h"
#include "view/view_script.h"
#include "view/view_settings.h"

namespace rt::view {

enum class Show { Render, Reference, Difference };

// One window frame of a scripted mouse (image pixels), fed to ImGui in place of the real one.
struct SyntheticMouse {
    float x = 0, y = 0;
    bool left = false, right = false;
    float wheel = 0;
};

class Viewer {
  public:
    Viewer(Scene loaded, const ViewArgs& args, std::vector<ScriptCommand> script);

    // Once a window frame, before drawing: takes finished passes, runs the script, rebuilds the
    // displayed image when something changed.
    void update();

    // Actions, from the panel, the mouse, keys or the script.
    void settings_changed();  // after editing `settings`
    void reset_camera();
    void click(int x, int y);
    void key(char k);  // 'S' screenshot, 'R' reset camera, 'Q' quit
    void show(Show what);
    void orbit_by(Real yaw, Real pitch);
    void pan_by(Real right, Real up);
    void zoom_by(Real factor);
    void set_projection(Projection projection);  // keeps the pivot's size on screen
    // Writes the scene file with the current camera (rt fmt's form, everything else kept) to
    // `file`: the scene file itself for the W key. Says what happened in status().
    void write_camera(const std::filesystem::path& file);

    // What the window shows and asks for.
    const Image8& display() const { return display_; }
    bool take_display_changed();  // true once after display() changed
    std::optional<std::filesystem::path> take_screenshot_request();
    std::optional<SyntheticMouse> take_mouse();  // this frame's scripted mouse, if any
    void screenshot_saved();                     // the window wrote the requested screenshot
    bool done() const { return done_; }
    int exit_code() const { return exit_code_; }

    // Read by the panel.
    ViewSettings settings;
    bool raster = true;  // the OpenGL preview beside the ray-traced image
    std::uint64_t scene_version() const { return generation_; }  // changes with scene()
    const PreparedScene& scene() const { return scene_; }
    const ViewSettings& initial_settings() const { return source_.initial(); }
    const std::string& scene_file() const { return scene_file_; }
    const std::optional<Frame>& frame() const { return frame_; }
    bool refined() const {
        return frame_ && frame_->refined() && frame_->generation == generation_;
    }
    double refine_seconds() const { return refine_seconds_; }  // restart to refined
    int threads() const { return renderer_.threads(); }
    const std::optional<PixelTree>& selected() const { return selected_; }
    Show showing() const { return show_; }
    bool has_reference() const { return reference_.has_value(); }
    const std::optional<CompareResult>& comparison() const { return comparison_; }
    const std::string& status() const { return status_; }
    // The current frame's NaN and infinite pixels (shown magenta): how many, the first, how to
    // debug it; empty when there are none.
    const std::string& non_finite() const { return non_finite_; }
    bool scripted() const { return !script_.empty(); }

  private:
    void run_script();
    bool run_command(const ScriptCommand& c);  // false: it waits (run again next frame)
    void queue_mouse(const ScriptCommand& c);  // mouse-click, mouse-drag, mouse-wheel
    void report_non_finite_pixels();
    void rebuild_display();
    void save_png(const Image8& image, const std::string& name);
    void fail(const ScriptCommand& c, const std::string& message);

    SceneSource source_;
    PreparedScene scene_;  // the scene of the current settings
    std::string scene_file_;
    std::filesystem::path out_;
    std::string script_file_;
    Vec3 up_;              // the scene camera's v: orbits turn about it
    Real pivot_distance_;  // orbit/zoom pivot in front of the eye
    Real initial_pivot_distance_;
    ProgressiveRenderer renderer_;
    std::uint64_t generation_ = 0;
    std::chrono::steady_clock::time_point restarted_at_;
    double refine_seconds_ = 0;
    std::optional<Frame> frame_;
    std::optional<PixelTree> selected_;
    std::optional<Image8> reference_;
    std::optional<CompareResult> comparison_;
    Show show_ = Show::Render;
    Image8 display_;
    bool display_dirty_ = true, display_changed_ = false;
    std::optional<std::filesystem::path> screenshot_request_;
    int screenshot_count_ = 0;
    std::string status_;
    std::string non_finite_;

    std::vector<SyntheticMouse> mouse_;  // frames still to play, last first
    std::vector<ScriptCommand> script_;
    std::size_t next_command_ = 0;
    std::chrono::steady_clock::time_point command_started_;
    bool command_waiting_ = false;
    bool done_ = false;
    int exit_code_ = 0;
};

}  // namespace rt::view
