// The packed scene's C++ structs (framework/gpu/gpu_scene.h) against the GLSL declarations in
// shaders/scene_layout.glsl, as the driver lays them out: every member's offset and every
// array's stride, read with glGetProgramResourceiv from a compiled compute shader.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <cctype>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/source_dir.h"
#include "gpu/gl/egl_context.h"
#include "gpu/gpu_scene.h"
#include "gpu/shader_constants.h"
#include "render/prepare.h"

namespace rt::gpu {
namespace {

struct Member {
    const char* name;  // a buffer variable, as GL names it
    std::size_t offset, stride;
    const char* use;  // GLSL that reads it into `acc` (so the compiler keeps it)
};

#define RT_MEMBER(T, glsl_array, field, use)                         \
    Member {                                                         \
        glsl_array "[0]." #field, offsetof(T, field), sizeof(T), use \
    }

const std::vector<Member>& members() {
    static const std::vector<Member> list = {
        RT_MEMBER(GpuSphere, "spheres", center_radius, "acc += spheres[0].center_radius;"),
        RT_MEMBER(GpuSphere, "spheres", material, "acc += vec4(spheres[0].material);"),
        RT_MEMBER(GpuPlane, "planes", point_material, "acc += planes[0].point_material;"),
        RT_MEMBER(GpuPlane, "planes", normal, "acc += planes[0].normal;"),
        RT_MEMBER(GpuBox, "boxes", min_material, "acc += boxes[0].min_material;"),
        RT_MEMBER(GpuBox, "boxes", max, "acc += boxes[0].max;"),
        RT_MEMBER(GpuTriangle, "triangles", vertices_material,
                  "acc += vec4(triangles[0].vertices_material);"),
        RT_MEMBER(GpuMaterial, "materials", ambient, "acc += materials[0].ambient;"),
        RT_MEMBER(GpuMaterial, "materials", diffuse, "acc += materials[0].diffuse;"),
        RT_MEMBER(GpuMaterial, "materials", specular_shininess,
                  "acc += materials[0].specular_shininess;"),
        RT_MEMBER(GpuMaterial, "materials", emissive, "acc += materials[0].emissive;"),
        RT_MEMBER(GpuMaterial, "materials", reflective, "acc += materials[0].reflective;"),
        RT_MEMBER(GpuMaterial, "materials", transmissive_ior,
                  "acc += materials[0].transmissive_ior;"),
        RT_MEMBER(GpuMaterial, "materials", maps, "acc += vec4(materials[0].maps);"),
        Member{"materials[0].map_transform[0]", offsetof(GpuMaterial, map_transform),
               sizeof(GpuMaterial), "acc += materials[0].map_transform[3];"},
        RT_MEMBER(GpuTexture, "textures", kind_image_filter_wrap,
                  "acc += vec4(textures[0].kind_image_filter_wrap);"),
        RT_MEMBER(GpuTexture, "textures", a_srgb, "acc += textures[0].a_srgb;"),
        RT_MEMBER(GpuTexture, "textures", b_scale, "acc += textures[0].b_scale;"),
        RT_MEMBER(GpuTextureImage, "texture_images", width_height_first,
                  "acc += vec4(texture_images[0].width_height_first);"),
        Member{"texels[0]", 0, sizeof(glm::vec4), "acc += texels[0];"},
        RT_MEMBER(GpuEnvironment, "environment", kind_image,
                  "acc += vec4(environment[0].kind_image);"),
        RT_MEMBER(GpuEnvironment, "environment", faces_px_nx_py_ny,
                  "acc += vec4(environment[0].faces_px_nx_py_ny);"),
        RT_MEMBER(GpuEnvironment, "environment", faces_pz_nz,
                  "acc += vec4(environment[0].faces_pz_nz);"),
        RT_MEMBER(GpuEnvironment, "environment", intensity_rotate_y,
                  "acc += environment[0].intensity_rotate_y;"),
        RT_MEMBER(GpuLight, "lights", position_kind, "acc += lights[0].position_kind;"),
        RT_MEMBER(GpuLight, "lights", direction, "acc += lights[0].direction;"),
        RT_MEMBER(GpuLight, "lights", intensity, "acc += lights[0].intensity;"),
        RT_MEMBER(GpuLight, "lights", attenuation, "acc += lights[0].attenuation;"),
        RT_MEMBER(BvhNode, "bvh_nodes", min, "acc.xyz += bvh_nodes[0].min;"),
        RT_MEMBER(BvhNode, "bvh_nodes", first, "acc.x += float(bvh_nodes[0].first);"),
        RT_MEMBER(BvhNode, "bvh_nodes", max, "acc.xyz += bvh_nodes[0].max;"),
        RT_MEMBER(BvhNode, "bvh_nodes", count, "acc.x += float(bvh_nodes[0].count);"),
        Member{"positions[0]", 0, sizeof(glm::vec4), "acc += positions[0];"},
        Member{"normals[0]", 0, sizeof(glm::vec4), "acc += normals[0];"},
        Member{"uvs[0]", 0, sizeof(glm::vec2), "acc.xy += uvs[0];"},
        Member{"bvh_primitives[0]", 0, sizeof(std::uint32_t), "acc.x += float(bvh_primitives[0]);"},
    };
    return list;
}
#undef RT_MEMBER

// Stage 10's uniform block SampledScene (std140) as scene_layout.glsl declares it without the
// host's defines: MAX_AREA_LIGHTS and MAX_MOVING_SPHERES 2. Offsets are from the block's start,
// where gpu::sampled_block puts each part; `stride` is checked with element [1].
const std::vector<Member>& block_members() {
    constexpr std::size_t area = sizeof(GpuSampling);
    constexpr std::size_t moving = area + 2 * sizeof(GpuAreaLight);
    static const std::vector<Member> list = {
        {"sampling.spp_filter_indirect", offsetof(GpuSampling, spp_filter_indirect), 0,
         "acc += vec4(sampling.spp_filter_indirect);"},
        {"sampling.seed_counts", offsetof(GpuSampling, seed_counts), 0,
         "acc += vec4(sampling.seed_counts);"},
        {"sampling.lens_shutter", offsetof(GpuSampling, lens_shutter), 0,
         "acc += sampling.lens_shutter;"},
        {"sampling.occlusion", offsetof(GpuSampling, occlusion), 0, "acc += sampling.occlusion;"},
        {"area_lights[0].corner_kind", area + offsetof(GpuAreaLight, corner_kind),
         sizeof(GpuAreaLight), "acc += area_lights[1].corner_kind;"},
        {"area_lights[0].edge_u", area + offsetof(GpuAreaLight, edge_u), sizeof(GpuAreaLight),
         "acc += area_lights[1].edge_u;"},
        {"area_lights[0].edge_v", area + offsetof(GpuAreaLight, edge_v), sizeof(GpuAreaLight),
         "acc += area_lights[1].edge_v;"},
        {"area_lights[0].center_radius", area + offsetof(GpuAreaLight, center_radius),
         sizeof(GpuAreaLight), "acc += area_lights[1].center_radius;"},
        {"area_lights[0].radiance", area + offsetof(GpuAreaLight, radiance), sizeof(GpuAreaLight),
         "acc += area_lights[1].radiance;"},
        {"moving_spheres[0].velocity_sphere", moving + offsetof(GpuMovingSphere, velocity_sphere),
         sizeof(GpuMovingSphere), "acc += moving_spheres[1].velocity_sphere;"},
    };
    return list;
}

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Compiles and links the layout into a compute shader; "" on success, else the driver's log.
std::string build_program(GLuint& program) {
    std::string source = "#version 430\n" + shader_prelude() + "layout(local_size_x = 1) in;\n" +
                         read_file(source_dir() / "shaders/scene_layout.glsl") +
                         read_file(source_dir() / "shaders/scene_buffers.glsl") +
                         "layout(std430, binding = RT_BINDING_OUTPUT) writeonly buffer Out { vec4 "
                         "result; };\n"
                         "void main() {\n    vec4 acc = vec4(0);\n";
    for (const Member& m : members()) source += std::string("    ") + m.use + "\n";
    for (const Member& m : block_members()) source += std::string("    ") + m.use + "\n";
    source += "    result = acc;\n}\n";
    const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    char log[4096] = {};
    if (!ok) {
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        return std::string("compile: ") + log;
    }
    program = glCreateProgram();
    glAttachShader(program, shader);
    glLinkProgram(program);
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        glGetProgramInfoLog(program, sizeof log, nullptr, log);
        return std::string("link: ") + log;
    }
    return "";
}

TEST(GpuLayout, GlslOffsetsAndStridesMatchTheCppStructs) {
    EglContext gl;
    ASSERT_TRUE(gl.ok()) << gl.error();
    GLuint program = 0;
    const std::string problem = build_program(program);
    ASSERT_EQ(problem, "") << "shaders/scene_layout.glsl and scene_buffers.glsl do not build";
    for (const Member& m : members()) {
        const GLuint index = glGetProgramResourceIndex(program, GL_BUFFER_VARIABLE, m.name);
        ASSERT_NE(index, GL_INVALID_INDEX) << m.name << " is not an active buffer variable";
        // Arrays of structs have a top-level stride; a plain array (positions[]) its own.
        const GLenum properties[] = {GL_OFFSET, GL_TOP_LEVEL_ARRAY_STRIDE, GL_ARRAY_STRIDE};
        GLint values[3] = {-1, -1, -1};
        glGetProgramResourceiv(program, GL_BUFFER_VARIABLE, index, 3, properties, 3, nullptr,
                               values);
        if (values[1] == 0) values[1] = values[2];
        EXPECT_EQ(std::size_t(values[0]), m.offset)
            << m.name << ": GLSL puts it at byte " << values[0] << ", the C++ struct at "
            << m.offset
            << " (change framework/gpu/gpu_scene.h and shaders/scene_layout.glsl together)";
        EXPECT_EQ(std::size_t(values[1]), m.stride)
            << m.name << ": GLSL's array stride is " << values[1] << ", sizeof in C++ " << m.stride;
    }
    // The uniform block: each member's offset, and an array's stride as element [1] - [0].
    for (const Member& m : block_members()) {
        auto offset_of = [&](const std::string& name) {
            const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, name.c_str());
            EXPECT_NE(index, GL_INVALID_INDEX) << name << " is not an active uniform";
            const GLenum property = GL_OFFSET;
            GLint value = -1;
            if (index != GL_INVALID_INDEX)
                glGetProgramResourceiv(program, GL_UNIFORM, index, 1, &property, 1, nullptr,
                                       &value);
            return value;
        };
        const GLint offset = offset_of(m.name);
        EXPECT_EQ(std::size_t(offset), m.offset)
            << m.name << ": GLSL puts it at byte " << offset << " of SampledScene, "
            << "gpu::sampled_block at " << m.offset;
        if (m.stride == 0) continue;
        std::string second = m.name;
        second.replace(second.find("[0]"), 3, "[1]");
        EXPECT_EQ(std::size_t(offset_of(second) - offset), m.stride)
            << m.name << ": GLSL's array stride differs from sizeof in C++ (" << m.stride << ")";
    }
    // Each storage block and the uniform block at the binding the host binds its buffer to.
    const std::pair<GLenum, std::pair<const char*, int>> blocks[] = {
        {GL_SHADER_STORAGE_BLOCK, {"Spheres", kSpheres}},
        {GL_SHADER_STORAGE_BLOCK, {"Planes", kPlanes}},
        {GL_SHADER_STORAGE_BLOCK, {"Boxes", kBoxes}},
        {GL_SHADER_STORAGE_BLOCK, {"Triangles", kTriangles}},
        {GL_SHADER_STORAGE_BLOCK, {"Positions", kPositions}},
        {GL_SHADER_STORAGE_BLOCK, {"Normals", kNormals}},
        {GL_SHADER_STORAGE_BLOCK, {"Uvs", kUvs}},
        {GL_SHADER_STORAGE_BLOCK, {"Materials", kMaterials}},
        {GL_SHADER_STORAGE_BLOCK, {"Lights", kLights}},
        {GL_SHADER_STORAGE_BLOCK, {"BvhNodes", kBvhNodes}},
        {GL_SHADER_STORAGE_BLOCK, {"BvhPrimitives", kBvhPrimitives}},
        {GL_SHADER_STORAGE_BLOCK, {"Textures", kTextures}},
        {GL_SHADER_STORAGE_BLOCK, {"TextureImages", kTextureImages}},
        {GL_SHADER_STORAGE_BLOCK, {"Texels", kTexels}},
        {GL_SHADER_STORAGE_BLOCK, {"Environments", kEnvironment}},
        {GL_SHADER_STORAGE_BLOCK, {"Out", kOutputBinding}},
        {GL_UNIFORM_BLOCK, {"SampledScene", kSampledSceneBinding}}};
    for (const auto& [interface, block] : blocks) {
        const GLuint index = glGetProgramResourceIndex(program, interface, block.first);
        ASSERT_NE(index, GL_INVALID_INDEX) << block.first << " is not an active block";
        const GLenum property = GL_BUFFER_BINDING;
        GLint binding = -1;
        glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &binding);
        EXPECT_EQ(binding, block.second) << block.first << " is at binding " << binding
                                         << "; the host binds its buffer at " << block.second;
    }
    glDeleteProgram(program);
}

