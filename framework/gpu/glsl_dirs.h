// Where the GPU renderer reads the student's GLSL from. Not student code: a grading judge may call
// these (stage 10's GPU tests read sampling.glsl to make a variant of it).
#pragma once

#include <filesystem>

namespace rt {

// Where the student's GLSL is read from: $RT_GPU_STUDENT_DIR when set (the grader's sandboxed
// tests and renders: the submission being graded), else stages/09-gpu of the course tree.
std::filesystem::path gpu_student_dir();

// Where stage 10's GLSL (sampling.glsl, included only for scenes with Features::sampled()) is
// read from: $RT_GPU_STUDENT_DIR when it holds sampling.glsl, else stages/10-sampling.
std::filesystem::path gpu_sampling_dir();

// Where stage 11's GLSL (bsdf.glsl and path.glsl, included only for path-traced scenes) is read
// from: $RT_GPU_STUDENT_DIR when it holds path.glsl, else stages/11-path-tracing.
std::filesystem::path gpu_path_dir();

}  // namespace rt
