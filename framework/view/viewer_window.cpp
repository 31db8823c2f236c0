// The viewer's window: GLFW, an OpenGL 3.3 core context (functions through libepoxy), Dear ImGui's
// GLFW and OpenGL 3 back-ends. The render is a texture drawn 1:1 right of the panel.
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "render/accelerate.h"
#include "scene/scene_loader.h"
#include "view/raster_preview.h"
#include "view/view.h"
#include "view/viewer.h"
#include "view/viewer_panel.h"

namespace rt::view {
namespace {

constexpr int kPanelWidth = 380;
constexpr int kMinHeight = 640;
// Small course images (200 x 150) are blown up by a whole factor toward this size, so a lecture
// hall sees them; each image pixel stays a crisp square (nearest filtering). Two of them (the
// raster preview beside the render) fit a 1920-pixel projector with the panel.
constexpr int kTargetWidth = 720, kTargetHeight = 720;
// Wider than this and the raster preview is drawn at half size (a lecture's larger --width).
constexpr int kMaxWindowWidth = 1920;

// The raster preview's size relative to the render's: the same when both fit.
float raster_fraction(int shown_width) {
    return kPanelWidth + 2 * shown_width <= kMaxWindowWidth ? 1.0f : 0.5f;
}
constexpr Real kOrbitDegreesPerPixel = Real(0.3);
constexpr Real kZoomPerWheelStep = Real(0.9);

// GLFW's reason for the last failure: part of the one-line error when no window opens.
std::string last_glfw_error;

void glfw_error(int code, const char* text) {
    last_glfw_error = text;
    (void)code;
}

// The whole window's pixels, top row first (glReadPixels reads bottom-up).
Image8 read_window(GLFWwindow* window) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    Image8 image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 3)};
    std::vector<std::uint8_t> rows(image.data.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    const std::size_t row = std::size_t(width) * 3;
    for (int y = 0; y < height; ++y)
        std::copy_n(&rows[std::size_t(height - 1 - y) * row], row,
                    &image.data[std::size_t(y) * row]);
    return image;
}

class ImageTexture {
  public:
    ImageTexture() { glGenTextures(1, &id_); }
    ~ImageTexture() { glDeleteTextures(1, &id_); }
    void upload(const Image8& image) {
        glBindTexture(GL_TEXTURE_2D, id_);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image.width, image.height, 0, GL_RGB,
                     GL_UNSIGNED_BYTE, image.data.data());
    }
    ImTextureID id() const { return reinterpret_cast<ImTextureID>(std::intptr_t(id_)); }

  private:
    GLuint id_ = 0;
};

// The image area: the texture, and the mouse on it (drag orbit, right/middle drag pan, wheel
// zoom, a click without a drag selects the pixel).
void image_area(Viewer& viewer, const ImageTexture& texture, const RasterPreview& raster,
                int scale) {
    const Image8& shown = viewer.display();
    const ImVec2 size(float(shown.width * scale), float(shown.height * scale));
    ImGui::SetNextWindowPos(ImVec2(float(kPanelWidth), 0));
    const float fraction = raster_fraction(int(size.x));
    ImGui::SetNextWindowSize(ImVec2(size.x * (1 + fraction), size.y));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0);
    ImGui::Begin("image", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoBringToFrontOnFocus);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::Image(texture.id(), size);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    if (viewer.raster) {
        const ImVec2 right(origin.x + size.x, origin.y);
        draw->AddImage(reinterpret_cast<ImTextureID>(std::intptr_t(raster.texture())), right,
                       ImVec2(right.x + size.x * fraction, right.y + size.y * fraction),
                       ImVec2(0, 1), ImVec2(1, 0));
        draw->AddText(ImVec2(right.x + 6, right.y + 4), IM_COL32(255, 255, 255, 220),
                      "OpenGL raster, Blinn-Phong (no shadows, recursion or textures)");
    }
    draw->AddText(ImVec2(origin.x + 6, origin.y + 4), IM_COL32(255, 255, 255, 220),
                  "ray traced (CPU)");
    ImGui::SetCursorScreenPos(origin);
    ImGui::InvisibleButton("pixels", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    const ImGuiIO& io = ImGui::GetIO();
    const bool moved = io.MouseDelta.x != 0 || io.MouseDelta.y != 0;
    if (ImGui::IsItemActive() && moved) {
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left))
            viewer.orbit_by(io.MouseDelta.x * kOrbitDegreesPerPixel,
                            io.MouseDelta.y * kOrbitDegreesPerPixel);
        else if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) ||
                 ImGui::IsMouseDragging(ImGuiMouseButton_Middle))
            viewer.pan_by(-io.MouseDelta.x / size.y, io.MouseDelta.y / size.y);
    }
    if (ImGui::IsItemHovered() && io.MouseWheel != 0)
        viewer.zoom_by(std::pow(kZoomPerWheelStep, Real(io.MouseWheel)));
    if (ImGui::IsItemDeactivated() && io.MouseDragMaxDistanceSqr[0] < 9 &&
        ImGui::IsMouseReleased(ImGuiMouseButton_Left))
        viewer.click(int((io.MousePos.x - origin.x) / float(scale)),
                     int((io.MousePos.y - origin.y) / float(scale)));
    ImGui::End();
    ImGui::PopStyleVar(2);
}

