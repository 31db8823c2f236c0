#include "apps/gallery_page.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/text_file.h"
#include "render/gpu/web_export.h"
#include "render/prepare.h"
#include "render/render.h"
#include "scene/scene_loader.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

// `rt export-web`'s page of the scene beside its render (NAME.web.html), or an empty path with
// `problem` saying why the scene has none (export_web_page refuses what WebGL cannot hold).
fs::path write_web_page(const PreparedScene& scene, const Image& image, const fs::path& image_file,
                        std::string& problem) {
    fs::path page = image_file;
    page.replace_extension(".web.html");
    try {
        write_text_atomically(page, export_web_page(scene, scene.mode, to_image8(image)));
        return page;
    } catch (const std::exception& e) {
        problem = e.what();
        return {};
    }
}

// A link from the gallery folder to `target`, with '/' separators (a browser's form).
std::string relative_link(const fs::path& target, const fs::path& from) {
    return fs::relative(fs::weakly_canonical(target), fs::weakly_canonical(from)).generic_string();
}

}  // namespace

// The comparison a scene gets, as data-compare (cmake/check_gallery_page.cmake reads it back).
std::string GalleryPage::compare_text(const Entry& e) {
    // 17 significant digits: how CMake's JSON reader prints a number back.
    char text[200];
    std::snprintf(text, sizeof text, "tolerance=%d pass=%.17g fail=%.17g neighbourhood=%d block=%d",
                  e.options.tolerance, e.options.max_failing_percent, e.fail_percent,
                  e.options.neighbourhood ? 1 : 0, e.options.block);
    return text;
}

