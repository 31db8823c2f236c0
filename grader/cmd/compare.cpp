// `rt-grade compare`: the grader's image scoring outside a grading run, for calibration
// (grader/tests/calibrate_flags.sh renders with the reference built with other flags).
#include "cmd/compare.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "core/parallel_for.h"
#include "course/manifest.h"
#include "grading/image_scoring.h"
#include "image/image.h"
#include "util.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

struct Scored {
    bool ok = false;
    std::string line;
};

Scored score_file(const fs::path& image_file, const fs::path& reference, const SceneSpec& scene) {
    Scored s;
    Image8 actual;
    if (image_file.extension() == ".exr") {
        Image linear;
        std::string why;
        if (!read_render(image_file, linear, why)) {
            s.line = why;
            return s;
        }
        actual = to_image8(linear);
    } else {
        actual = read_image8(image_file);  // display values, taken as they are
    }
    const ImageScore score = score_image(actual, read_image8(reference), scene.thresholds);
    char head[64];
    std::snprintf(head, sizeof head, "score %.2f of %g: ", score.fraction * scene.points,
                  scene.points);
    s.ok = score.compare.size_matches && score.fraction >= 1;
    s.line = head + score.metrics;
    return s;
}

}  // namespace

int run_compare(const CompareRequest& r, std::ostream& log) {
    const auto specs = load_stage_specs(r.source);
    auto find_scene = [&](const std::string& stage_folder,
                          const std::string& name) -> const SceneSpec* {
        for (const auto& s : specs)
            if (fs::path(s.folder).filename() == stage_folder)
                for (const auto& sc : s.scenes)
                    if (sc.name == name) return &sc;
        return nullptr;
    };
    if (!r.image.empty()) {
        const auto slash = r.scene.find('/');
        const SceneSpec* scene = slash == std::string::npos ? nullptr
                                                            : find_scene(r.scene.substr(0, slash),
                                                                         r.scene.substr(slash + 1));
        if (!scene) {
            log << "rt-grade compare: --scene must name a graded scene as NN-name/scene\n";
            return 2;
        }
        const Scored s =
            score_file(r.image, r.source / "reference_images" / (r.scene + ".png"), *scene);
        log << r.scene << ": " << (s.ok ? "PASS " : "FAIL ") << s.line << "\n";
        return s.ok ? 0 : 1;
    }
    if (r.renderer.empty()) {
        log << "rt-grade compare: give --renderer BIN or --image FILE --scene NN-name/scene\n";
        return 2;
    }
    char tmpl[] = "/tmp/rt-grade-compare-XXXXXX";
    if (!mkdtemp(tmpl)) return 2;
    const fs::path scratch = tmpl;
    const int threads = r.threads > 0 ? r.threads : default_thread_count();
    int failed = 0, total = 0;
    for (const auto& s : specs) {
        if (!r.stages.empty() && std::count(r.stages.begin(), r.stages.end(), s.number) == 0)
            continue;
        // `compare` calibrates the CPU renderer: a GPU stage's scenes are earlier stages' own.
        if (s.gpu) continue;
        const std::string stage = fs::path(s.folder).filename().string();
        for (const auto& sc : s.scenes) {
            ++total;
            const fs::path exr = scratch / (stage + "-" + sc.name + ".exr");
            const auto start = std::chrono::steady_clock::now();
            std::string out;
            // A renderer that hangs (a broken build) must not stall the calibration forever.
            const int code = run_trusted(
                "timeout 300 " + shell_quote(r.renderer.string()) + " render " +
                    shell_quote((r.source / s.folder / "scenes" / (sc.name + ".json")).string()) +
                    " -o " + shell_quote(exr.string()) + " -q --threads " + std::to_string(threads),
                &out);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            Scored result;
            if (code != 0)
                result.line = "the renderer exited with code " + std::to_string(code) + ": " + out;
            else
                result =
                    score_file(exr, r.source / "reference_images" / stage / (sc.name + ".png"), sc);
            failed += !result.ok;
            char timing[32];
            std::snprintf(timing, sizeof timing, " (%.1f s)", seconds);
            log << stage << "/" << sc.name << ": " << (result.ok ? "PASS " : "FAIL ") << result.line
                << timing << "\n";
        }
    }
    std::error_code ec;
    fs::remove_all(scratch, ec);
    log << (total - failed) << " of " << total << " scenes at full points\n";
    return failed == 0 && total > 0 ? 0 : 1;
}

}  // namespace rt::grader
