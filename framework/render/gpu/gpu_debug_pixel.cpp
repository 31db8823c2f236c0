#include "render/gpu/gpu_debug_pixel.h"

#include <cstdio>
#include <fstream>

#include "core/source_dir.h"
#include "gpu/shader_constants.h"
#include "render/ray_tree.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

using namespace gpu;  // the notes' kinds, kDebug* (gpu/shader_constants.h)

std::string fmt(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string fmt(const glm::vec4& v, int n) {
    std::string s = n > 1 ? "(" : "";
    for (int i = 0; i < n; ++i) s += (i ? ", " : "") + fmt(double(v[i]));
    return s + (n > 1 ? ")" : "");
}

// Line `line` of `file` (a path as messages show it), without its indentation.
std::string source_line(const std::string& file, int line) {
    fs::path path(file);
    if (path.is_relative()) path = source_dir() / path;
    std::ifstream in(path);
    std::string text;
    for (int i = 0; i < line && std::getline(in, text); ++i) {
    }
    const std::size_t start = text.find_first_not_of(" \t");
    return start == std::string::npos ? "" : text.substr(start);
}

// A student's rt_debug: "rt_debug at FILE:LINE `text`: value".
std::string value_line(const GpuDebugRecord& r, const AssembledShader& shader) {
    const ShaderLocation at = shader_location(r.where, shader.files);
    std::string value;
    switch (r.type) {
        case 4:  // int, as its high and low 16 bits
            value = std::to_string(int(r.value.x) * 65536 + int(r.value.y));
            break;
        case 5:
            value = r.value.x != 0 ? "true" : "false";
            break;
        default:
            value = fmt(r.value, r.type + 1);
    }
    return "rt_debug at " + at.file + ":" + std::to_string(at.line) + " `" +
           source_line(at.file, at.line) + "`: " + value;
}

// One note as a line of the tree; the empty string for the notes another line includes.
std::string note_line(const PreparedScene& scene, const GpuDebugRecord& r,
                      const GpuDebugRecord* next) {
    static const char* const kRayNames[] = {"camera", "reflection", "refraction"};
    const int n3 = 3;
    switch (r.kind) {
        case kDebugRay: {
            const int branch = int(r.value.w);
            std::string line = std::string(kRayNames[branch >= 0 && branch < 3 ? branch : 0]) +
                               " ray (depth " + std::to_string(r.where) + ") from " +
                               fmt(r.value, n3);
            if (next && next->kind == kDebugDirection) line += " dir " + fmt(next->value, n3);
            return line;
        }
        case kDebugHit: {
            const int id = (int(r.value.y) << 28) | int(r.value.z);
            std::string line = "hit t = " + fmt(double(r.value.x));
            if (next && next->kind == kDebugPoint) line += " at " + fmt(next->value, n3);
            return line + " on " + primitive_name(scene, id) + ", material " +
                   material_name(scene, int(r.value.w)) + (r.type == 1 ? ", outside" : ", inside");
        }
        case kDebugNormal:
            return "lighting normal " + fmt(r.value, n3);
        case kDebugMiss:
            return "miss: background " + fmt(r.value, n3);
        case kDebugShadow:
            return "shadow ray to light " + std::to_string(r.where) + ": visibility " +
                   fmt(r.value, n3);
        case kDebugLocal:
            return "local light " + fmt(r.value, n3);
        case kDebugReflected:
        case kDebugRefracted:
            if (r.value.w == 0 && r.value.x == 0 && r.value.y == 0 && r.value.z == 0) return "";
            return std::string(r.kind == kDebugReflected ? "reflection" : "refraction") +
                   " weight " + fmt(r.value, n3) + (r.value.w != 0 ? "" : " (not traced)");
        case kDebugSample:
            return "camera sample " + std::to_string(r.where) + " at image point " +
                   fmt(r.value, 2);
        case kDebugPixel:
            return "pixel value " + fmt(r.value, r.value.w == -2 ? 4 : 3) +
                   (r.value.w == -2 ? " (a stub was reached: magenta)" : "");
    }
    return "";  // kDebugDirection and kDebugPoint are part of the line before them
}

// A ray at depth d is indented 4d, what happened to it 4d + 2, as in the CPU's tree.
int indent(int kind, int depth) {
    if (kind == kDebugPixel || kind == kDebugSample || depth < 0) return 0;
    return 4 * depth + (kind == kDebugRay ? 0 : 2);
}

}  // namespace

void read_gpu_probe(const std::vector<glm::vec4>& output, std::size_t pixel_count,
                    const AssembledShader& shader, GpuPixelProbe& probe) {
    // output[0] holds the stub flags; the shader's pixels[k] is output[k + 1].
    const std::size_t header = pixel_count + 1;
    probe.made = int(output[header].x);
    probe.records.clear();
    for (int k = 0; k < probe.made && k < kDebugCapacity; ++k) {
        const glm::vec4 tag = output[header + 1 + 2 * std::size_t(k)];
        probe.records.push_back(
            {int(tag.x), int(tag.y), int(tag.z), output[header + 2 + 2 * std::size_t(k)]});
    }
    probe.shader = shader;
}

GpuPixelProbe debug_pixel_gpu(const PreparedScene& scene, RenderMode mode, int x, int y,
                              const GpuRenderOptions& options) {
    GpuPixelProbe probe;
    probe.x = x;
    probe.y = y;
    GpuRenderer renderer(options);
    renderer.render(scene, mode, nullptr, &probe);
    return probe;
}

std::string gpu_pixel_text(const PreparedScene& scene, const GpuPixelProbe& probe) {
    std::string text = "pixel (" + std::to_string(probe.x) + ", " + std::to_string(probe.y) +
                       ") on the GPU: what the shader computed, in the order it did\n";
    int depth = -1;  // the last ray's: its notes are indented under it
    const auto& records = probe.records;
    for (std::size_t i = 0; i < records.size(); ++i) {
        const GpuDebugRecord& r = records[i];
        if (r.kind == kDebugRay) depth = r.where;
        const GpuDebugRecord* next = i + 1 < records.size() ? &records[i + 1] : nullptr;
        const std::string line =
            r.kind == kDebugValue ? value_line(r, probe.shader) : note_line(scene, r, next);
        if (line.empty()) continue;
        text += std::string(std::size_t(indent(r.kind, depth)), ' ') + line + "\n";
    }
    if (probe.made > kDebugCapacity)
        text += "(" + std::to_string(probe.made - kDebugCapacity) +
                " more notes were made; the first " + std::to_string(kDebugCapacity) +
                " are shown)\n";
    if (probe.made == 0) text += "(no notes: the shader did not reach this pixel)\n";
    return text;
}

}  // namespace rt
