// Writes stage 08's procedural environment images (framework/testing/environment_images.h):
//   build/bin/make-environment-images stages/08-environment/scenes
#include <cstdio>
#include <exception>

#include "testing/environment_images.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make-environment-images FOLDER\n");
        return 2;
    }
    try {
        rt::testing::write_environment_images(argv[1]);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    std::printf("wrote %s/sky.exr and %s/cube/*.png\n", argv[1], argv[1]);
    return 0;
}
