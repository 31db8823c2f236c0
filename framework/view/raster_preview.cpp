#include "view/raster_preview.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "geometry/procedural_mesh.h"
#include "image/image.h"

namespace rt::view {
namespace {

constexpr int kMaxLights = 8;

// One vertex: position, normal, then the material's k_a, k_d, k_s, k_e and n_s.
struct Vertex {
    glm::vec3 position, normal, ambient, diffuse, specular, emissive;
    float shininess;
};

const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 ka;
layout(location = 3) in vec3 kd;
layout(location = 4) in vec3 ks;
layout(location = 5) in vec3 ke;
layout(location = 6) in float ns;
uniform mat4 view_projection;
out vec3 world, n;
flat out vec3 a, d, s, e;
flat out float shininess;
void main() {
    world = position; n = normal; a = ka; d = kd; s = ks; e = ke; shininess = ns;
    gl_Position = view_projection * vec4(position, 1.0);
}
)";

// Blinn-Phong as stage 03 computes it (docs/conventions.md), without shadows or recursion;
// written sRGB-encoded, as the ray tracer's PNGs are.
const char* const kFragmentShader = R"(#version 330 core
in vec3 world, n;
flat in vec3 a, d, s, e;
flat in float shininess;
uniform vec3 eye, forward, ambient_light;
uniform bool orthographic;
uniform int light_count;
uniform int light_kind[8];  // 0 point, 1 directional
uniform vec3 light_position[8], light_direction[8], light_intensity[8], light_attenuation[8];
out vec4 color;
float encode(float c) {
    c = clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}
void main() {
    vec3 N = normalize(n);
    vec3 V = orthographic ? -forward : normalize(eye - world);
    if (dot(N, V) < 0.0) N = -N;  // the side facing the viewer, like a ray's front face
    vec3 c = e + a * ambient_light;
    for (int i = 0; i < light_count; ++i) {
        vec3 L = -light_direction[i];
        float attenuation = 1.0;
        if (light_kind[i] == 0) {
            L = light_position[i] - world;
            float r = length(L);
            L /= r;
            vec3 k = light_attenuation[i];
            attenuation = 1.0 / (k.x + k.y * r + k.z * r * r);
        }
        float ndl = dot(N, L);
        if (ndl <= 0.0) continue;
        vec3 H = normalize(L + V);
        c += light_intensity[i] * attenuation *
             (d * ndl + s * pow(max(dot(N, H), 0.0), shininess));
    }
    color = vec4(encode(c.r), encode(c.g), encode(c.b), 1.0);
}
)";

GLuint compile(GLenum kind, const char* source) {
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("rt view: the raster preview's shader: ") + log);
    }
    return shader;
}

glm::vec3 f3(const Vec3& v) {
    return glm::vec3(float(v.x), float(v.y), float(v.z));
}

class MeshBuilder {
  public:
    explicit MeshBuilder(const PreparedScene& scene) : scene_(scene) {}
    void add(const Vec3& p, const Vec3& normal, int material) {
        const Material m = material >= 0 && std::size_t(material) < scene_.materials.size()
                               ? scene_.materials[std::size_t(material)]
                               : Material{};
        vertices.push_back(
            Vertex{f3(p), f3(normal), m.ambient, m.diffuse, m.specular, m.emissive, m.shininess});
    }
    void quad(const std::array<Vec3, 4>& c, const Vec3& normal, int material) {
        for (int i : {0, 1, 2, 0, 2, 3}) add(c[std::size_t(i)], normal, material);
    }
    std::vector<Vertex> vertices;

  private:
    const PreparedScene& scene_;
};

// The scene's extent, for plane sizes and the depth range.
Real scene_radius(const PreparedScene& scene, Vec3& center) {
    Vec3 lo(kInfinity), hi(-kInfinity);
    const auto grow = [&](const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    };
    for (const Sphere& s : scene.spheres) {
        grow(s.center - Vec3(s.radius));
        grow(s.center + Vec3(s.radius));
    }
    for (const Box& b : scene.boxes) {
        grow(b.min);
        grow(b.max);
    }
    for (const Vec3& v : scene.vertices) grow(v);
    for (const Plane& p : scene.planes) grow(p.point);
    grow(scene.camera.eye);
    center = (lo + hi) * Real(0.5);
    return std::max(Real(1), glm::length(hi - lo) * Real(0.5));
}

