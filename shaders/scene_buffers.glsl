// The packed scene in storage buffers (std430, the structs of scene_layout.glsl), as the GPU unit
// tests' intersect_cases.comp and Framework.GpuLayout read it, with each array's accessor.
//
// Every shader reads element i of the scene's array `name` as name_at(i), for an int or a uint
// i, whatever holds the array: here a storage buffer; in trace.comp a buffer texture over the
// same buffer (texel_arrays.glsl); in rt export-shadertoy a constant array; in rt export-web a
// data texture (framework/render/gpu/web_arrays.cpp). The stage 09 code is the same for all four.
#ifdef HAS_MOTION_BLUR
// The spheres at time 0; spheres_at reads the invocation's moved copy (compute_io.glsl).
layout(std430, binding = RT_BINDING_SPHERES) readonly buffer Spheres { Sphere spheres_at_rest[]; };
#else
layout(std430, binding = RT_BINDING_SPHERES) readonly buffer Spheres { Sphere spheres[]; };
#endif
layout(std430, binding = RT_BINDING_PLANES) readonly buffer Planes { Plane planes[]; };
layout(std430, binding = RT_BINDING_BOXES) readonly buffer Boxes { Box boxes[]; };
layout(std430, binding = RT_BINDING_TRIANGLES) readonly buffer Triangles { Triangle triangles[]; };
layout(std430, binding = RT_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = RT_BINDING_NORMALS) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = RT_BINDING_UVS) readonly buffer Uvs { vec2 uvs[]; };
layout(std430, binding = RT_BINDING_MATERIALS) readonly buffer Materials { Material materials[]; };
layout(std430, binding = RT_BINDING_LIGHTS) readonly buffer Lights { Light lights[]; };
layout(std430, binding = RT_BINDING_BVH_NODES) readonly buffer BvhNodes { BvhNode bvh_nodes[]; };
layout(std430, binding = RT_BINDING_BVH_PRIMITIVES) readonly buffer BvhPrimitives { uint bvh_primitives[]; };
layout(std430, binding = RT_BINDING_TEXTURES) readonly buffer Textures { Texture textures[]; };
layout(std430, binding = RT_BINDING_TEXTURE_IMAGES) readonly buffer TextureImages { TextureImage texture_images[]; };
layout(std430, binding = RT_BINDING_TEXELS) readonly buffer Texels { vec4 texels[]; };
layout(std430, binding = RT_BINDING_ENVIRONMENT) readonly buffer Environments { Environment environment[]; };

// name_at(i) for an array `name` of `Type`s held in a GLSL array, for int and uint indices.
#define RT_ARRAY_ACCESSORS(Type, name) \
    Type name##_at(int i) { return name[i]; } \
    Type name##_at(uint i) { return name[i]; }

#ifndef HAS_MOTION_BLUR
RT_ARRAY_ACCESSORS(Sphere, spheres)
#endif
RT_ARRAY_ACCESSORS(Plane, planes)
RT_ARRAY_ACCESSORS(Box, boxes)
RT_ARRAY_ACCESSORS(Triangle, triangles)
RT_ARRAY_ACCESSORS(vec4, positions)
RT_ARRAY_ACCESSORS(vec4, normals)
RT_ARRAY_ACCESSORS(vec2, uvs)
RT_ARRAY_ACCESSORS(Material, materials)
RT_ARRAY_ACCESSORS(Light, lights)
RT_ARRAY_ACCESSORS(BvhNode, bvh_nodes)
RT_ARRAY_ACCESSORS(uint, bvh_primitives)
RT_ARRAY_ACCESSORS(Texture, textures)
RT_ARRAY_ACCESSORS(TextureImage, texture_images)
RT_ARRAY_ACCESSORS(vec4, texels)
RT_ARRAY_ACCESSORS(Environment, environment)
