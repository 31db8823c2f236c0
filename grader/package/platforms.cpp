// `rt-grade package` (platforms.h) as a list of named steps: the workspace, the bundle, its
// settings and audit, then the platform's own files around it.
#include "package/platforms.h"

#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <ctime>

#include "course/manifest.h"
#include "package/bundle.h"
#include "util.h"
#include "workspace/workspace_prepare.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

const fs::perms kExecutable = fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec;

fs::path templates(const PackageRequest& r) {
    return r.grade.source / "grader" / "package";
}

// A platform file copied from grader/package/PLATFORM/, executable when it is a script.
void copy_template(const PackageRequest& r, const std::string& from, const fs::path& to) {
    fs::create_directories(to.parent_path());
    fs::copy_file(templates(r) / from, to, fs::copy_options::overwrite_existing);
    if (to.extension() == ".sh" || to.filename() == "run_autograder")
        fs::permissions(to, kExecutable);
}

// The stages the package grades, checked against the tree.
std::vector<StageSpec> graded_stages(const PackageRequest& r) {
    std::vector<StageSpec> graded;
    for (const auto& s : load_stage_specs(r.grade.source))
        if (r.grade.stages.empty() ||
            std::count(r.grade.stages.begin(), r.grade.stages.end(), s.number))
            graded.push_back(s);
    for (const int n : r.grade.stages)
        if (std::none_of(graded.begin(), graded.end(),
                         [n](const StageSpec& s) { return s.number == n; }))
            throw std::runtime_error("--stages: stage " + two_digits(n) +
                                     " has no grading.json in " + r.grade.source.string());
    return graded;
}

// A stage with GLSL runs shaders on Mesa's llvmpipe and checks them with glslangValidator.
bool needs_gpu(const std::vector<StageSpec>& graded) {
    for (const auto& s : graded) {
        if (s.gpu) return true;
        for (const auto& f : s.student_files)
            if (f.ends_with(".glsl") || f.ends_with(".comp")) return true;
    }
    return false;
}

// packages.txt: the names the platform's set-up installs, one a line.
void write_packages(const fs::path& bundle, const std::vector<TargetPackage>& packages, bool gpu) {
    std::string text;
    for (const auto& p : packages)
        if (!p.gpu_only || gpu) text += p.name + "\n";
    write_text(bundle / "packages.txt", text);
}

// settings.sh: what the package grades, sourced by its scripts (every value shell-quoted).
void write_settings(const PackageRequest& r, const fs::path& bundle) {
    std::string stages;
    for (const int n : r.grade.stages) stages += (stages.empty() ? "" : ",") + std::to_string(n);
    std::string names;
    for (const auto& [n, name] : r.problem_names)
        names += (names.empty() ? "" : ",") + std::to_string(n) + "=" + name;
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    write_text(bundle / "settings.sh",
               std::string("# Written by rt-grade package (") + date +
                   "), sourced by the platform's scripts: what this package grades.\n"
                   "platform=" +
                   platform_name(r.platform) + "\n" + "stages=" + shell_quote(stages) +
                   "  # --stages; empty: every stage\n" + "max_per_day=" +
                   std::to_string(r.max_per_day) + "  # --max-per-day (Gradescope); 0: no limit\n" +
                   "problem_names=" + shell_quote(names) + "  # --problem-names (Autolab)\n" +
                   "deadline_seconds=540  # Gradescope: rt-grade stops and writes its results "
                   "(the default timeout is 600)\n");
}

std::string human_size(const fs::path& path) {
    return std::string(
        trim(command_output("du -sh " + shell_quote(path.string()) + " | cut -f1").value_or("?")));
}

// `zip` of `entries` (relative to `dir`) into `zip`, replacing it.
void zip_into(const fs::path& dir, const std::string& entries, const fs::path& zip) {
    std::error_code ec;
    fs::remove(zip, ec);
    std::string output;
    if (run_trusted("cd " + shell_quote(dir.string()) + " && zip -q -r -X -y " +
                        shell_quote(zip.string()) + " " + entries,
                    &output) != 0)
        throw std::runtime_error("zip failed (is the zip package installed?): " + output);
}

// An output folder of an earlier package is replaced; any other non-empty folder is refused.
fs::path fresh_out_dir(const fs::path& out) {
    std::error_code ec;
    if (fs::exists(out, ec) && !fs::is_empty(out, ec) &&
        !fs::exists(out / "autograde-Makefile", ec) && !fs::exists(out / "Dockerfile", ec))
        throw std::runtime_error(out.string() +
                                 " is not empty and holds no earlier package: choose --out DIR");
    fs::remove_all(out, ec);
    fs::create_directories(out);
    return out;
}