std::vector<Vertex> tessellate(const PreparedScene& scene) {
    MeshBuilder mesh(scene);
    const TriangleMesh ball = make_icosphere(3);
    for (const Sphere& s : scene.spheres)
        for (const auto& t : ball.triangles)
            for (std::uint32_t i : t)
                mesh.add(s.center + ball.vertices[i] * s.radius, ball.normals[i], s.material);
    Vec3 center;
    const Real size = 20 * scene_radius(scene, center);
    for (const Plane& p : scene.planes) {
        const Vec3 helper = std::abs(p.normal.x) < Real(0.9) ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
        const Vec3 a = glm::normalize(glm::cross(p.normal, helper)) * size;
        const Vec3 b = glm::cross(p.normal, a);
        mesh.quad({p.point - a - b, p.point + a - b, p.point + a + b, p.point - a + b}, p.normal,
                  p.material);
    }
    for (const Box& b : scene.boxes)
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
                Vec3 n(0);
                n[axis] = side ? 1 : -1;
                const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                std::array<Vec3, 4> c;
                for (int k = 0; k < 4; ++k) {
                    Vec3 p;
                    p[axis] = side ? b.max[axis] : b.min[axis];
                    p[u] = (k == 1 || k == 2) ? b.max[u] : b.min[u];
                    p[v] = (k >= 2) ? b.max[v] : b.min[v];
                    c[std::size_t(k)] = p;
                }
                mesh.quad(c, n, b.material);
            }
    for (std::size_t t = 0; t < scene.triangles.size(); ++t) {
        Vec3 a, b, c;
        scene.triangle_vertices(t, a, b, c);
        const Vec3 face = glm::cross(b - a, c - a);
        const Vec3 corners[3] = {a, b, c};
        const Vec2 bary[3] = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
        for (int k = 0; k < 3; ++k) {
            Vec3 n = shading_normal(scene, t, bary[k]);
            if (glm::dot(n, n) == 0) n = face;
            mesh.add(corners[k], n, scene.triangles[t].material);
        }
    }
    return mesh.vertices;
}

}  // namespace

RasterPreview::RasterPreview(const PreparedScene& scene) {
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    program_ = glCreateProgram();
    glAttachShader(program_, vs);
    glAttachShader(program_, fs);
    glLinkProgram(program_);
    glDeleteShader(vs);
    glDeleteShader(fs);

    const std::vector<Vertex> vertices = tessellate(scene);
    vertex_count_ = GLsizei(vertices.size());
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(1, &vbo_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(),
                 GL_STATIC_DRAW);
    for (GLuint i = 0; i < 7; ++i) {
        glEnableVertexAttribArray(i);
        glVertexAttribPointer(i, i == 6 ? 1 : 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<const void*>(std::uintptr_t(i * sizeof(glm::vec3))));
    }
    glBindVertexArray(0);

    width_ = scene.image.width;
    height_ = scene.image.height;
    glGenTextures(1, &color_);
    glBindTexture(GL_TEXTURE_2D, color_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

RasterPreview::~RasterPreview() {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(1, &depth_);
    glDeleteTextures(1, &color_);
    glDeleteBuffers(1, &vbo_);
    glDeleteVertexArrays(1, &vao_);
    glDeleteProgram(program_);
}

void RasterPreview::draw(const PreparedScene& scene) {
    const Camera& cam = scene.camera;
    Vec3 center;
    const Real radius = scene_radius(scene, center);
    const float far = float(40 * radius + glm::length(cam.eye - center));
    const float aspect = float(width_) / float(height_);
    const glm::mat4 view = glm::lookAt(f3(cam.eye), f3(cam.eye - cam.w), f3(cam.v));
    const bool ortho = cam.projection == Projection::Orthographic;
    const float h = float(cam.view_height) / 2;
    const glm::mat4 projection =
        ortho ? glm::ortho(-h * aspect, h * aspect, -h, h, 0.0f, far)
              : glm::perspective(glm::radians(float(cam.vertical_fov_degrees)), aspect, far * 1e-5f,
                                 far);

    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width_, height_);
    const Color bg = scene.background;
    glClearColor(linear_to_srgb(bg.r), linear_to_srgb(bg.g), linear_to_srgb(bg.b), 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(program_);
    const auto at = [&](const char* name) { return glGetUniformLocation(program_, name); };
    glUniformMatrix4fv(at("view_projection"), 1, GL_FALSE, glm::value_ptr(projection * view));
    glUniform3fv(at("eye"), 1, glm::value_ptr(f3(cam.eye)));
    glUniform3fv(at("forward"), 1, glm::value_ptr(f3(-cam.w)));
    glUniform3fv(at("ambient_light"), 1, glm::value_ptr(scene.ambient_light));
    glUniform1i(at("orthographic"), ortho);
    // A scene without lights (the debug-mode scenes of stages 01-02) would be black: light it
    // with a headlight, a directional light along the view.
    std::vector<Light> scene_lights = scene.lights;
    if (scene_lights.empty()) {
        Light headlight;
        headlight.kind = LightKind::Directional;
        headlight.direction = -cam.w;
        scene_lights.push_back(headlight);
    }
    const int lights = std::min<int>(kMaxLights, int(scene_lights.size()));
    glUniform1i(at("light_count"), lights);
    for (int i = 0; i < lights; ++i) {
        const Light& l = scene_lights[std::size_t(i)];
        // snprintf, not std::string +: GCC 12 reports a false -Wrestrict there (bug 105329).
        const auto uniform = [&](const char* name) {
            char text[64];
            std::snprintf(text, sizeof text, "%s[%d]", name, i);
            return glGetUniformLocation(program_, text);
        };
        glUniform1i(uniform("light_kind"), l.kind == LightKind::Point ? 0 : 1);
        glUniform3fv(uniform("light_position"), 1, glm::value_ptr(f3(l.position)));
        glUniform3fv(uniform("light_direction"), 1, glm::value_ptr(f3(l.direction)));
        glUniform3fv(uniform("light_intensity"), 1, glm::value_ptr(l.intensity));
        glUniform3fv(uniform("light_attenuation"), 1, glm::value_ptr(f3(l.attenuation)));
    }
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace rt::view
