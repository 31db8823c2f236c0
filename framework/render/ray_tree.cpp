#include "render/ray_tree.h"

// GCC 12 at -O3 reports a false -Wrestrict inside std::string's operator+ (GCC bug 105329).
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rt {
namespace {

using json = nlohmann::json;

template <typename V>
json array3(const V& v) {
    return json::array({double(v[0]), double(v[1]), double(v[2])});
}

template <typename V>  // Vec3 or Color (the same type when Real is float)
std::string fmt(const V& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", double(v[0]), double(v[1]), double(v[2]));
    return buf;
}

json node_json(const PreparedScene& scene, const RayNode& n) {
    json j;
    j["kind"] = to_string(n.kind);
    j["depth"] = n.depth;
    j["origin"] = array3(n.ray.origin);
    j["direction"] = array3(n.ray.direction);
    j["ray_weight"] = array3(n.ray_weight);
    j["weight"] = array3(n.weight);
    if (n.hit) {
        std::size_t index = 0;
        const Scene::Kind kind = scene.primitive_kind(n.hit_record.primitive, index);
        const int m = n.hit_record.material;
        j["hit"] = {{"t", double(n.hit_record.t)},
                    {"point", array3(n.surface.point)},
                    {"normal", array3(n.surface.normal)},
                    {"front_face", n.surface.front_face},
                    {"primitive", n.hit_record.primitive},
                    {"primitive_kind", to_string(kind)},
                    {"material", m},
                    {"material_name", scene.material_name(m)}};
    } else {
        j["hit"] = nullptr;
    }
    j["local"] = array3(n.local);
    j["contribution"] = array3(n.contribution);
    json shadows = json::array();
    for (const ShadowRecord& s : n.shadows) {
        json js = {{"light", s.light},
                   {"origin", array3(s.ray.origin)},
                   {"direction", array3(s.ray.direction)},
                   {"t_max", std::isfinite(double(s.t_range.max)) ? json(double(s.t_range.max))
                                                                  : json("inf")},
                   {"transmittance", array3(s.transmittance)}};
        js["blocked_by"] = s.blocked_by >= 0 ? json(s.blocked_by) : json(nullptr);
        if (s.blocked_by >= 0) js["blocked_t"] = double(s.blocked_t);
        shadows.push_back(js);
    }
    j["shadow_rays"] = shadows;
    json children = json::array();
    for (const RayNode& c : n.children) children.push_back(node_json(scene, c));
    j["children"] = children;
    return j;
}

void node_text(const PreparedScene& scene, const RayNode& n, int indent, std::string& out) {
    const std::string pad(std::size_t(indent) * 2, ' ');
    out += pad + to_string(n.kind) + " ray (depth " + std::to_string(n.depth) + ") from " +
           fmt(n.ray.origin) + " dir " + fmt(n.ray.direction) + ", weight " + fmt(n.weight) + "\n";
    if (!n.hit) {
        out += pad + "  miss: background " + fmt(n.local) + ", contributes " + fmt(n.contribution) +
               "\n";
    } else {
        char t[32];
        std::snprintf(t, sizeof t, "%.6g", double(n.hit_record.t));
        out += pad + "  hit t = " + t + " at " + fmt(n.surface.point) + " on " +
               primitive_name(scene, n.hit_record.primitive) + ", material " +
               material_name(scene, n.hit_record.material) +
               (n.surface.front_face ? ", outside" : ", inside") + "\n";
        if (scene.features.light_links)
            out +=
                pad + "  light linking: " + light_links_text(scene, n.hit_record.material) + "\n";
        for (const ShadowRecord& s : n.shadows)
            out += pad + "  shadow ray to light " + std::to_string(s.light) + ": " +
                   (s.blocked_by < 0 ? std::string("unblocked")
                                     : "blocked by " + primitive_name(scene, s.blocked_by)) +
                   ", transmittance " + fmt(s.transmittance) + "\n";
        out +=
            pad + "  direct light " + fmt(n.local) + ", contributes " + fmt(n.contribution) + "\n";
    }
    for (const RayNode& c : n.children) {
        out += pad + "  " + to_string(c.kind) + " weight " + fmt(c.ray_weight) + ":\n";
        node_text(scene, c, indent + 2, out);
    }
}

// Clips the segment a-b (image coordinates) to the rectangle [lo, hi] (Liang-Barsky).
bool clip_2d(Vec2& a, Vec2& b, Vec2 lo, Vec2 hi) {
    Real t0 = 0, t1 = 1;
    const Vec2 d = b - a;
    const Real p[4] = {-d.x, d.x, -d.y, d.y};
    const Real q[4] = {a.x - lo.x, hi.x - a.x, a.y - lo.y, hi.y - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;
            continue;
        }
        const Real r = q[i] / p[i];
        if (p[i] < 0)
            t0 = std::max(t0, r);
        else
            t1 = std::min(t1, r);
        if (t0 > t1) return false;
    }
    const Vec2 start = a + t0 * d, end = a + t1 * d;
    a = start;
    b = end;
    return true;
}

void plot(Image& image, int x, int y, const Color& c) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
    image.pixels[std::size_t(y) * std::size_t(image.width) + std::size_t(x)] = c;
}

