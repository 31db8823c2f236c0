// The framework's texturing step and background, as framework/render/texturing.cpp and
// framework/render/background.cpp do them on the CPU, over the student's stage 07-08 GLSL.
// Only nearest and bilinear lookups (texture_lookup, set by the host, may force one for every
// image): --texture-filter oiio has no GPU port (render_gpu says so).

#ifdef HAS_MAPS
// The vertex uvs of a triangle; (0, 0), (1, 0), (0, 1) when the scene has none.
void triangle_vertex_uvs(int triangle, out vec2 a, out vec2 b, out vec2 c) {
    a = vec2(0, 0);
    b = vec2(1, 0);
    c = vec2(0, 1);
#ifdef HAS_VERTEX_UVS
    if (!scene_has(kFeatureVertexUvs)) return;
    const uvec4 v = triangles_at(triangle).vertices_material;
    a = uvs_at(v.x);
    b = uvs_at(v.y);
    c = uvs_at(v.z);
#endif
}

vec2 surface_texcoord(Hit hit, SurfacePoint at) {
    const int i = primitive_index(hit.primitive);
    switch (primitive_kind(hit.primitive)) {
        case kSphere:
            return sphere_texcoord(normalize(at.point - spheres_at(i).center_radius.xyz));
        case kPlane:
            return plane_texcoord(planes_at(i).point_material.xyz, planes_at(i).normal.xyz, at.point);
        case kBox:
            return box_texcoord(boxes_at(i).min_material.xyz, boxes_at(i).max.xyz, at.point,
                                at.front_face ? at.normal : -at.normal);
        case kTriangle: {
            vec2 a, b, c;
            triangle_vertex_uvs(i, a, b, c);
            return triangle_texcoord(a, b, c, hit.uv);
        }
    }
    return vec2(0);
}

#ifdef HAS_NORMAL_MAPS
// The tangent along +u: spheres along increasing longitude, planes and boxes their frame's t,
// triangles dP/du from the vertex uvs; any perpendicular where that is degenerate.
vec3 surface_tangent(Hit hit, SurfacePoint at) {
    const vec3 outward = at.front_face ? at.normal : -at.normal;
    const int i = primitive_index(hit.primitive);
    switch (primitive_kind(hit.primitive)) {
        case kSphere: {
            const vec3 t = vec3(outward.z, 0, -outward.x);
            const float t_length = length(t);
            return t_length > 1e-6 ? t / t_length : vec3(1, 0, 0);  // poles: any
        }
        case kPlane:
            return plane_frame(planes_at(i).normal.xyz).t;
        case kBox:
            return plane_frame(outward).t;
        case kTriangle: {
            vec3 p0, p1, p2;
            triangle_vertices(i, p0, p1, p2);
            vec2 a, b, c;
            triangle_vertex_uvs(i, a, b, c);
            const vec3 e1 = p1 - p0, e2 = p2 - p0;
            const vec2 d1 = b - a, d2 = c - a;
            const float det = d1.x * d2.y - d2.x * d1.y;
            if (det != 0.0) {
                const vec3 t = (e1 * d2.y - e2 * d1.y) / det;  // dP/du
                if (length(t) > 0.0) return normalize(t);
            }
            break;
        }
    }
    return plane_frame(at.normal).t;
}
#endif

// A slot's colour at uv (slot transform: xy scale, zw offset); 1 for a texture that is missing.
vec3 evaluate_slot(int slot_texture, vec4 transform, vec2 uv, vec3 point) {
    const Texture t = textures_at(slot_texture);
    const vec2 mapped = vec2(uv.x * transform.x + transform.z, uv.y * transform.y + transform.w);
    switch (t.kind_image_filter_wrap.x) {
#ifdef HAS_IMAGE_TEXTURES
        case kTextureImage: {
            if (t.kind_image_filter_wrap.y < 0) return vec3(1);
            const TextureView view = texture_view(t.kind_image_filter_wrap.y, t.a_srgb.w != 0.0);
            int image_filter = t.kind_image_filter_wrap.z;
            if (texture_lookup == kLookupNearest) image_filter = kFilterNearest;
            if (texture_lookup == kLookupBilinear) image_filter = kFilterBilinear;
            const int wrap = t.kind_image_filter_wrap.w;
            return image_filter == kFilterNearest ? sample_nearest(view, mapped, wrap)
                                            : sample_bilinear(view, mapped, wrap);
        }
#endif
#ifdef HAS_CHECKER_TEXTURES
        case kTextureChecker2D:
            return checker_2d(mapped, t.a_srgb.rgb, t.b_scale.rgb);
        case kTextureChecker3D:
            return checker_3d(point, t.a_srgb.rgb, t.b_scale.rgb, t.b_scale.w);
#endif
#ifdef HAS_NOISE_TEXTURES
        case kTextureMarble:
            return marble(point, t.a_srgb.rgb, t.b_scale.rgb, t.b_scale.w);
#endif
    }
    return vec3(1);
}

// render/texturing.cpp's apply_textures: the material as its maps colour it at this hit, and
// the normal-mapped lighting normal. A slot's texture index is -1 when unused (gpu_scene.h).
void apply_textures(Hit hit, SurfacePoint at, vec3 to_viewer, inout Material material,
                    inout vec3 lighting_normal) {
    const ivec4 maps = material.maps;
    if (maps == ivec4(-1)) return;
    const vec2 uv = surface_texcoord(hit, at);
    if (maps.x >= 0) {
        const vec3 c = evaluate_slot(maps.x, material.map_transform[0], uv, at.point);
        material.diffuse.rgb *= c;
        material.ambient.rgb *= c;  // ambient light lights the surface's own colour
    }
    if (maps.y >= 0)
        material.specular_shininess.rgb *=
            evaluate_slot(maps.y, material.map_transform[1], uv, at.point);
    if (maps.z >= 0)
        material.emissive.rgb *= evaluate_slot(maps.z, material.map_transform[2], uv, at.point);
#ifdef HAS_NORMAL_MAPS
    if (maps.w >= 0) {
        // A normal map's values as stored: the loader marks it not sRGB.
        const vec3 texel = evaluate_slot(maps.w, material.map_transform[3], uv, at.point);
        lighting_normal = normal_from_map(lighting_normal, surface_tangent(hit, at), texel,
                                          to_viewer);
    }
#endif
}
#endif  // HAS_MAPS

// What a ray that hits nothing sees (render/background.cpp).
vec3 background(vec3 direction) {
#ifdef HAS_ENVIRONMENT
    return environment_radiance(direction);
#else
    return background_color;
#endif
}
