#include "grade.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "image/compare.h"
#include "image/image.h"
#include "perceptual.h"
#include "release.h"
#include "report.h"
#include "intake.h"
#include "sandbox.h"
#include "util.h"
#include "test_output.h"
#include "verdict_channel.h"
#include "workspace.h"

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace rt::grader {

std::atomic<bool> g_interrupted{false};

namespace {

// ---------------------------------------------------------------- running

struct TestOutcome {
    std::string name, number, status = "failed", output, visibility = "visible";
    std::vector<std::string> tags;
    double score = 0, max_score = 0;
    int stage = 0;
    bool is_scene = false;
    // Scenes: images for the HTML report (PNG bytes), metrics.
    std::string student_png, reference_png, diff_png;
    std::string metrics;
};

// A file the child wrote, copied out through a descriptor that refuses symlinks, fifos and
// devices: the child owned the folder and could have planted anything there.
bool copy_out(const fs::path& child_dir, const std::string& name, const fs::path& to,
              std::uintmax_t cap, std::string& why) {
    const int dir = open(child_dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    const int fd = dir < 0 ? -1 : openat(dir, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (dir >= 0) close(dir);
    struct stat st {};
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        if (fd >= 0) close(fd);
        why = "the renderer wrote no image";
        return false;
    }
    if (std::uintmax_t(st.st_size) > cap) {
        close(fd);
        why = "the rendered image is too large";
        return false;
    }
    std::string bytes(std::size_t(st.st_size), '\0');
    const bool all = pread(fd, bytes.data(), bytes.size(), 0) == ssize_t(bytes.size());
    close(fd);
    if (!all) {
        why = "the rendered image cannot be read";
        return false;
    }
    write_text(to, bytes);
    return true;
}

std::string png_bytes(const Image8& image, const fs::path& dir, const std::string& name) {
    const fs::path file = dir / (name + ".png");
    write_image8(image, file);
    return read_text(file);
}

// A folder only the grader can enter (0700), created fresh.
fs::path trusted_dir(const fs::path& path) {
    std::error_code ec;
    fs::remove_all(path, ec);
    fs::create_directories(path);
    fs::permissions(path, fs::perms::owner_all);
    return path;
}

// A folder the child may write (handed to its uid by the sandbox); its parents allow passing
// through (0711) but not listing, for the uid-drop mode without a jail.
fs::path child_dir(const fs::path& path) {
    std::error_code ec;
    fs::remove_all(path, ec);
    fs::create_directories(path);
    fs::permissions(path, fs::perms::owner_all);
    return path;
}

// The unseen view's camera turn, in degrees: 4 to 9, either way, from the workspace secret,
// the submission's content and the scene. The same submission gets the same view (regrades
// agree); a changed one another view, so a reference image learned from a report is useless.
double unseen_yaw(const std::string& secret, const std::string& digest, const std::string& scene) {
    const std::uint64_t h = fnv1a(scene, fnv1a(digest, fnv1a(secret)));
    const double degrees = 4 + double(h % 5001) / 1000.0;
    return (h >> 32) & 1 ? degrees : -degrees;
}

}  // namespace


namespace {

std::map<std::string, std::vector<std::string>> list_tests(const Workspace& w,
                                                           const std::vector<StageSpec>& specs) {
    std::map<std::string, std::vector<std::string>> tests;
    for (const auto& s : specs)
        for (const auto& g : s.groups)
            if (!tests.count(g.binary))
                tests[g.binary] = json::parse(read_text(w.priv / "expected" / (g.binary + ".json")))
                                      .get<std::vector<std::string>>();
    return tests;
}

// A rendered image and how the render went.
struct Render {
    bool ok = false;
    Image8 image;
    std::string output;  // the renderer's output, or why there is no image
};

}  // namespace

GradeSummary grade_submission(const GradeOptions& o, std::ostream& log) {
    const auto start = std::chrono::steady_clock::now();
    GradeSummary summary;
    const Workspace w = workspace_paths(o);
    const auto all_specs = load_stage_specs(o.source);
    std::vector<StageSpec> graded;
    std::string started_note;
    if (o.stages.empty() && o.started_only) {
        // Self-grading: the stages whose files differ from their stubs (at least stage 01).
        for (const auto& s : all_specs) {
            bool started = false;
            for (const auto& f : s.student_files) {
                std::error_code ec;
                const fs::path mine = o.source / s.folder / f, stub = w.priv / "pristine" / s.folder / (f + ".stub");
                started = started || (fs::is_regular_file(mine, ec) && fs::is_regular_file(stub, ec) &&
                                      read_text(mine) != read_text(stub));
            }
            if (started) graded.push_back(s);
        }
        if (graded.empty() && !all_specs.empty()) {
            graded.push_back(all_specs.front());
            started_note = "No stage started yet (every student file is still its stub): grading stage " +
                           two_digits(all_specs.front().number) + ".\n";
        } else {
            started_note = "Grading the stages you have started:";
            for (const auto& s : graded) started_note += " " + two_digits(s.number);
            started_note += " (--stages N,M grades others).\n";
        }
    } else {
        for (const auto& s : all_specs)
            if (o.stages.empty() || std::count(o.stages.begin(), o.stages.end(), s.number))
                graded.push_back(s);
    }
    const auto expected = list_tests(w, all_specs);
    const Isolation isolation = probe_isolation();

    // Every test the grade will have, score 0 until run: the placeholder results.json and
    // the list a failed build reports.
    std::vector<TestOutcome> outcomes;
    struct Task {
        std::size_t outcome;
        std::string binary, test;  // unit test
        const SceneSpec* scene = nullptr;
        const StageSpec* stage = nullptr;
    };
    std::vector<Task> tasks;
    for (const auto& s : graded) {
        int n = 0;
        for (const auto& g : s.groups) {
            const auto it = expected.find(g.binary);
            if (it == expected.end()) continue;
            for (const auto& t : it->second) {
                bool in = false;
                for (const auto& p : g.include) in = in || glob_match(p, t);
                for (const auto& p : g.exclude) in = in && !glob_match(p, t);
                if (!in) continue;
                TestOutcome out;
                out.stage = s.number;
                out.name = "Stage " + two_digits(s.number) + " " + t;
                out.number = std::to_string(s.number) + "." + std::to_string(++n);
                out.max_score = g.points;
                out.visibility = g.visibility;
                out.tags = {"stage" + two_digits(s.number),
                            g.hidden_sources.empty() ? "unit" : "hidden"};
                out.output = "not run: grading did not finish\n";
                tasks.push_back({outcomes.size(), g.binary, t, nullptr, &s});
                outcomes.push_back(out);
            }
        }
        for (const auto& sc : s.scenes) {
            TestOutcome out;
            out.stage = s.number;
            out.name = "Stage " + two_digits(s.number) + " image " + sc.name;
            out.number = std::to_string(s.number) + "." + std::to_string(++n);
            out.max_score = sc.points;
            out.visibility = sc.visibility;
            out.tags = {"stage" + two_digits(s.number), "image"};
            out.output = "not run: grading did not finish\n";
            out.is_scene = true;
            tasks.push_back({outcomes.size(), "rt", sc.name, &sc, &s});
            outcomes.push_back(out);
        }
    }
    std::vector<TestOutcome> notes;  // 0-point entries: build, file checks
    std::string general = started_note;  // top-level output

    auto to_report = [&]() {
        Report r;
        r.isolation = describe(isolation);
        r.general = general;
        r.seconds = seconds_since(start);
        for (const auto& s : graded) r.stages.push_back({s.number, s.title, s.folder});
        for (const auto* list : {&notes, &outcomes})
            for (const auto& t : *list)
                r.tests.push_back({t.stage, t.name, t.number, t.status, t.output, t.visibility,
                                   t.tags, t.score, t.max_score, t.is_scene, t.student_png,
                                   t.reference_png, t.diff_png, t.metrics});
        return r;
    };
    if (!o.results.empty()) write_results_json(to_report(), o.results);

    // Gradings share the workspace read-only; `prepare` takes this lock exclusively.
    const int lock = open((w.cache / "workspace.lock").c_str(), O_CREAT | O_RDWR | O_CLOEXEC | O_NOFOLLOW, 0600);
    flock(lock, LOCK_SH);
    struct Unlock {
        int fd;
        ~Unlock() { close(fd); }
    } unlock{lock};
    const BuildPlan plan = load_build_plan(w);
    char scratch_template[] = "/tmp/rt-grade-run-XXXXXX";
    if (!mkdtemp(scratch_template)) throw std::runtime_error("rt-grade: cannot create a scratch folder in /tmp");
    const fs::path scratch = scratch_template;
    // Only the grader lists it; uid-drop children (no jail) may pass through to their own folder.
    fs::permissions(scratch, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);

    // The reference renderer, where a sandbox uid may execute but not read it (uid-drop mode
    // has no jail to bind it into).
    const fs::path reference_rt = trusted_dir(scratch / "reference") / "rt";
    if (plan.has_reference) {
        fs::copy_file(w.priv / "bin" / "rt", reference_rt);
        fs::permissions(reference_rt.parent_path(), fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
        fs::permissions(reference_rt, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
    }

    Intake in = take_in(o, graded, all_specs, w.src);
    if (!in.error.empty()) general += "The submission could not be read: " + in.error + "\n";
    std::string digest;
    for (const auto& [key, text] : in.files) digest += key + "\n" + hex(fnv1a(text)) + "\n";
    for (const auto& s : graded) {
        for (const auto& f : s.student_files) {
            const std::string key = s.folder + "/" + f;
            if (in.files.count(key)) continue;
            TestOutcome note;
            note.stage = s.number;
            note.name = "Stage " + two_digits(s.number) + " file " + f;
            note.number = std::to_string(s.number) + ".0";
            note.tags = {"stage" + two_digits(s.number), "submission"};
            note.output = in.rejected.count(key)
                              ? key + " was not used: " + in.rejected[key] + "\n"
                              : key + " is missing from the submission\n";
            note.output += "The stage is graded with the starter stub in its place.\n";
            notes.push_back(note);
        }
    }

    // Without namespaces the hidden tests are kept from the children (compiler included) by
    // permissions only.
    if (isolation == Isolation::UidDrop)
        for (const auto& d : hidden_dirs(w)) {
            std::error_code ec;
            fs::permissions(d, fs::perms::owner_all, ec);
        }

    // Build: each submitted file compiled in the jail, checked, its non-API symbols localized.
    std::map<std::string, fs::path> student_objects;
    std::map<int, std::string> build_errors;  // stage -> what the student sees
    for (const auto& s : graded)
        for (const auto& f : s.student_files) {
            const std::string key = s.folder + "/" + f;
            if (!in.files.count(key) || g_interrupted) continue;
            std::string name = key;
            std::replace(name.begin(), name.end(), '/', '_');
            const fs::path raw = trusted_dir(scratch / "objects" / name) / (name + ".o");
            std::string compile_log;
            if (!compile_in_jail(w, plan, key, in.files[key], scratch / "compile" / name, raw,
                                 compile_log)) {
                build_errors[s.number] += key + " does not compile. The compiler's first errors:\n\n" +
                                          first_errors(compile_log);
                continue;
            }
            const fs::path local = raw.parent_path() / (name + ".local.o");
            const auto api = plan.api.count(key) ? plan.api.at(key) : std::set<std::string>{};
            const std::string problems = check_and_localize(raw, api, plan, local);
            if (!problems.empty()) {
                build_errors[s.number] +=
                    key + " defines symbols or sections the grader does not allow (main, test "
                          "code, framework functions, code that runs before main). Remove them:\n" +
                    problems;
                continue;
            }
            student_objects[key] = local;
        }
    // A starter tree has no solutions: the stages before a graded one use the tree's own files
    // (compiled here like any student file; the stub when they do not compile).
    std::map<std::string, fs::path> own_solutions;
    for (const auto& key : plan.solution_from_source) {
        if (student_objects.count(key)) {
            own_solutions[key] = student_objects[key];
            continue;
        }
        std::string text;
        std::error_code ec;
        if (!fs::is_regular_file(o.source / key, ec)) continue;
        text = read_text(o.source / key);
        std::string name = key;
        std::replace(name.begin(), name.end(), '/', '_');
        const fs::path raw = trusted_dir(scratch / "objects" / (name + "-own")) / (name + ".o");
        std::string compile_log;
        const auto api = plan.api.count(key) ? plan.api.at(key) : std::set<std::string>{};
        if (compile_in_jail(w, plan, key, text, scratch / "compile" / (name + "-own"), raw, compile_log) &&
            check_and_localize(raw, api, plan, raw.parent_path() / (name + ".local.o")).empty())
            own_solutions[key] = raw.parent_path() / (name + ".local.o");
    }
    auto earlier_stage_object = [&](const std::string& key) -> fs::path {
        if (!plan.solution_from_source.count(key)) return solution_object(w, key);
        const auto it = own_solutions.find(key);
        return it != own_solutions.end() ? it->second : stub_object(w, key);
    };

    // Link: per graded stage, as if it were graded alone (solutions before it, stubs after).
    std::map<int, fs::path> stage_bins;
    for (const auto& s : graded) {
        if (build_errors.count(s.number) || g_interrupted) continue;
        std::vector<fs::path> objects;
        for (const auto& t : all_specs)
            for (const auto& f : t.student_files) {
                const std::string key = t.folder + "/" + f;
                if (t.number < s.number) objects.push_back(earlier_stage_object(key));
                else if (t.number == s.number && student_objects.count(key))
                    objects.push_back(student_objects[key]);
                else objects.push_back(stub_object(w, key));
            }
        std::vector<std::string> targets{"rt"};
        for (const auto& g : s.groups)
            if (std::find(targets.begin(), targets.end(), g.binary) == targets.end())
                targets.push_back(g.binary);
        const fs::path bin = scratch / ("stage-" + two_digits(s.number)) / "bin";
        std::string link_log;
        if (!link_stage(w, plan, objects, targets, bin, link_log)) {
            std::string shown = link_log;
            for (const auto& root : {w.src.string() + "/", w.build.string() + "/", scratch.string() + "/"}) {
                std::size_t p;
                while ((p = shown.find(root)) != std::string::npos) shown.erase(p, root.size());
            }
            build_errors[s.number] += "Linking your files failed (a function of the stage's API "
                                      "missing or defined twice?):\n\n" + shown.substr(0, 4000);
            continue;
        }
        // Executable by a sandbox uid, readable by none (they hold earlier stages' solutions).
        const auto exec_only = fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec;
        fs::permissions(bin.parent_path(), exec_only);
        fs::permissions(bin, exec_only);
        for (const auto& t : targets) fs::permissions(bin / t, exec_only);
        fs::remove(bin / "librt_stages.a");
        stage_bins[s.number] = bin;
    }
    for (const auto& [stage, errors] : build_errors) {
        summary.build_failed = true;
        TestOutcome note;
        note.stage = stage;
        note.name = "Build (compiling your files): stage " + two_digits(stage);
        note.number = std::to_string(stage) + ".0";
        note.tags = {"build", "stage" + two_digits(stage)};
        note.output = "The build failed, so no test of this stage could run.\n" +
                      (g_interrupted ? std::string("(grading was interrupted during the build)\n") : errors);
        notes.insert(notes.begin(), note);
        for (auto& t : outcomes)
            if (t.stage == stage) t.output = "not run: the build failed (see the Build test)\n";
    }


    // Run every test and render in its own sandboxed child, `jobs` at a time.
    const std::vector<fs::path> hidden = hidden_dirs(w);
    std::atomic<int> survivors{0};
    auto base_spec = [&](const fs::path& binary, const fs::path& out, const fs::path& trusted) {
        RunSpec r;
        r.limits.memory_mb = 512;  // Gradescope's default container has 768 MB
        r.working_dir = out;
        r.capture_dir = trusted / "capture";
        r.binds = {{w.src, {}, false}, {binary, {}, false}, {out, {}, true}};
        r.empty_dirs = hidden;
        r.cancel = &g_interrupted;
        return r;
    };
    auto render = [&](const fs::path& binary, const Task& task, double yaw, const fs::path& dir,
                      const std::string& tag) {
        Render result;
        const fs::path out = child_dir(dir / (tag + "-out"));
        const fs::path trusted = trusted_dir(dir / (tag + "-trusted"));
        RunSpec r = base_spec(binary, out, trusted);
        r.argv = {binary.string(), "render",
                  (w.src / task.stage->folder / "scenes" / (task.scene->name + ".json")).string(),
                  "-o", (out / "render.exr").string(), "--threads", "1", "-q"};
        if (yaw != 0) {
            char text[32];
            std::snprintf(text, sizeof text, "%.3f", yaw);
            r.argv.insert(r.argv.end(), {"--yaw", text});
        }
        r.limits.wall_seconds = o.time_limit > 0 ? o.time_limit : task.stage->render_seconds;
        r.limits.cpu_seconds = int(std::ceil(r.limits.wall_seconds));
        const RunResult res = run_sandboxed(r);
        survivors += res.survivors;
        result.output = clean_output(res.output);
        if (result.output.size() > 3000) result.output.resize(3000);
        Image image;
        std::string why;
        if (!res.ok()) {
            result.output = "the renderer " + res.describe(r.limits) + "\n" + result.output;
        } else if (!copy_out(out, "render.exr", trusted / "render.exr", 512u << 20, why) ||
                   !read_render(trusted / "render.exr", image, why)) {
            result.output = why + "\n" + result.output;
        } else {
            result.ok = true;
            result.image = to_image8(image);
        }
        return result;
    };
    std::atomic<std::size_t> next{0};
    const int jobs = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
    auto worker = [&]() {
        for (std::size_t i; (i = next++) < tasks.size();) {
            if (g_interrupted) break;
            const Task& task = tasks[i];
            const auto bin_it = stage_bins.find(task.stage->number);
            if (bin_it == stage_bins.end()) continue;  // its build failed
            const fs::path bin = bin_it->second;
            TestOutcome& out = outcomes[task.outcome];
            const fs::path dir = scratch / "run" / std::to_string(i);
            fs::create_directories(dir);
            fs::permissions(dir, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
            if (!task.scene) {
                const fs::path child = child_dir(dir / "out");
                const fs::path trusted = trusted_dir(dir / "trusted");
                RunSpec r = base_spec(bin / task.binary, child, trusted);
                r.argv = {(bin / task.binary).string(), "--gtest_filter=" + task.test, "--gtest_color=no"};
                r.limits.wall_seconds = o.time_limit > 0 ? o.time_limit : task.stage->test_seconds;
                r.limits.cpu_seconds = int(std::ceil(r.limits.wall_seconds));
                VerdictChannel channel;
                r.env = {"RT_GRADE_NONCE_FD=" + std::to_string(kNonceFd),
                         "RT_GRADE_RESULT_FD=" + std::to_string(kResultFd)};
                r.pass_fds = {{channel.nonce_read, kNonceFd}, {channel.child_end, kResultFd}};
                const RunResult res = channel.ok ? run_sandboxed(r) : RunResult{};
                survivors += res.survivors;
                std::string why = channel.ok ? "" : "the grader could not open the test channel";
                const std::string records = channel.records();
                const bool passed = res.ok() && channel_passed(records, channel.nonce, task.test, why);
                out.output = trim_gtest_output(res.output);
                if (!passed) {
                    std::string head = res.ok() ? why : res.describe(r.limits);
                    if (res.end == RunResult::End::Exited && res.exit_code == 1) {
                        // GoogleTest's own verdict: say what failed in the first line.
                        const std::string first = first_failure(out.output);
                        head = first.empty() ? "failed (see the output below)" : "failed: " + first;
                    }
                    if (res.output_truncated) head += " (output truncated)";
                    out.output = head + "\n" + out.output;
                }
                out.status = passed ? "passed" : "failed";
                out.score = passed ? out.max_score : 0;
            } else {
                // The shipped view, scored against its reference...
                const Render mine = render(bin / "rt", task, 0, dir, "shipped");
                const Image8 reference = read_image8(
                    w.priv / "reference_images" / fs::path(task.stage->folder).filename() /
                    (task.scene->name + ".png"));
                out.output = mine.output;
                if (mine.ok) {
                    const ImageScore sc = score_image(mine.image, reference, task.scene->thresholds);
                    const fs::path pngs = trusted_dir(dir / "png");
                    out.student_png = png_bytes(mine.image, pngs, "student");
                    out.reference_png = png_bytes(reference, pngs, "reference");
                    out.output = sc.metrics + "\n" + mine.output;
                    double fraction = sc.compare.size_matches ? sc.fraction : 0;
                    if (sc.compare.size_matches) {
                        out.diff_png = png_bytes(sc.compare.heat_map, pngs, "diff");
                        out.metrics = sc.metrics;
                    }
                    // ... and a view no starter tree holds: the camera turned by a few degrees,
                    // rendered by the student's code and by the reference renderer here.
                    double yaw = unseen_yaw(plan.secret, digest, task.stage->folder + "/" + task.scene->name);
                    Render truth;
                    for (int attempt = 0; plan.has_reference && attempt < 3; ++attempt, yaw *= 1.8) {
                        truth = render(reference_rt, task, yaw, dir, "truth");
                        // A turn that leaves the image as shipped would test nothing.
                        if (!truth.ok || score_image(reference, truth.image, task.scene->thresholds).fraction < 1)
                            break;
                    }
                    std::string unseen;
                    if (!plan.has_reference) {
                        unseen = "(a starter tree has no reference renderer: the course's grader "
                                 "also scores an unseen view of this scene)";
                    } else if (!truth.ok) {
                        unseen = "the unseen view could not be rendered by the reference (grader problem): " +
                                 truth.output;
                        fraction = 0;
                    } else {
                        const Render theirs = render(bin / "rt", task, yaw, dir, "unseen");
                        char head[96];
                        std::snprintf(head, sizeof head, "unseen view (camera turned %.1f degrees): ", yaw);
                        if (!theirs.ok) {
                            unseen = head + theirs.output;
                            fraction = 0;
                        } else if (plan.shipped_hashes.count(pixel_hash(theirs.image))) {
                            unseen = std::string(head) + "the image is one of the shipped reference "
                                                         "images, not a render of this view: 0 points";
                            fraction = 0;
                        } else {
                            const ImageScore us = score_image(theirs.image, truth.image, task.scene->thresholds);
                            unseen = head + (us.compare.size_matches ? us.metrics : std::string("wrong size"));
                            fraction = std::min(fraction, us.compare.size_matches ? us.fraction : 0.0);
                        }
                    }
                    out.output = sc.metrics + "\n" + unseen + "\n" + mine.output;
                    out.score = std::round(out.max_score * fraction * 100) / 100;
                    if (fraction >= 1) out.status = "passed";
                }
            }
            // Workspace paths read as the student's tree: stages/..., framework/...
            for (const auto& root : {w.src.string() + "/", w.build.string() + "/", scratch.string() + "/"}) {
                std::size_t p;
                while ((p = out.output.find(root)) != std::string::npos) out.output.erase(p, root.size());
            }
            for (const auto& hint : handout_hints(out.output))
                out.output += "Read the handout: " + hint + "\n";
        }
    };
    std::vector<std::thread> pool;
    for (int j = 0; j < jobs; ++j) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    if (g_interrupted) general += "Grading was interrupted: tests not run score 0.\n";
    if (survivors > 0)
        general += "Sandbox: " + std::to_string(survivors.load()) +
                   " processes outlived their test and could not be killed.\n";

    if (!in.ignored.empty() || in.ignored_other > 0) {
        general += "Ignored files (only the student files of the graded stages are used):\n";
        for (const auto& ig : in.ignored) general += "  " + ig.path + ": " + ig.reason + "\n";
        if (in.ignored_other > 0)
            general += "  ... and " + std::to_string(in.ignored_other) + " more files outside the whitelist\n";
    }
    if (isolation != Isolation::Namespaces)
        general += "Sandbox: " + describe(isolation) + "\n";

    for (const auto& s : graded) {
        double got = 0;
        for (const auto& t : outcomes)
            if (t.stage == s.number) got += t.score;
        summary.stage_numbers.push_back(s.number);
        summary.stage_scores.push_back(got);
    }
    for (const auto& t : outcomes) {
        summary.score += t.score;
        summary.max_score += t.max_score;
    }
    summary.seconds = seconds_since(start);
    const Report report = to_report();
    if (!o.results.empty()) write_results_json(report, o.results);
    if (!o.html.empty()) write_html_report(report, o.html);
    if (!o.quiet) write_terminal_summary(report, log, o.reveal_hidden);

    std::error_code ec;
    fs::remove_all(scratch, ec);
    if (!in.temp.empty()) fs::remove_all(in.temp, ec);
    return summary;
}


}  // namespace rt::grader