// A 3D segment, clipped in front of a perspective camera, projected and drawn.
void draw_segment(const PreparedScene& scene, Vec3 a, Vec3 b, const Color& color, Image& image) {
    const Camera& cam = scene.camera;
    if (cam.projection == Projection::Perspective) {
        const Real near = Real(1e-3);
        const Real za = -glm::dot(a - cam.eye, cam.w), zb = -glm::dot(b - cam.eye, cam.w);
        if (za < near && zb < near) return;
        if (za < near) a = a + (b - a) * ((near - za) / (zb - za));
        if (zb < near) b = b + (a - b) * ((near - zb) / (za - zb));
    }
    auto pa = project_to_image(scene, a), pb = project_to_image(scene, b);
    if (!pa || !pb) return;
    Vec2 p = *pa, q = *pb;
    if (!clip_2d(p, q, Vec2(0),
                 Vec2(Real(image.width) - Real(1e-3), Real(image.height) - Real(1e-3))))
        return;
    const int steps = int(std::ceil(std::max(std::abs(q.x - p.x), std::abs(q.y - p.y)))) + 1;
    for (int i = 0; i <= steps; ++i) {
        const Vec2 s = p + (q - p) * (Real(i) / Real(steps));
        plot(image, int(std::floor(s.x)), int(std::floor(s.y)), color);
    }
}

void draw_node(const PreparedScene& scene, const RayNode& n, Real far, Image& image) {
    static const Color kCamera{1, 0, 0}, kShadow{1, 0, 1}, kReflection{0, 0, 1},
        kRefraction{1, 1, 0};
    const Color color = n.kind == RayNode::Kind::Camera       ? kCamera
                        : n.kind == RayNode::Kind::Reflection ? kReflection
                                                              : kRefraction;
    const Vec3 dir = glm::normalize(n.ray.direction);
    const Vec3 end = n.hit ? n.surface.point : n.ray.origin + far * dir;
    draw_segment(scene, n.ray.origin, end, color, image);
    for (const ShadowRecord& s : n.shadows) {
        Real t = std::min(s.blocked_by >= 0 ? s.blocked_t : s.t_range.max, far);
        draw_segment(scene, s.ray.origin, s.ray.at(t), kShadow, image);
    }
    for (const RayNode& c : n.children) draw_node(scene, c, far, image);
}

}  // namespace

std::string primitive_name(const PreparedScene& scene, int id) {
    if (!scene.is_primitive(id)) return "none";
    std::size_t index = 0;
    const Scene::Kind kind = scene.primitive_kind(id, index);
    return std::string(to_string(kind)) + " " + std::to_string(index) + " (id " +
           std::to_string(id) + ")";
}

std::string material_name(const PreparedScene& scene, int m) {
    if (m < 0 || std::size_t(m) >= scene.materials.size()) return "?";
    const std::string& name = scene.material_name(m);
    return name.empty() ? "#" + std::to_string(m) : "\"" + name + "\"";
}

PixelTree debug_pixel(const PreparedScene& scene, int x, int y) {
    PixelTree tree;
    tree.x = x;
    tree.y = y;
    tree.color = shade_pixel(scene, x, y, &tree.root);
    return tree;
}

std::string light_links_text(const PreparedScene& scene, int material) {
    std::string reached, shadowless, not_reached;
    auto add = [](std::string& list, std::size_t i) {
        list += (list.empty() ? "" : ", ") + std::to_string(i);
    };
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        add(light_reaches(light, material) ? reached : not_reached, i);
        if (light_reaches(light, material) && !light.casts_shadows) add(shadowless, i);
    }
    return "reached by lights " + (reached.empty() ? "none" : reached) +
           (shadowless.empty() ? "" : " (no shadows: " + shadowless + ")") + "; not by " +
           (not_reached.empty() ? "any" : not_reached);
}

std::string ray_tree_text(const PreparedScene& scene, const PixelTree& tree) {
    std::string out =
        "pixel (" + std::to_string(tree.x) + ", " + std::to_string(tree.y) + "): colour " +
        fmt(tree.color) + " (linear), max_depth " + std::to_string(scene.max_depth) +
        (scene.features.shadows ? ", shadows" : "") + (scene.fresnel ? ", fresnel" : "") + "\n";
    node_text(scene, tree.root, 0, out);
    return out;
}

std::string ray_tree_json(const PreparedScene& scene, const PixelTree& tree) {
    json j;
    j["pixel"] = {tree.x, tree.y};
    j["color"] = array3(tree.color);
    j["max_depth"] = scene.max_depth;
    j["shadows"] = scene.features.shadows;
    j["fresnel"] = scene.fresnel;
    j["tree"] = node_json(scene, tree.root);
    return j.dump(2);
}

std::optional<Vec2> project_to_image(const PreparedScene& scene, const Vec3& point) {
    const Camera& cam = scene.camera;
    const Vec3 q = point - cam.eye;
    const Real xc = glm::dot(q, cam.u), yc = glm::dot(q, cam.v), zc = -glm::dot(q, cam.w);
    const Real w = Real(scene.image.width), h = Real(scene.image.height);
    if (cam.projection == Projection::Orthographic) {
        const Real vh = cam.view_height;
        return Vec2((xc / (vh * scene.image.aspect()) + Real(0.5)) * w, (Real(0.5) - yc / vh) * h);
    }
    if (!(zc > 0)) return std::nullopt;
    const Real tan_half = std::tan(cam.vertical_fov_degrees * kPi / 360);
    return Vec2((xc / zc / (tan_half * scene.image.aspect()) + 1) * Real(0.5) * w,
                (1 - yc / zc / tan_half) * Real(0.5) * h);
}

void draw_ray_tree(const PreparedScene& scene, const PixelTree& tree, Image& image) {
    // A ray that misses is drawn to a distance well beyond the scene's camera.
    const Real far = 1000 * std::max(Real(1), glm::length(scene.camera.eye));
    draw_node(scene, tree.root, far, image);
    // The camera ray projects to its own pixel: mark that pixel with a small red cross.
    for (int d = -3; d <= 3; ++d) {
        plot(image, tree.x + d, tree.y, Color(1, 0, 0));
        plot(image, tree.x, tree.y + d, Color(1, 0, 0));
    }
}

}  // namespace rt