// Whether `text` has "binding = <digit>" (spaces optional).
bool binds_by_number(const std::string& text) {
    for (std::size_t at = text.find("binding"); at != std::string::npos;
         at = text.find("binding", at + 1)) {
        std::size_t i = at + 7;
        while (i < text.size() && text[i] == ' ') ++i;
        if (i >= text.size() || text[i] != '=') continue;
        ++i;
        while (i < text.size() && text[i] == ' ') ++i;
        if (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) return true;
    }
    return false;
}

// The names N of every "const int kN =" in `text`.
std::vector<std::string> declared_int_constants(const std::string& text) {
    std::vector<std::string> names;
    for (std::size_t at = text.find("const int k"); at != std::string::npos;
         at = text.find("const int k", at + 1)) {
        std::size_t end = at + 10;
        while (end < text.size() && std::isalnum(static_cast<unsigned char>(text[end]))) ++end;
        std::size_t i = end;
        while (i < text.size() && text[i] == ' ') ++i;
        if (i < text.size() && text[i] == '=') names.push_back(text.substr(at + 10, end - at - 10));
    }
    return names;
}

// The numbers C++ and GLSL share are written into the shaders by gpu/shader_constants.cpp: no
// GLSL file of the framework or of a stage declares one of them again, or binds a block by a
// number of its own.
TEST(GpuLayout, SharedNumbersHaveOneHome) {
    const std::string prelude = shader_prelude();
    int files = 0;
    for (const char* folder : {"shaders", "stages/09-gpu", "stages/10-sampling"})
        for (const auto& entry : std::filesystem::directory_iterator(source_dir() / folder)) {
            const std::string ext = entry.path().extension().string();
            if (ext != ".glsl" && ext != ".comp") continue;
            ++files;
            const std::string text = read_file(entry.path());
            EXPECT_FALSE(binds_by_number(text))
                << entry.path() << " binds a block by number: use RT_BINDING_* (the prelude's)";
            for (const std::string& name : declared_int_constants(text))
                EXPECT_EQ(prelude.find(" " + name + " = "), std::string::npos)
                    << entry.path() << " declares " << name
                    << ", which gpu/shader_constants.cpp already writes into every shader";
        }
    EXPECT_GT(files, 10);
}