namespace {

const char* const kStyle = R"(
body { font: 14px system-ui, sans-serif; margin: 1.5em; background: #1d1f21; color: #ddd; }
a { color: #8ab4f8; }
h2 { margin-top: 1.6em; border-bottom: 1px solid #444; }
.scene { display: inline-block; vertical-align: top; margin: 0 1.2em 1.2em 0; padding: .5em;
         background: #2a2c2f; border-left: 6px solid #666; }
.scene.pass { border-color: #3c3; } .scene.partial { border-color: #fc3; }
.scene.fail { border-color: #e33; } .scene.none { border-color: #666; }
.scene img { width: 200px; image-rendering: pixelated; margin-right: 4px; background: #000; }
.scene .cols { display: flex; } .scene .cols div { text-align: center; font-size: 12px; }
.badge { font-weight: bold; } .pass .badge { color: #3c3; } .partial .badge { color: #fc3; }
.fail .badge { color: #e33; }
.metric { font-size: 12px; color: #aaa; max-width: 612px; }
)";

}  // namespace

GalleryPage::GalleryPage(fs::path source, fs::path out)
    : source_(std::move(source)), out_(std::move(out)) {}

const GalleryPage::Stage& GalleryPage::stage_info(const fs::path& stage) {
    const std::string key = stage.filename().string();
    if (auto it = stages_.find(key); it != stages_.end()) return it->second;
    Stage s;
    // The grader's reader (course/manifest.h): a graded scene is compared as rt-grade compares it.
    if (fs::exists(stage / "grading.json")) s.spec = load_stage_spec(source_, stage);
    const std::string title = s.spec ? s.spec->title : read_stage_info(stage / "stage.json").title;
    s.title = title.empty() ? key : title;
    s.handout = relative_link(stage / "README.md", out_);
    return stages_.emplace(key, std::move(s)).first->second;
}

void GalleryPage::add(const fs::path& stage, const fs::path& scene_file, const fs::path& image_file,
                      const Image& image, const fs::path& web_page,
                      const std::string& web_problem) {
    const Stage& s = stage_info(stage);
    Entry e;
    e.stage = stage.filename().string();
    e.name = scene_file.stem().string();
    const SceneSpec* graded = s.spec ? s.spec->scene(e.name) : nullptr;
    e.graded = graded != nullptr;
    const ImageThresholds thresholds = s.spec ? s.spec->thresholds_of(e.name) : ImageThresholds{};
    e.options = thresholds.compare_options();
    e.fail_percent = thresholds.fail_percent;
    e.image = relative_link(image_file, out_);
    if (!web_page.empty()) e.web = relative_link(web_page, out_);
    e.web_problem = web_problem;
    const fs::path reference = source_ / "reference_images" / e.stage / (e.name + ".png");
    if (fs::exists(reference)) {
        const fs::path folder = image_file.parent_path();
        const fs::path copy = folder / (e.name + ".reference.png");
        const fs::path difference = folder / (e.name + ".difference.png");
        fs::copy_file(reference, copy, fs::copy_options::overwrite_existing);
        e.result = compare_images(to_image8(image), read_image8(reference), e.options);
        e.compared = true;
        e.reference = relative_link(copy, out_);
        if (e.result.size_matches) {
            write_image8(e.result.heat_map, difference);
            e.difference = relative_link(difference, out_);
        }
    }
    entries_.push_back(std::move(e));
}

int GalleryPage::failing() const {
    return int(std::count_if(entries_.begin(), entries_.end(), [](const Entry& e) {
        return e.graded && (!e.compared || !e.result.passed);
    }));
}

// One scene's card: its badge, the render, reference and difference, and the metric.
void GalleryPage::write_scene(std::ostream& page, const Entry& e) {
    std::string status = "none";
    std::string badge = "no reference";
    if (e.compared && !e.result.size_matches) {
        status = "fail";
        badge = "wrong size";
    } else if (e.compared) {
        const double p = e.result.failing_percent;
        status = e.result.passed ? "pass" : p < e.fail_percent ? "partial" : "fail";
        badge = e.result.passed ? "pass" : p < e.fail_percent ? "partial credit" : "FAIL";
    }
    if (!e.graded) badge += " (not graded)";
    page << "<div id=\"" << html_escape(e.stage + "-" + e.name) << "\" class=\"scene " << status
         << "\" data-scene=\"" << html_escape(e.stage + "/" + e.name) << "\" data-graded=\""
         << (e.graded ? "true" : "false") << "\" data-compare=\"" << compare_text(e) << "\">\n<b>"
         << html_escape(e.name) << "</b> <span class=\"badge\">" << html_escape(badge)
         << "</span>\n<div class=\"cols\">\n";
    const auto column = [&](const std::string& file, const char* label) {
        if (file.empty()) return;
        page << "<div><a href=\"" << html_escape(file) << "\"><img src=\"" << html_escape(file)
             << "\" alt=\"" << label << "\"></a><br>" << label << "</div>\n";
    };
    column(e.image, "render");
    column(e.reference, "reference");
    column(e.difference, "difference");
    page << "</div>\n";
    // The lecture's slide: the scene live in the browser (docs/viewer.md).
    if (!e.web.empty())
        page << "<div class=\"metric\"><a href=\"" << html_escape(e.web)
             << "\">live WebGL2 page</a> (stage 09's GLSL in the browser: orbit, zoom)</div>\n";
    else if (!e.web_problem.empty())
        page << "<div class=\"metric\">no WebGL2 page: " << html_escape(e.web_problem)
             << "</div>\n";
    if (e.compared)
        page << "<div class=\"metric\">" << html_escape(e.result.summary()) << " (tolerance "
             << e.options.tolerance << ", pass up to " << e.options.max_failing_percent << "%"
             << (e.options.block > 0 ? ", " + std::to_string(e.options.block) + "x" +
                                           std::to_string(e.options.block) + "-block means"
                                     : "")
             << ")</div>\n";
    page << "</div>\n";
}

fs::path GalleryPage::write() const {
    std::ostringstream page;
    int passed = 0;
    int graded = 0;
    for (const Entry& e : entries_) {
        if (!e.graded) continue;
        ++graded;
        passed += e.compared && e.result.passed;
    }
    page << html_page_start("rt gallery", kStyle) << "<h1>rt gallery</h1>\n<p>" << passed << " of "
         << graded << " graded scenes match their reference image by the grader's metric";
    if (entries_.size() > std::size_t(graded))
        page << " (the other " << entries_.size() - graded << " of the " << entries_.size()
             << " scenes are not graded: no verdict)";
    page << ". Each scene: "
            "your render, the reference, and the difference (black: equal; red: yours brighter, "
            "blue: darker; dim within the tolerance, <b>full: a failing pixel</b>).</p>\n";
    // At a glance: the graded scenes that do not pass, each linked to its place below.
    bool first = true;
    for (const Entry& e : entries_) {
        if (!e.graded || (e.compared && e.result.passed)) continue;
        page << (first ? "<p><b>Not passing:</b> " : ", ") << "<a href=\"#" << html_escape(e.stage)
             << "-" << html_escape(e.name) << "\">" << html_escape(e.stage + "/" + e.name)
             << "</a>";
        first = false;
    }
    if (!first) page << "</p>\n";
    std::string stage;
    for (const Entry& e : entries_) {
        if (e.stage != stage) {
            if (!stage.empty()) page << "</section>\n";
            stage = e.stage;
            const Stage& s = stages_.at(stage);
            page << "<section id=\"" << html_escape(stage) << "\">\n<h2>" << html_escape(stage)
                 << ": " << html_escape(s.title) << " <small>(<a href=\"" << html_escape(s.handout)
                 << "\">handout</a>)</small></h2>\n";
        }
        write_scene(page, e);
    }
    if (!stage.empty()) page << "</section>\n";
    // Once loaded, the page records how many of its images the browser could decode, so a
    // headless browser test (cmake/check_gallery_page.cmake) can count them.
    page << "<script>\nwindow.addEventListener('load', () => {\n"
            "  const images = [...document.images];\n"
            "  document.body.dataset.imagesTotal = images.length;\n"
            "  document.body.dataset.imagesLoaded =\n"
            "      images.filter(i => i.complete && i.naturalWidth > 0).length;\n"
            "});\n</script>\n";
    page << kHtmlPageEnd;
    const fs::path file = out_ / "index.html";
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << page.str();
    if (!out) throw std::runtime_error("rt: error: cannot write " + file.string());
    return file;
}

// Every stage folder with scenes, in order: stages/NN-name/scenes/*.json.
int run_gallery(const fs::path& source, const fs::path& out, int threads) {
    std::vector<fs::path> stages;
    std::string without_scenes;  // stage 09: its GPU port draws the other stages' scenes
    for (const auto& entry : fs::directory_iterator(source / "stages")) {
        if (!entry.is_directory()) continue;
        if (fs::is_directory(entry.path() / "scenes"))
            stages.push_back(entry.path());
        else if (fs::exists(entry.path() / "stage.json"))
            without_scenes +=
                (without_scenes.empty() ? "" : ", ") + entry.path().filename().string();
    }
    std::sort(stages.begin(), stages.end());
    int count = 0;
    const auto start = std::chrono::steady_clock::now();
    // `rt gallery --out reference_images` regenerates the references (README.md): no page, no
    // copies or difference images among them.
    std::error_code ec;
    const bool regenerating = fs::equivalent(out, source / "reference_images", ec);
    GalleryPage page(source, out);
    for (const fs::path& stage : stages) {
        std::vector<fs::path> scenes;
        for (const auto& entry : fs::directory_iterator(stage / "scenes"))
            if (entry.path().extension() == ".json") scenes.push_back(entry.path());
        std::sort(scenes.begin(), scenes.end());
        const fs::path stage_out = out / stage.filename();
        fs::create_directories(stage_out);
        for (const fs::path& scene_file : scenes) {
            const PreparedScene scene = prepare_scene(load_scene(scene_file));
            RenderOptions options;
            options.threads = threads;
            const fs::path image_file = stage_out / (scene_file.stem().string() + ".png");
            Image image = render(scene, scene.mode, options);
            const NonFinitePixels non_finite = mark_non_finite_pixels(image);
            if (non_finite.count > 0)
                std::fprintf(stderr, "%s\n", non_finite.describe(scene_file.string()).c_str());
            write_image(image, image_file);
            if (!regenerating) {
                std::string web_problem;
                const fs::path web = write_web_page(scene, image, image_file, web_problem);
                page.add(stage, scene_file, image_file, image, web, web_problem);
            }
            std::printf("  %s\n", image_file.c_str());
            ++count;
        }
    }
    std::printf(
        "rendered %d scenes in %.1f s: every stage's scenes/%s\ngallery: %s\n", count,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
        without_scenes.empty() ? "" : (" (" + without_scenes + ": no scenes/ of its own)").c_str(),
        fs::absolute(out).lexically_normal().c_str());
    if (regenerating) return 0;
    const fs::path index = page.write();
    std::printf("page: %s (%d graded scenes do not match their reference)\n",
                fs::absolute(index).lexically_normal().c_str(), page.failing());
    return 0;
}

}  // namespace rt
