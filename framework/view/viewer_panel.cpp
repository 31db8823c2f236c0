// The viewer's side panel (Dear ImGui): the HUD, the settings, the selected pixel's ray tree.
#include "view/viewer_panel.h"

#include <imgui.h>

#include <array>
#include <cstdio>
#include <string>

#include "render/ray_tree.h"
#include "render/render.h"

namespace rt::view {
namespace {

// The filters the panel offers: each texture's own, or all nearest or bilinear.
const char* const kFilterNames[] = {to_string(TextureLookup::PerTexture),
                                    to_string(TextureLookup::Nearest),
                                    to_string(TextureLookup::Bilinear)};

// The colours draw_ray_tree uses, so the list and the overlay read alike.
ImVec4 kind_color(RayNode::Kind kind) {
    switch (kind) {
        case RayNode::Kind::Camera:
            return {1, 0.35f, 0.35f, 1};
        case RayNode::Kind::Reflection:
            return {0.45f, 0.6f, 1, 1};
        case RayNode::Kind::Refraction:
            return {1, 1, 0.3f, 1};
    }
    return {1, 1, 1, 1};
}

std::string what_was_hit(const PreparedScene& scene, const RayNode& n) {
    if (!n.hit) return "miss (background)";
    std::size_t index = 0;
    const Scene::Kind kind = scene.primitive_kind(n.hit_record.primitive, index);
    char text[160];
    const std::string& material = scene.material_name(n.hit_record.material);
    std::snprintf(text, sizeof text, "%s %zu, t %.3g, %s", to_string(kind), index,
                  double(n.hit_record.t),
                  material.empty() ? ("material #" + std::to_string(n.hit_record.material)).c_str()
                                   : ("\"" + material + "\"").c_str());
    return text;
}

void ray_list(const PreparedScene& scene, const RayNode& n) {
    ImGui::PushID(&n);
    ImGui::TextColored(kind_color(n.kind), "%*s%s d%d", n.depth * 2, "", to_string(n.kind),
                       n.depth);
    ImGui::SameLine();
    ImGui::TextUnformatted(what_was_hit(scene, n).c_str());
    if (n.hit && scene.features.light_links)
        ImGui::TextColored({1, 0.85f, 0.4f, 1}, "%*s  %s", n.depth * 2, "",
                           light_links_text(scene, n.hit_record.material).c_str());
    ImGui::Text("%*s  contribution (%.4f, %.4f, %.4f)", n.depth * 2, "", double(n.contribution.r),
                double(n.contribution.g), double(n.contribution.b));
    for (const ShadowRecord& s : n.shadows)
        ImGui::TextColored({1, 0.4f, 1, 1}, "%*s  shadow to light %zu: %s, T (%.3f, %.3f, %.3f)",
                           n.depth * 2, "", s.light, s.blocked_by >= 0 ? "blocked" : "clear",
                           double(s.transmittance.r), double(s.transmittance.g),
                           double(s.transmittance.b));
    for (const RayNode& child : n.children) ray_list(scene, child);
    ImGui::PopID();
}

int count_rays(const RayNode& n) {
    int count = 1 + int(n.shadows.size());
    for (const RayNode& child : n.children) count += count_rays(child);
    return count;
}

void hud(const Viewer& viewer) {
    const PreparedScene& scene = viewer.scene();
    ImGui::TextWrapped("%s", viewer.scene_file().c_str());
    if (viewer.settings.gpu)
        ImGui::Text("%d x %d, GPU (stage 09, headless EGL)", scene.image.width, scene.image.height);
    else
        ImGui::Text("%d x %d, %d threads", scene.image.width, scene.image.height, viewer.threads());
    if (const auto& frame = viewer.frame()) {
        if (frame->generation != viewer.scene_version()) {
            // The first pass of the change is not done (a slow setting, e.g. no BVH).
            ImGui::TextUnformatted("rendering the change (previous image shown)");
        } else if (!frame->error.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.4f, 1));
            ImGui::TextWrapped("%s", frame->error.c_str());
            ImGui::PopStyleColor();
        } else if (viewer.refined()) {
            const double pixels = double(scene.image.width) * scene.image.height;
            ImGui::TextWrapped("refined: %.3f s a frame (%.1f fps), %.2f Mrays/s (camera rays)%s",
                               frame->seconds, 1 / frame->seconds, pixels / frame->seconds / 1e6,
                               frame->gpu ? " on the GPU" : "");
        } else {
            if (frame->block > 1)
                ImGui::Text("refining: 1/%d resolution", frame->block);
            else
                ImGui::Text("refining: %d of %d samples a pixel", frame->samples,
                            scene.sampling.samples_per_pixel);
        }
    } else {
        ImGui::TextUnformatted("rendering...");
    }
    if (const auto& c = viewer.comparison()) {
        // Against the reference only the scene file's own settings are meant to match.
        const bool as_file = viewer.settings == viewer.initial_settings();
        ImGui::PushStyleColor(ImGuiCol_Text, !as_file    ? ImVec4(0.7f, 0.7f, 0.7f, 1)
                                             : c->passed ? ImVec4(0.4f, 1, 0.4f, 1)
                                                         : ImVec4(1, 0.4f, 0.4f, 1));
        if (!c->size_matches)
            ImGui::TextWrapped("vs reference: the render's size differs from the reference's");
        else
            ImGui::TextWrapped("vs reference: %s, %lld failing pixels%s",
                               c->passed ? "pass" : "FAIL", c->failing_pixels,
                               as_file ? "" : " (settings changed)");
        ImGui::PopStyleColor();
    }
}

