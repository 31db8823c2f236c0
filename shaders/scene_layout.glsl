// The packed scene's structs (std430). The C++ side is framework/gpu/gpu_scene.h;
// Framework.GpuLayout.* checks the two against each other with the driver's own offsets, so change
// both together. Each array of them is read through an accessor, name_at(i) (scene_buffers.glsl).
// Integers stored in a float's bits (materials, light kinds): floatBitsToInt(x).

struct Sphere { vec4 center_radius; ivec4 material; };
struct Plane { vec4 point_material; vec4 normal; };
struct Box { vec4 min_material; vec4 max; };
struct Triangle { uvec4 vertices_material; };
struct Material {
    vec4 ambient;
    vec4 diffuse;
    vec4 specular_shininess;
    vec4 emissive;            // xyz k_e, w roughness (stage 11's GGX lobe)
    vec4 reflective;          // xyz k_r, w fuzz (stage 10's glossy reflection; 0 a mirror)
    vec4 transmissive_ior;
    ivec4 maps;               // texture of the diffuse, specular, emissive, normal slot (-1: none)
    vec4 map_transform[4];    // per slot: xy scale, zw offset
};
struct Texture { ivec4 kind_image_filter_wrap; vec4 a_srgb; vec4 b_scale; };
struct TextureImage { ivec4 width_height_first; };
// Exactly one: kind_image.x 0 none, 1 lat-long (image kind_image.y), 2 cube map (faces in
// OpenGL's order +x -x +y -y | +z -z); intensity_rotate_y.y in degrees.
struct Environment { ivec4 kind_image; ivec4 faces_px_nx_py_ny; ivec4 faces_pz_nz; vec4 intensity_rotate_y; };
struct Light { vec4 position_kind; vec4 direction; vec4 intensity; vec4 attenuation; };
struct BvhNode { vec3 min; uint first; vec3 max; uint count; };
// Stage 10. An area light: corner_kind.w (int bits) 0 rectangle (corner + s edge_u + t edge_v,
// lit on the side of cross(edge_u, edge_v)), 1 sphere (center_radius); radiance L_e.
struct AreaLight { vec4 corner_kind; vec4 edge_u; vec4 edge_v; vec4 center_radius; vec4 radiance; };
// A sphere that moves while the shutter is open: spheres[sphere] at time 0 (velocity_sphere.w,
// int bits), moving by velocity_sphere.xyz per unit of time.
struct MovingSphere { vec4 velocity_sphere; };
// The sampling settings (scene.h's SamplingSettings) and the counts of the two arrays above.
struct Sampling {
    ivec4 spp_filter_indirect;  // samples per pixel, filter (0 box, 1 tent), indirect (0 ambient,
                                // 1 occlusion, 2 diffuse), w unused
    uvec4 seed_counts;          // seed low and high 32 bits, area lights, moving spheres
    vec4 lens_shutter;          // aperture, focus distance, shutter open, shutter close
    vec4 occlusion;             // x occlusion distance (may be +inf), yzw unused
};
// The camera (set as the uniform `camera`, or baked in as a constant by rt export-shadertoy).
struct Camera {
    int projection;  // kProjectionPerspective or kProjectionOrthographic
    vec3 eye, u, v, w;  // u right, v up, the camera looks along -w
    float vertical_fov_degrees;
    float view_height;
};

// Stage 10's data is a uniform block (std140, the same offsets as std430 here: vec4s only): the
// compute stage has 16 storage blocks and the uber shader uses them all. Sized by the host's
// defines; the defaults serve the layout test and shaders without sampling.
#ifndef MAX_AREA_LIGHTS
#define MAX_AREA_LIGHTS 2
#endif
#ifndef MAX_MOVING_SPHERES
#define MAX_MOVING_SPHERES 2
#endif
layout(std140, binding = RT_BINDING_SAMPLED_SCENE) uniform SampledScene { Sampling sampling; AreaLight area_lights[MAX_AREA_LIGHTS]; MovingSphere moving_spheres[MAX_MOVING_SPHERES]; };
