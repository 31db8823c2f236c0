// trace.comp's accessors (scene_buffers.glsl says what they are): the scene's arrays read by
// texel fetches from buffer textures over the very storage buffers (one texture unit each, at the
// storage buffer's binding: gpu_render.cpp's texel_views). This form is llvmpipe's: it loads a
// storage buffer's word one invocation at a time but a texel for all eight lanes at once, which
// took the BVH mesh scene from 1.10 to 1.37-1.46 Mrays/s (rt-bench gpu, large_icosphere;
// docs/performance-log.md, 2026-12-05). Every texel is four words (RGBA32UI) but the BVH's
// primitive indices' (R32UI) and uvs' (RG32UI).
#ifdef HAS_MOTION_BLUR
// The spheres at time 0; spheres_at reads the invocation's moved copy (compute_io.glsl).
layout(std430, binding = RT_BINDING_SPHERES) readonly buffer Spheres { Sphere spheres_at_rest[]; };
#else
layout(binding = RT_BINDING_SPHERES) uniform highp usamplerBuffer rt_texels_spheres;
#endif
layout(binding = RT_BINDING_PLANES) uniform highp usamplerBuffer rt_texels_planes;
layout(binding = RT_BINDING_BOXES) uniform highp usamplerBuffer rt_texels_boxes;
layout(binding = RT_BINDING_TRIANGLES) uniform highp usamplerBuffer rt_texels_triangles;
layout(binding = RT_BINDING_POSITIONS) uniform highp usamplerBuffer rt_texels_positions;
layout(binding = RT_BINDING_NORMALS) uniform highp usamplerBuffer rt_texels_normals;
layout(binding = RT_BINDING_UVS) uniform highp usamplerBuffer rt_texels_uvs;
layout(binding = RT_BINDING_MATERIALS) uniform highp usamplerBuffer rt_texels_materials;
layout(binding = RT_BINDING_LIGHTS) uniform highp usamplerBuffer rt_texels_lights;
layout(binding = RT_BINDING_BVH_NODES) uniform highp usamplerBuffer rt_texels_bvh_nodes;
layout(binding = RT_BINDING_BVH_PRIMITIVES) uniform highp usamplerBuffer rt_texels_bvh_primitives;
layout(binding = RT_BINDING_TEXTURES) uniform highp usamplerBuffer rt_texels_textures;
layout(binding = RT_BINDING_TEXTURE_IMAGES) uniform highp usamplerBuffer rt_texels_texture_images;
layout(binding = RT_BINDING_TEXELS) uniform highp usamplerBuffer rt_texels_texels;
layout(binding = RT_BINDING_ENVIRONMENT) uniform highp usamplerBuffer rt_texels_environment;

// Texel k of element i of an array whose elements are `size` texels.
#define RT_TEXEL(array, size, i, k) texelFetch(rt_texels_##array, (size) * int(i) + (k))
#define RT_VEC4(array, size, i, k) uintBitsToFloat(RT_TEXEL(array, size, i, k))
#define RT_IVEC4(array, size, i, k) ivec4(RT_TEXEL(array, size, i, k))

#ifndef HAS_MOTION_BLUR
Sphere spheres_at(int i) { return Sphere(RT_VEC4(spheres, 2, i, 0), RT_IVEC4(spheres, 2, i, 1)); }
#endif
Plane planes_at(int i) { return Plane(RT_VEC4(planes, 2, i, 0), RT_VEC4(planes, 2, i, 1)); }
Box boxes_at(int i) { return Box(RT_VEC4(boxes, 2, i, 0), RT_VEC4(boxes, 2, i, 1)); }
Triangle triangles_at(int i) { return Triangle(RT_TEXEL(triangles, 1, i, 0)); }
vec4 positions_at(int i) { return RT_VEC4(positions, 1, i, 0); }
vec4 normals_at(int i) { return RT_VEC4(normals, 1, i, 0); }
vec2 uvs_at(int i) { return uintBitsToFloat(RT_TEXEL(uvs, 1, i, 0).xy); }
Material materials_at(int i) {
    const vec4 transform[4] = vec4[4](RT_VEC4(materials, 11, i, 7), RT_VEC4(materials, 11, i, 8),
                                      RT_VEC4(materials, 11, i, 9), RT_VEC4(materials, 11, i, 10));
    return Material(RT_VEC4(materials, 11, i, 0), RT_VEC4(materials, 11, i, 1),
                    RT_VEC4(materials, 11, i, 2), RT_VEC4(materials, 11, i, 3),
                    RT_VEC4(materials, 11, i, 4), RT_VEC4(materials, 11, i, 5),
                    RT_IVEC4(materials, 11, i, 6), transform);
}
Light lights_at(int i) {
    return Light(RT_VEC4(lights, 4, i, 0), RT_VEC4(lights, 4, i, 1), RT_VEC4(lights, 4, i, 2),
                 RT_VEC4(lights, 4, i, 3));
}
BvhNode bvh_nodes_at(int i) {
    const uvec4 a = RT_TEXEL(bvh_nodes, 2, i, 0), b = RT_TEXEL(bvh_nodes, 2, i, 1);
    return BvhNode(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz), b.w);
}
uint bvh_primitives_at(int i) { return RT_TEXEL(bvh_primitives, 1, i, 0).x; }
Texture textures_at(int i) {
    return Texture(RT_IVEC4(textures, 3, i, 0), RT_VEC4(textures, 3, i, 1),
                   RT_VEC4(textures, 3, i, 2));
}
TextureImage texture_images_at(int i) { return TextureImage(RT_IVEC4(texture_images, 1, i, 0)); }
vec4 texels_at(int i) { return RT_VEC4(texels, 1, i, 0); }
Environment environment_at(int i) {
    return Environment(RT_IVEC4(environment, 4, i, 0), RT_IVEC4(environment, 4, i, 1),
                       RT_IVEC4(environment, 4, i, 2), RT_VEC4(environment, 4, i, 3));
}

// The stage 09 code indexes with uints too.
#ifndef HAS_MOTION_BLUR
Sphere spheres_at(uint i) { return spheres_at(int(i)); }
#endif
Plane planes_at(uint i) { return planes_at(int(i)); }
Box boxes_at(uint i) { return boxes_at(int(i)); }
Triangle triangles_at(uint i) { return triangles_at(int(i)); }
vec4 positions_at(uint i) { return positions_at(int(i)); }
vec4 normals_at(uint i) { return normals_at(int(i)); }
vec2 uvs_at(uint i) { return uvs_at(int(i)); }
Material materials_at(uint i) { return materials_at(int(i)); }
Light lights_at(uint i) { return lights_at(int(i)); }
BvhNode bvh_nodes_at(uint i) { return bvh_nodes_at(int(i)); }
uint bvh_primitives_at(uint i) { return bvh_primitives_at(int(i)); }
Texture textures_at(uint i) { return textures_at(int(i)); }
TextureImage texture_images_at(uint i) { return texture_images_at(int(i)); }
vec4 texels_at(uint i) { return texels_at(int(i)); }
Environment environment_at(uint i) { return environment_at(int(i)); }
