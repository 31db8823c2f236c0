// Scripted viewer sessions (`rt view SCENE --script FILE --out DIR`): the viewer replays the
// commands one after another, as a person would at the window, then exits. One command a line;
// `#` starts a comment.
//
//   sleep SECONDS          wait (the window keeps drawing and the render keeps refining)
//   wait-refined           wait until the full-resolution render of the current settings is shown
//   key K                  press a key: S screenshot, R reset camera, Q quit
//   click X Y              click image pixel (X, Y): its ray tree is drawn and listed
//   set NAME VALUE         change a setting: mode M, shadows on|off, max-depth N, bvh on|off,
//                          filter scene|nearest|bilinear
//   toggle NAME            flip shadows or bvh
//   orbit YAW PITCH        turn the camera about its pivot (degrees)
//   pan RIGHT UP           move the camera (fractions of the view's height)
//   zoom FACTOR            move toward the pivot (< 1) or away (> 1)
//   reset-camera           back to the scene file's camera
//   show render|reference|difference   what the image area shows
//   raster on|off          the OpenGL Blinn-Phong preview beside the ray-traced image
//   screenshot NAME        the whole window as DIR/NAME.png (panel included)
//   save-render NAME       the current render, without overlays, as DIR/NAME.png
//   save-display NAME      the image area as shown (overlays included) as DIR/NAME.png
//   mouse-click X Y        the same through the window's mouse handling (synthetic events)
//   mouse-drag X0 Y0 X1 Y1 left|right   a drag (left orbits, right pans), image pixels
//   mouse-wheel X Y STEPS  wheel steps over pixel (X, Y) (positive: zoom in)
//   quit                   end the session (also done after the last line)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rt::view {

struct ScriptCommand {
    int line = 0;
    std::string name;
    std::vector<std::string> args;
};

// Reads and checks the whole script before the window opens. Throws std::runtime_error with
// one line "FILE:LINE: error: what is wrong; how to write it".
std::vector<ScriptCommand> read_script(const std::filesystem::path& file);

}  // namespace rt::view
