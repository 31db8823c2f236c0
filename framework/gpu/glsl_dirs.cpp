// The folders of the student's GLSL (glsl_dirs.h).
#include "gpu/glsl_dirs.h"

#include <cstdlib>

#include "core/source_dir.h"

namespace fs = std::filesystem;

namespace rt {

fs::path gpu_student_dir() {
    // The grader points its sandboxed tests and renders at the GLSL it grades.
    const char* graded = std::getenv("RT_GPU_STUDENT_DIR");
    return graded && *graded ? fs::path(graded) : source_dir() / "stages/09-gpu";
}

fs::path gpu_sampling_dir() {
    const char* graded = std::getenv("RT_GPU_STUDENT_DIR");
    if (graded && *graded && fs::is_regular_file(fs::path(graded) / "sampling.glsl"))
        return fs::path(graded);
    return source_dir() / "stages/10-sampling";
}

}  // namespace rt
