// Stage 09's framework tests: a fresh copy of the student GLSL to break on purpose, and the
// release tool's stripping of it (shader_test.cpp, debug_pixel_test.cpp).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "release/release.h"
#include "testing/stage_test.h"

namespace rt::gpu_test {

inline const char* const kStudentFiles[] = {"camera.glsl",     "intersect.glsl", "bvh.glsl",
                                            "shade.glsl",      "recursion.glsl", "textures.glsl",
                                            "environment.glsl"};

inline std::string read(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void write(const std::filesystem::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

// A fresh copy of stages/09-gpu's GLSL in a temporary folder.
class StudentCopy {
  public:
    explicit StudentCopy(const std::string& name)
        : dir_(std::filesystem::temp_directory_path() /
               ("rt-stage09-" + name + "-" + std::to_string(getpid()))) {
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
        for (const char* f : kStudentFiles)
            std::filesystem::copy_file(::rt::testing::source_dir() / "stages/09-gpu" / f, dir_ / f);
    }
    ~StudentCopy() { std::filesystem::remove_all(dir_); }
    const std::filesystem::path& dir() const { return dir_; }

  private:
    std::filesystem::path dir_;
};

// The release tool's own stripping (grader/release/markers.cpp): solutions out, stubs un-commented.
inline std::string strip_solutions(const std::string& text) {
    return grader::process_markers(text, grader::RegionMode::Strip).text;
}

}  // namespace rt::gpu_test