void settings(Viewer& viewer) {
    ViewSettings& s = viewer.settings;
    bool changed = false;
    int mode = int(s.mode);
    static const auto names = [] {
        std::array<const char*, kRenderModeCount> all{};
        for (int i = 0; i < kRenderModeCount; ++i) all[std::size_t(i)] = to_string(RenderMode(i));
        return all;
    }();
    if (ImGui::Combo("mode", &mode, names.data(), kRenderModeCount)) {
        s.mode = RenderMode(mode);
        changed = true;
    }
    changed |= ImGui::Checkbox("shadows", &s.shadows);
    changed |= ImGui::SliderInt("max depth", &s.max_depth, 0, 16);
    bool bvh = s.accelerator == Accelerator::Bvh;
    if (ImGui::Checkbox("BVH (stage 06)", &bvh)) {
        s.accelerator = bvh ? Accelerator::Bvh : Accelerator::None;
        changed = true;
    }
    int filter = std::min(int(s.texture_lookup), 2);
    if (ImGui::Combo("texture filter", &filter, kFilterNames, IM_ARRAYSIZE(kFilterNames))) {
        s.texture_lookup = TextureLookup(filter);
        changed = true;
    }
    // The terms of stage 03 and the effects of stages 05 and 08, off in the scene itself.
    changed |= ImGui::Checkbox("ambient", &s.ambient);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("diffuse", &s.diffuse);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("specular", &s.specular);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("emissive", &s.emissive);
    changed |= ImGui::Checkbox("reflection", &s.reflection);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("refraction", &s.refraction);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("Fresnel", &s.fresnel);
    changed |= ImGui::Checkbox("environment", &s.environment);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("GPU (stage 09's shader)", &s.gpu);
    if (changed) viewer.settings_changed();
    ImGui::Checkbox("raster preview (OpenGL Blinn-Phong)", &viewer.raster);
    int projection = int(s.camera.projection == Projection::Orthographic);
    const char* projections[] = {"perspective", "orthographic"};
    if (ImGui::Combo("projection (P)", &projection, projections, 2))
        viewer.set_projection(projection ? Projection::Orthographic : Projection::Perspective);
    if (ImGui::Button("reset camera (R)")) viewer.reset_camera();
    ImGui::SameLine();
    if (ImGui::Button("write camera (W)")) viewer.key('W');
    ImGui::SameLine();
    if (ImGui::Button("screenshot (S)")) viewer.key('S');
    if (viewer.has_reference()) {
        int show = int(viewer.showing());
        bool pick = ImGui::RadioButton("render", &show, 0);
        ImGui::SameLine();
        pick |= ImGui::RadioButton("reference", &show, 1);
        ImGui::SameLine();
        pick |= ImGui::RadioButton("difference", &show, 2);
        if (pick) viewer.show(Show(show));
    }
}

}  // namespace

void draw_panel(Viewer& viewer, float width, float height) {
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(width, height));
    ImGui::Begin("rt view", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    hud(viewer);
    ImGui::Separator();
    settings(viewer);
    ImGui::Separator();
    ImGui::TextWrapped("Drag: orbit. Right drag: pan. Wheel: zoom. Click: ray tree.");
    if (!viewer.status().empty()) ImGui::TextWrapped("%s", viewer.status().c_str());
    if (!viewer.non_finite().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 1, 1));  // the pixels' magenta
        ImGui::TextWrapped("%s", viewer.non_finite().c_str());
        ImGui::PopStyleColor();
    }
    if (const auto& tree = viewer.selected()) {
        ImGui::Separator();
        ImGui::Text("pixel (%d, %d): %d rays, colour (%.4f, %.4f, %.4f)", tree->x, tree->y,
                    count_rays(tree->root), double(tree->color.r), double(tree->color.g),
                    double(tree->color.b));
        ImGui::BeginChild("rays", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
        ray_list(viewer.scene(), tree->root);
        ImGui::EndChild();
    }
    ImGui::End();
}

}  // namespace rt::view