void write_gradescope(const PackageRequest& r, const fs::path& stage, std::ostream& log) {
    copy_template(r, "gradescope/setup.sh", stage / "setup.sh");
    copy_template(r, "gradescope/run_autograder", stage / "run_autograder");
    const fs::path zip = fs::absolute(r.out.empty() ? fs::path("autograder.zip") : r.out);
    zip_into(stage, "setup.sh run_autograder rt-grade", zip);
    log << "autograder: " << zip.string() << " (" << human_size(zip)
        << "): upload it as the assignment's autograder (Ubuntu 22.04 base image, the default "
           "768 MB and half a CPU); setup.sh installs packages only\n";
}

void write_prairielearn(const PackageRequest& r, const fs::path& stage, std::ostream& log) {
    const fs::path out = fresh_out_dir(fs::absolute(r.out.empty() ? "prairielearn" : r.out));
    copy_template(r, "prairielearn/Dockerfile", out / "Dockerfile");
    copy_template(r, "prairielearn/entrypoint.sh", out / "entrypoint.sh");
    fs::rename(stage / "rt-grade", out / "rt-grade");
    log << "prairielearn: " << out.string() << " (" << human_size(out)
        << "): an image context; build and push it (docker build -t COURSE/rt-grade "
        << out.string()
        << "), then set the question's externalGradingOptions: image COURSE/rt-grade, "
           "entrypoint /grader/entrypoint.sh (docs/grading.md#prairielearn)\n";
}

void write_autolab(const PackageRequest& r, const fs::path& stage, std::ostream& log) {
    const fs::path out = fresh_out_dir(fs::absolute(r.out.empty() ? "autolab" : r.out));
    copy_template(r, "autolab/autograde-Makefile", out / "autograde-Makefile");
    copy_template(r, "autolab/autolab_grade.sh", stage / "rt-grade" / "autolab_grade.sh");
    std::string output;
    if (run_trusted("tar -C " + shell_quote(stage.string()) + " -cf " +
                        shell_quote((out / "autograde.tar").string()) + " rt-grade",
                    &output) != 0)
        throw std::runtime_error("tar failed: " + output);
    log << "autolab: " << out.string() << " (autograde.tar " << human_size(out / "autograde.tar")
        << "): upload autograde-Makefile and autograde.tar as the assessment's autograder files "
           "(docs/grading.md#autolab)\n";
}

}  // namespace

std::optional<Platform> parse_platform(const std::string& name) {
    for (const Platform p : {Platform::Gradescope, Platform::PrairieLearn, Platform::Autolab})
        if (name == platform_name(p)) return p;
    return std::nullopt;
}

std::string platform_name(Platform platform) {
    switch (platform) {
        case Platform::Gradescope:
            return "gradescope";
        case Platform::PrairieLearn:
            return "prairielearn";
        case Platform::Autolab:
            return "autolab";
    }
    return "?";
}

int run_package(const PackageRequest& r, std::ostream& log, std::ostream& err) {
    char tmpl[] = "/tmp/rt-grade-package-XXXXXX";
    if (!mkdtemp(tmpl)) {
        err << "rt-grade: error: cannot create a folder in /tmp for the package\n";
        return 1;
    }
    const fs::path stage = tmpl;
    const fs::path bundle = stage / "rt-grade";
    int code = 1;
    try {
        require_packaging_tools();
        const std::vector<StageSpec> graded = graded_stages(r);
        if (!prepare_workspace(r.grade, err)) throw std::runtime_error("no grading workspace");
        BundleRequest b{r.grade.source, workspace_paths(r.grade),
                        fs::read_symlink("/proc/self/exe"), bundle,
                        read_target_packages(r.grade.source)};
        if (!write_bundle(b, log, err)) throw std::runtime_error("the bundle was not written");
        write_packages(bundle, b.packages, needs_gpu(graded));
        write_settings(r, bundle);
        if (!audit_bundle(r.grade.source, bundle, log))
            throw std::runtime_error(
                "the bundle fails its audit (above): it would not load on "
                "Ubuntu 22.04, so no package was written");
        if (r.platform == Platform::Gradescope) write_gradescope(r, stage, log);
        if (r.platform == Platform::PrairieLearn) write_prairielearn(r, stage, log);
        if (r.platform == Platform::Autolab) write_autolab(r, stage, log);
        code = 0;
    } catch (const std::exception& e) {
        err << "rt-grade: error: package: " << e.what() << "\n";
    }
    std::error_code ec;
    fs::remove_all(stage, ec);
    return code;
}

}  // namespace rt::grader
