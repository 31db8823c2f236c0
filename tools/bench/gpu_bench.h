// `rt-bench gpu` (issue 14): camera rays a second of stage 09's compute shader (and of stage
// 10's sampled path) on this machine's OpenGL (llvmpipe without a GPU) against the CPU renderer
// on 1 and 2 threads, the shader specialised to the scene (its HAS_ defines) against the uber
// shader (every feature compiled in). Links student code: the CPU stages and the GLSL.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "gpu/gl/gl_context.h"

namespace rt::bench {

struct GpuBenchConfig {
    // Scene files, relative to the course tree unless absolute: the Whitted scene, a BVH mesh and
    // stage 10's soft shadows (16 samples a pixel, two area lights).
    std::vector<std::string> scenes = {"stages/05-recursion/scenes/whitted.json",
                                       "stages/06-bvh/scenes/large_icosphere.json",
                                       "stages/10-sampling/scenes/soft_shadows.json"};
    int width = 320, height = 240;
    int repeat = 3;  // timed runs of each measurement; the fastest counts
    GlKind context = GlKind::Egl;
};

// Prints a Markdown table (one row per scene and renderer); 1 when a GPU image disagrees with
// the CPU's under the conformance test's metric (the figures would measure a wrong shader).
int run_gpu_bench(const GpuBenchConfig& config, std::ostream& out);

}  // namespace rt::bench