void keys(Viewer& viewer) {
    if (ImGui::GetIO().WantTextInput) return;
    if (ImGui::IsKeyPressed(GLFW_KEY_S, false)) viewer.key('S');
    if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) viewer.key('R');
    if (ImGui::IsKeyPressed(GLFW_KEY_W, false)) viewer.key('W');
    if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) viewer.key('P');
    if (ImGui::IsKeyPressed(GLFW_KEY_Q, false) || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false))
        viewer.key('Q');
}

// GLFW and ImGui set up and torn down in order, whatever happens in between.
struct Window {
    GLFWwindow* handle = nullptr;
    Window(int width, int height, const std::string& title) {
        glfwSetErrorCallback(glfw_error);
        if (!glfwInit())
            throw std::runtime_error("cannot open a window (" + last_glfw_error +
                                     "); run under a desktop or `xvfb-run -a rt view ...`");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
        handle = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
        if (!handle) {
            glfwTerminate();
            throw std::runtime_error("no OpenGL 3.3 core window (" + last_glfw_error +
                                     "); `rt gl-info --window` shows what the display offers");
        }
        glfwMakeContextCurrent(handle);
        glfwSwapInterval(1);
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside the student's files
        ImGui::StyleColorsDark();
        ImGui_ImplGlfw_InitForOpenGL(handle, true);
        ImGui_ImplOpenGL3_Init("#version 330 core");
    }
    ~Window() {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
        glfwDestroyWindow(handle);
        glfwTerminate();
    }
};

}  // namespace

int run_view(const ViewArgs& args) {
    // Script and scene errors come before any window opens.
    std::vector<ScriptCommand> script;
    if (!args.script.empty()) script = read_script(args.script);
    if (!args.script.empty() || args.out != ".") std::filesystem::create_directories(args.out);
    Scene scene = load_scene(args.scene);
    if (args.width > 0) scene.image.width = args.width;
    if (args.height > 0) scene.image.height = args.height;
    const ImageSize size = scene.image;

    const int scale = std::max(1, std::min(kTargetWidth / std::max(size.width, 1),
                                           kTargetHeight / std::max(size.height, 1)));
    const float fraction = raster_fraction(size.width * scale);
    Window window(kPanelWidth + int(float(size.width * scale) * (1 + fraction)),
                  std::max(size.height * scale, kMinHeight), "rt view " + args.scene);
    Viewer viewer(std::move(scene), args, std::move(script));
    ImageTexture texture;
    RasterPreview raster(viewer.scene());
    std::uint64_t raster_version = ~std::uint64_t(0);
    while (!viewer.done() && !glfwWindowShouldClose(window.handle)) {
        // Sleeps between events: 60 times a second while passes or a script are coming, a few
        // times a second once refined (an idle window redrawing at 60 Hz took 40% of a core
        // under Mesa's llvmpipe); mouse and keys wake it at once.
        glfwWaitEventsTimeout(viewer.scripted() || !viewer.refined() ? 1.0 / 60 : 0.25);
        viewer.update();
        if (viewer.take_display_changed()) texture.upload(viewer.display());
        if (viewer.raster && raster_version != viewer.scene_version()) {
            raster.draw(viewer.scene());
            raster_version = viewer.scene_version();
        }

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        if (const auto mouse = viewer.take_mouse()) {
            // After the back-end has read the real mouse, before ImGui uses it.
            ImGuiIO& io = ImGui::GetIO();
            io.MousePos =
                ImVec2(float(kPanelWidth) + mouse->x * float(scale), mouse->y * float(scale));
            io.MouseDown[ImGuiMouseButton_Left] = mouse->left;
            io.MouseDown[ImGuiMouseButton_Right] = mouse->right;
            io.MouseDown[ImGuiMouseButton_Middle] = false;
            io.MouseWheel = mouse->wheel;
        }
        ImGui::NewFrame();
        int width = 0, height = 0;
        glfwGetFramebufferSize(window.handle, &width, &height);
        draw_panel(viewer, float(kPanelWidth), float(height));
        image_area(viewer, texture, raster, scale);
        keys(viewer);
        ImGui::Render();
        glViewport(0, 0, width, height);
        glClearColor(0.12f, 0.12f, 0.14f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        if (const auto file = viewer.take_screenshot_request()) {
            write_image8(read_window(window.handle), *file);
            viewer.screenshot_saved();
        }
        glfwSwapBuffers(window.handle);
    }
    return viewer.exit_code();
}

}  // namespace rt::view
