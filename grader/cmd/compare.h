// `rt-grade compare` (compare.cpp).
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace rt::grader {

// `rt-grade compare`: scores images with the grader's comparison against reference_images and
// the thresholds of grading.json. Either renders every graded scene with `renderer` (a trusted
// build, e.g. the reference compiled with other flags) or scores `image` as scene `scene`
// ("NN-name/scene"; a PNG is taken as display values, an EXR as linear). Prints one line per
// scene; returns 0 when every scene gets full points, 1 otherwise, 2 on a usage error.
struct CompareRequest {
    std::filesystem::path source;
    std::filesystem::path renderer;
    std::vector<int> stages;
    int threads = 0;
    std::filesystem::path image;
    std::string scene;
};
int run_compare(const CompareRequest& request, std::ostream& log);

}  // namespace rt::grader
