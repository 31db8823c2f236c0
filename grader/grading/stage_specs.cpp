// What the grader adds to the course manifest (course/manifest.h).
#include "grading/stage_specs.h"

#include <filesystem>

namespace rt::grader {

bool is_compiled_student_file(const std::string& key) {
    return std::filesystem::path(key).extension() != ".glsl";
}

}  // namespace rt::grader
