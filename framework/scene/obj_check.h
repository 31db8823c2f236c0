// The checking pass over an OBJ file: what tinyobjloader would misread or drop, reported with
// the line, and what the loader needs to know before tinyobjloader reads the file.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scene/obj_loader.h"

namespace rt::obj_internal {

struct MaterialLibrary {
    std::size_t line;  // of its mtllib line
    std::string file;  // as written
};

// What the checking pass learns about the file before tinyobjloader reads it.
struct ObjSummary {
    std::vector<std::size_t> vertex_lines;  // line of each "v", in order
    long long normal_count = 0, uv_count = 0;
    std::vector<ObjMaterial> materials;  // distinct "usemtl" names, first use first
    std::vector<MaterialLibrary> libraries;
    bool usemtl_before_mtllib = false;  // tinyobjloader only honours usemtl after mtllib
    std::size_t triangle_count = 0;     // after triangulation
    // First face line naming a "vt" / "vn" index in a file that has no such line at all: some
    // exporters write "f 1/1/1 ..." regardless. Those indices are ignored (with a warning).
    std::size_t dangling_uv_line = 0, dangling_normal_line = 0;
};

// tinyobjloader silently turns unparsable coordinates into 0 and keeps out-of-range face
// indices, so check what it would misread, while the line numbers are still known. Throws
// ObjError.
ObjSummary check_obj_text(const std::string& text, const std::string& name);

// Turns the lines a triangle mesh does not need into comments, keeping the line count:
// tinyobjloader's extensions ("t" tags, "vw" skin weights) size arrays from unchecked numbers in
// the file, and "l" (polylines) and "p" (points) are not surfaces.
void comment_out_unused_lines(std::string& text);

// tinyobjloader reads a usemtl name up to the first blank, but names may hold spaces: the text
// with every "usemtl NAME" replaced by "usemtl rt-material-I" (I: NAME's index in `materials`),
// line count unchanged, and the token of index I.
std::string with_material_tokens(const std::string& text,
                                 const std::vector<ObjMaterial>& materials);
std::string material_token(std::size_t index);

}  // namespace rt::obj_internal