TEST(GpuLayout, PackKeepsEveryValue) {
    PreparedScene scene;
    scene.spheres.push_back(Sphere{Vec3(1, 2, 3), Real(0.5), 2});
    scene.planes.push_back(Plane{Vec3(0, -1, 0), Vec3(0, 1, 0), 1});
    scene.boxes.push_back(Box{Vec3(-1), Vec3(1), 3});
    scene.vertices = {Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    scene.triangles.push_back(Triangle{{0, 1, 2}, 4});
    Material m;
    m.specular = Color(0.25f);
    m.shininess = 64;
    m.transmissive = Color(0.5f);
    m.ior = 1.33f;
    scene.materials.push_back(m);
    Light l;
    l.kind = LightKind::Directional;
    l.direction = Vec3(0, -1, 0);
    l.intensity = Color(2);
    scene.lights.push_back(l);
    const GpuScene g = pack_scene(scene);
    EXPECT_EQ(g.spheres[0].center_radius, glm::vec4(1, 2, 3, 0.5f));
    EXPECT_EQ(g.spheres[0].material.x, 2);
    EXPECT_EQ(g.planes[0].point_material.w, int_bits(1));
    EXPECT_EQ(g.boxes[0].min_material.w, int_bits(3));
    EXPECT_EQ(g.triangles[0].vertices_material, glm::uvec4(0, 1, 2, 4));
    EXPECT_EQ(g.positions[2], glm::vec4(0, 1, 0, 1));
    EXPECT_EQ(g.materials[0].specular_shininess, glm::vec4(0.25f, 0.25f, 0.25f, 64));
    EXPECT_EQ(g.materials[0].transmissive_ior.w, 1.33f);
    EXPECT_EQ(g.lights[0].position_kind.w, int_bits(1));
    // w: the light's links, every material reached (the scene's one: mask 1) and shadows cast.
    EXPECT_EQ(g.lights[0].intensity,
              glm::vec4(2, 2, 2, int_bits(kLightReachRest | kLightCastsShadows)));
    EXPECT_EQ(g.lights[0].direction.w, int_bits(1));
    EXPECT_EQ(g.materials[0].maps, glm::ivec4(-1));

    // Textures: the slots, the table, the images and the texels.
    scene.materials[0].normal_map = TextureSlot{0, {2, 3}, {0.5f, 0.25f}};
    Texture t;
    t.kind = TextureKind::Image;
    t.image = 0;
    t.wrap = TextureWrap::Mirror;
    t.srgb = true;
    scene.textures.push_back(t);
    scene.texture_images.push_back(TextureImage{2, 1, 0});
    scene.texels = {Color(0.25f), Color(1, 0, 0)};
    const GpuScene h = pack_scene(scene);
    EXPECT_EQ(h.materials[0].maps, glm::ivec4(-1, -1, -1, 0));
    EXPECT_EQ(h.materials[0].map_transform[3], glm::vec4(2, 3, 0.5f, 0.25f));
    EXPECT_EQ(h.textures[0].kind_image_filter_wrap,
              glm::ivec4(int(TextureKind::Image), 0, int(TextureFilter::Bilinear),
                         int(TextureWrap::Mirror)));
    EXPECT_EQ(h.textures[0].a_srgb.w, 1.0f);
    EXPECT_EQ(h.texture_images[0].width_height_first, glm::ivec4(2, 1, 0, 0));
    EXPECT_EQ(h.texels[1], glm::vec4(1, 0, 0, 1));

    // The environment: always one entry, kind None without one.
    ASSERT_EQ(h.environment.size(), 1u);
    EXPECT_EQ(h.environment[0].kind_image, glm::ivec4(int(EnvironmentKind::None), -1, 0, 0));
    scene.environment.kind = EnvironmentKind::CubeMap;
    for (int f = 0; f < kCubeFaces; ++f) scene.environment.faces[f] = 10 + f;
    scene.environment.intensity = 2.5f;
    scene.environment.rotate_y = -30;
    const GpuScene e = pack_scene(scene);
    EXPECT_EQ(e.environment[0].kind_image.x, int(EnvironmentKind::CubeMap));
    EXPECT_EQ(e.environment[0].faces_px_nx_py_ny, glm::ivec4(10, 11, 12, 13));
    EXPECT_EQ(e.environment[0].faces_pz_nz, glm::ivec4(14, 15, 0, 0));
    EXPECT_EQ(e.environment[0].intensity_rotate_y, glm::vec4(2.5f, -30, 0, 0));

    // Stage 10: fuzz, area lights, moving spheres, the settings, and the uniform block's bytes.
    scene.materials[0].fuzz = 0.25f;
    AreaLight rect;
    rect.corner = Vec3(-1, 3, -1);
    rect.edge_u = Vec3(2, 0, 0);
    rect.edge_v = Vec3(0, 0, 2);
    rect.radiance = Color(9, 8, 7);
    AreaLight ball;
    ball.kind = AreaLightKind::Sphere;
    ball.center = Vec3(1, 2, 3);
    ball.radius = Real(0.5);
    scene.area_lights = {rect, ball};
    scene.moving_spheres.push_back(MovingSphere{0, Vec3(1, 0, 0)});
    scene.sampling.samples_per_pixel = 16;
    scene.sampling.seed = 0x100000002ull;
    scene.sampling.filter = PixelFilter::Tent;
    scene.sampling.indirect = IndirectLight::Diffuse;
    scene.sampling.aperture = Real(0.3);
    scene.sampling.focus_distance = 5;
    scene.sampling.shutter_open = 0;
    scene.sampling.shutter_close = 1;
    scene.sampling.occlusion_distance = Real(1.5);
    const GpuScene s = pack_scene(scene);
    EXPECT_EQ(s.materials[0].reflective.w, 0.25f);
    ASSERT_EQ(s.area_lights.size(), 2u);
    EXPECT_EQ(s.area_lights[0].corner_kind, glm::vec4(-1, 3, -1, int_bits(0)));
    EXPECT_EQ(s.area_lights[0].edge_v, glm::vec4(0, 0, 2, 0));
    EXPECT_EQ(s.area_lights[0].radiance, glm::vec4(9, 8, 7, 0));
    EXPECT_EQ(s.area_lights[1].corner_kind.w, int_bits(1));
    EXPECT_EQ(s.area_lights[1].center_radius, glm::vec4(1, 2, 3, 0.5f));
    ASSERT_EQ(s.moving_spheres.size(), 1u);
    EXPECT_EQ(s.moving_spheres[0].velocity_sphere, glm::vec4(1, 0, 0, int_bits(0)));
    EXPECT_EQ(s.sampling.spp_filter_indirect,
              glm::ivec4(16, int(PixelFilter::Tent), int(IndirectLight::Diffuse), 0));
    EXPECT_EQ(s.sampling.seed_counts, glm::uvec4(2, 1, 2, 1));
    EXPECT_EQ(s.sampling.lens_shutter, glm::vec4(0.3f, 5, 0, 1));
    EXPECT_EQ(s.sampling.occlusion.x, 1.5f);
    const std::vector<unsigned char> block = sampled_block(s, 3, 2);
    ASSERT_EQ(block.size(),
              sizeof(GpuSampling) + 3 * sizeof(GpuAreaLight) + 2 * sizeof(GpuMovingSphere));
    GpuAreaLight second;
    std::memcpy(&second, block.data() + sizeof(GpuSampling) + sizeof(GpuAreaLight), sizeof second);
    EXPECT_EQ(second.center_radius, glm::vec4(1, 2, 3, 0.5f));
    GpuMovingSphere moving;
    std::memcpy(&moving, block.data() + sizeof(GpuSampling) + 3 * sizeof(GpuAreaLight),
                sizeof moving);
    EXPECT_EQ(moving.velocity_sphere.x, 1.0f);
}

}  // namespace
}  // namespace rt::gpu
