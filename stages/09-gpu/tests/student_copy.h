// Stage 09's framework tests: a fresh copy of the student GLSL to break on purpose, and the
// release tool's stripping of it (shader_test.cpp, debug_pixel_test.cpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/text_file.h"
#include "course/manifest.h"
#include "release/release.h"
#include "testing/stage_test.h"
#include "testing/temp_dir.h"

namespace rt::gpu_test {

// Stage 09's student files, as its stage.json lists them (the course manifest's one reader).
inline std::vector<std::string> student_files() {
    return read_stage_info(::rt::testing::source_dir() / "stages/09-gpu/stage.json").student_files;
}

inline std::string read(const std::filesystem::path& file) {
    return read_text(file);
}

inline void write(const std::filesystem::path& file, const std::string& text) {
    write_text(file, text);
}

// A fresh copy of stages/09-gpu's GLSL in a temporary folder.
class StudentCopy {
  public:
    explicit StudentCopy(const std::string& name) : folder_("stage09-" + name) {
        for (const std::string& f : student_files())
            std::filesystem::copy_file(::rt::testing::source_dir() / "stages/09-gpu" / f,
                                       dir() / f);
    }
    const std::filesystem::path& dir() const { return folder_.path(); }

  private:
    ::rt::testing::TempDir folder_;
};

// The release tool's own stripping (grader/release/markers.cpp): solutions out, stubs un-commented.
inline std::string strip_solutions(const std::string& text) {
    return grader::process_markers(text, grader::RegionMode::Strip).text;
}

}  // namespace rt::gpu_test
