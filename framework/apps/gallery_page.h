// The gallery (`rt gallery --out DIR`) and its index.html (`rt gallery --out DIR`): every scene of every stage as a thumbnail
// beside its reference image and the difference image of the grader's metric (failing pixels
// white), with the stage's handout linked, so a student sees at a glance which scenes are wrong.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "course/manifest.h"
#include "image/compare.h"
#include "image/image.h"

namespace rt {

class GalleryPage {
  public:
    // `source`: the tree holding stages/ and reference_images/; `out`: the gallery folder.
    GalleryPage(std::filesystem::path source, std::filesystem::path out);

    // A scene's render, written as `image_file` (inside out/): copies its reference image beside
    // it and writes the difference image when the reference exists. `web_page`: its `rt
    // export-web` page (inside out/), or empty with `web_problem` saying why there is none.
    void add(const std::filesystem::path& stage, const std::filesystem::path& scene_file,
             const std::filesystem::path& image_file, const Image& image,
             const std::filesystem::path& web_page = {}, const std::string& web_problem = {});

    // Writes out/index.html; returns its path.
    std::filesystem::path write() const;

    int failing() const;  // graded scenes that do not pass

  private:
    struct Entry {
        std::string stage, name;  // folder name, scene file stem
        bool graded = false;
        std::string image, reference, difference;  // paths relative to out/ ("" when absent)
        std::string web, web_problem;  // the live WebGL2 page (relative), or why it has none
        CompareOptions options;
        double fail_percent = 2.0;  // past this the grader gives nothing (grading.json)
        bool compared = false;
        CompareResult result;
    };
    struct Stage {
        std::string title, handout;     // handout: relative link from out/ into the source tree
        std::optional<StageSpec> spec;  // its manifest, when it has a grading.json
    };
    const Stage& stage_info(const std::filesystem::path& stage);
    static std::string compare_text(const Entry& e);
    static void write_scene(std::ostream& page, const Entry& e);

    std::filesystem::path source_, out_;
    std::map<std::string, Stage> stages_;
    std::vector<Entry> entries_;
};

// `rt gallery`: renders every scene of every stage (stages/NN-name/scenes/*.json, in order) into
// out/NN-name/, then writes out/index.html; into the source tree's reference_images (regenerating
// them) it writes the images only.
int run_gallery(const std::filesystem::path& source, const std::filesystem::path& out, int threads);

}  // namespace rt
