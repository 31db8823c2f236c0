#include "testing/stage_test.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>

#include "core/not_implemented.h"
#include "core/source_dir.h"
#include "image/compare.h"
#include "render/prepare.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace rt::testing {
namespace {

// A crash (SIGSEGV and the like) ends the test binary, and ctest prints only "SEGFAULT". The
// handler says, before the default action, which test it was, what such a crash means and
// which build shows the line. It only writes prepared bytes: nothing else is safe there.
char g_crash_note[1024];
std::size_t g_crash_note_size = 0;

void on_crash(int signal) {
    const char* name = sigabbrev_np(signal);
    const char head[] = "\n*** SIG";
    [[maybe_unused]] ssize_t n = write(2, head, sizeof head - 1);
    n = write(2, name ? name : "?", name ? std::strlen(name) : 1);
    n = write(2, g_crash_note, g_crash_note_size);
    std::signal(signal, SIG_DFL);
    raise(signal);
}

void note_crashes_in(const ::testing::TestInfo& test) {
    const std::string stage = program_invocation_short_name;  // stageNN_tests, stageNN_x_tests
    const std::string label = stage.substr(0, std::min<std::size_t>(7, stage.size()));
    const std::string note =
        " in the test " + std::string(test.test_suite_name()) + "." + test.name() +
        ": your code read or wrote memory it does not own (an index past the end, a dangling "
        "reference or pointer) or recursed without end. The sanitizer build names the line: "
        "cmake --preset debug && cmake --build --preset debug --target " +
        label + " && ctest --preset debug -L " + label +
        " --output-on-failure (README.md#when-a-test-crashes)\n";
    g_crash_note_size = std::min(note.size(), sizeof g_crash_note);
    std::memcpy(g_crash_note, note.data(), g_crash_note_size);
    static stack_t alternate = [] {
        static char stack[64 * 1024];  // a stack overflow needs another stack to report on
        stack_t s{};
        s.ss_sp = stack;
        s.ss_size = sizeof stack;
        sigaltstack(&s, nullptr);
        return s;
    }();
    (void)alternate;
    struct sigaction action {};
    action.sa_handler = on_crash;
    action.sa_flags = SA_ONSTACK;
    for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) sigaction(signal, &action, nullptr);
}

}  // namespace

void StageTest::SetUp() {
    stubs_before_ = stub_calls_total();
    note_crashes_in(*::testing::UnitTest::GetInstance()->current_test_info());
}

void StageTest::TearDown() {
    if (stub_calls_total() != stubs_before_)
        ADD_FAILURE() << "this test reached code that is not implemented yet (see the "
                         "\"not implemented\" line above for the function and the handout "
                         "section to read)";
}

std::filesystem::path source_dir() {
    return rt::source_dir();
}

void expect_matches_reference(const std::string& stage, const std::string& scene_name,
                              const CompareOptions& options) {
    const auto scene_file = source_dir() / "stages" / stage / "scenes" / (scene_name + ".json");
    const auto reference_file = source_dir() / "reference_images" / stage / (scene_name + ".png");
    PreparedScene scene;
    try {
        // In a grading judge prepare_scene crosses to the worker (stage_api/calls.h).
        scene = prepare_scene(load_scene(scene_file));
    } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
        return;
    }
    const Image8 actual = to_image8(render(scene, scene.mode));
    Image8 reference;
    try {
        reference = read_image8(reference_file);
    } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
        return;
    }
    const CompareResult result = compare_images(actual, reference, options);
    if (result.passed) return;
    std::vector<KeptImage> kept = {{"your image", scene_name + ".png", &actual}};
    if (result.size_matches)
        kept.push_back({"difference", scene_name + ".diff.png", &result.heat_map});
    ADD_FAILURE() << scene_file.string() << ": " << result.summary()
                  << keep_failure_images(stage, kept)
                  << "\n  reference: " << reference_file.string();
}

std::string keep_failure_images(const std::string& folder, const std::vector<KeptImage>& images) {
    const auto out_dir = std::filesystem::path(RT_TEST_OUTPUT_DIR) / folder;
    std::string lines;
    try {
        std::filesystem::create_directories(out_dir);
        for (const KeptImage& k : images) {
            write_image8(*k.image, out_dir / k.file);
            lines += "\n  " + k.label + ": " + (out_dir / k.file).string();
        }
    } catch (const std::exception& e) {
        lines += "\n  (the images could not be kept: " + std::string(e.what()) + ")";
    }
    return lines;
}

}  // namespace rt::testing
