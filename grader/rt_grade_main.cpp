// rt-grade: the instructor's tool. Trusted code only -- it never links or loads student code.
#include <CLI/CLI.hpp>

#include <iostream>

#include "release.h"

#ifndef RT_SOURCE_DIR
#error "RT_SOURCE_DIR must name the course source tree (set by grader/CMakeLists.txt)"
#endif

int main(int argc, char** argv) {
    CLI::App app{"rt-grade: instructor tools for the ray-tracing course"};
    app.require_subcommand(1);

    rt::grader::ReleaseOptions release;
    std::string out;
    std::string source = RT_SOURCE_DIR;
    CLI::App* release_cmd = app.add_subcommand(
        "release",
        "Write a student starter tree: the source tree with solutions replaced by stubs");
    release_cmd->add_option("--out", out, "Directory to write the starter tree to")->required();
    release_cmd
        ->add_option("--source", source,
                     "Course source tree (default: the tree rt-grade was built from)")
        ->check(CLI::ExistingDirectory)
        ->capture_default_str();
    release_cmd
        ->add_option("--solved-through", release.solved_through,
                     "Stages 1..N keep their solutions (default 0: every stage stubbed)")
        ->check(CLI::Range(0, 99))  // stage numbers are two digits
        ->capture_default_str();
    release_cmd->add_flag("--force", release.force, "Write into a non-empty --out directory");
    release_cmd->add_flag(
        "--include-untracked", release.include_untracked,
        "Git checkout: also copy untracked files that .gitignore does not exclude");

    CLI11_PARSE(app, argc, argv);

    if (*release_cmd) {
        release.out = out;
        release.source = source;
        return rt::grader::run_release(release, std::cout, std::cerr);
    }
    return 2;
}
