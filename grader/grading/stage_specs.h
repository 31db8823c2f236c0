// What the grader adds to the course manifest (course/manifest.h): which student files are
// compiled, and the names of the judge and worker targets (stage_specs.cpp).
#pragma once

#include <string>

namespace rt::grader {

// The stages' manifests (stage.json, grading.json): ImageThresholds, SceneSpec, UnitGroup,
// StageSpec and load_stage_specs are course/manifest.h's.

// A student file compiled into the stage objects (C++), as opposed to GLSL read at run time.
bool is_compiled_student_file(const std::string& key);

// Every unit test runs as a judge and a worker (framework/remote/remote_call.h): the workspace
// builds <binary>_judge once (it holds no student code, C++ or GLSL) and links rt-worker per
// submission.
inline const char* kWorker = "rt-worker";
inline std::string judge_target(const std::string& binary) {
    return binary + "_judge";
}
inline bool is_judge_target(const std::string& target) {
    return target.ends_with("_judge");
}

}  // namespace rt::grader
