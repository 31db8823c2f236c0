// The run phase of a grading: every unit test and every render in a sandboxed child of its
// own, `jobs` at a time. Unit tests pass only through the verdict channel; scenes are scored
// on the shipped view and on an unseen view rendered by the reference here.
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <regex>
#include <string>
#include <thread>

#include "core/parallel_for.h"
#include "grading/grading.h"
#include "grading/image_scoring.h"
#include "grading/stage_specs.h"
#include "grading/test_output.h"
#include "grading/verdict_channel.h"
#include "sandbox/cpu_lease.h"
#include "util.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

// Wall-clock limit of a child per second of its CPU limit, plus slack (set_time_limits).
constexpr double kWallPerCpuSecond = 4;
constexpr double kWallSlackSeconds = 10;

// A file the child wrote, copied out through a descriptor that refuses symlinks, fifos and
// devices: the child owned the folder and could have planted anything there.
bool copy_out(const fs::path& child_dir, const std::string& name, const fs::path& to,
              std::uintmax_t cap, std::string& why) {
    const int dir = open(child_dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    const int fd =
        dir < 0 ? -1 : openat(dir, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
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

// The unseen view's camera turn, in degrees: 4 to 9, either way, from the workspace secret,
// the submission's content and the scene. The same submission gets the same view (regrades
// agree); a changed one another view, so a reference image learned from a report is useless.
double unseen_yaw(const std::string& secret, const std::string& digest, const std::string& scene) {
    const std::uint64_t h = fnv1a(scene, fnv1a(digest, fnv1a(secret)));
    const double degrees = 4 + double(h % 5001) / 1000.0;
    return (h >> 32) & 1 ? degrees : -degrees;
}

// A rendered image and how the render went.
struct Render {
    bool ok = false;
    Image8 image;
    std::string output;  // the renderer's output, or why there is no image
    double seconds = 0;  // wall-clock time of the run, measured here
};

// How many times each leaderboard run is repeated (the fastest counts), and the image size it
// renders at: large enough that tracing, not starting a process, is what is timed.
constexpr int kLeaderboardRepeats = 3;
constexpr const char* kLeaderboardWidth = "640";
constexpr const char* kLeaderboardHeight = "480";

// A failed test's first line when the worker (the student's code) ended early: how it ended and,
// from the judge's message, in which call ("CPU time limit hit (60 s, all its processes) in
// path_radiance"), rather than the judge's guess ("a crash, exit() or abort").
std::string worker_cause(const RunResult& worker, const Limits& limits, const std::string& output) {
    static const std::regex call("during a call of ([A-Za-z_][A-Za-z0-9_]*)");
    std::smatch m;
    const std::string where = std::regex_search(output, m, call) ? " in " + m[1].str() : "";
    return "your code's process: " + worker.describe(limits) + where;
}

class Runner {
  public:
    explicit Runner(Grading& g) : g_(g), hidden_(hidden_dirs(g.w)) {}

    void run(std::size_t i) {
        const GradeTask& task = g_.tasks[i];
        const auto bin_it = g_.stage_bins.find(task.stage->number);
        if (bin_it == g_.stage_bins.end()) return;  // its build failed
        TestOutcome& out = g_.outcomes[task.outcome];
        const fs::path dir = g_.scratch / "run" / std::to_string(i);
        fs::create_directories(dir);
        fs::permissions(dir, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
        if (!task.scene)
            run_unit_test(bin_it->second, task, dir, out);
        else
            score_scene(bin_it->second, task, dir, out);
        strip_workspace_roots(g_.w, g_.scratch, g_.glsl_dirs, g_.graded, out.output);
        for (const auto& hint : handout_hints(out.output))
            out.output += "Read the handout: " + hint + "\n";
    }

  private:
    RunSpec base_spec(const fs::path& binary, const fs::path& out, const fs::path& trusted) const {
        RunSpec r;
        r.limits.memory_mb = 512;  // Gradescope's default container has 768 MB
        r.working_dir = out;
        r.capture_dir = trusted / "capture";
        r.binds = {{binary, {}, false}, {out, {}, true}};
        show_workspace(g_.w, r);
        r.empty_dirs = hidden_;
        r.cancel = &g_interrupted;
        return r;
    }

    // A GPU stage's children load the graded GLSL (RT_GPU_STUDENT_DIR) and run Mesa's software
    // rasteriser: its threads count against the process limit, and its shader cache would write
    // into a home folder the child does not have. Each test compiles its own shader, which is
    // most of a GPU stage's grading: LLVM compiles 4-wide code (128-bit vectors) about 15 % faster
    // than llvmpipe's default 8-wide on AVX2 machines (stage 09's 55 tests: 12.5 s of CPU against
    // 14.8 s, docs/performance.md), for the small images the tests draw.
    void add_gpu(const GradeTask& task, RunSpec& r) const {
        const auto it = g_.glsl_dirs.find(task.stage->number);
        if (it == g_.glsl_dirs.end()) return;
        r.binds.push_back({it->second, {}, false});
        r.env.insert(r.env.end(), {"RT_GPU_STUDENT_DIR=" + it->second.string(), "LP_NUM_THREADS=2",
                                   "MESA_SHADER_CACHE_DISABLE=true", "LP_NATIVE_VECTOR_WIDTH=128"});
    }

    // The stage's seconds (or --time-limit) bound the child's work: its CPU time. The wall clock
    // only catches a child that waits instead of working, so its limit is a multiple: a busy
    // machine (a batch of gradings, CI, a shared host) stretches an honest test's wall time
    // several-fold but not its CPU time, and must never cost it its points.
    void set_time_limits(Limits& limits, double stage_seconds) const {
        const double seconds = g_.o.time_limit > 0 ? g_.o.time_limit : stage_seconds;
        limits.cpu_seconds = int(std::ceil(seconds));
        limits.wall_seconds = kWallPerCpuSecond * seconds + kWallSlackSeconds;
    }

    void run_unit_test(const fs::path& bin, const GradeTask& task, const fs::path& dir,
                       TestOutcome& out) {
        const fs::path child = child_dir(dir / "out");
        const fs::path trusted = trusted_dir(dir / "trusted");
        RunSpec r = base_spec(bin / task.binary, child, trusted);
        r.argv = {(bin / task.binary).string(), "--gtest_filter=" + task.test, "--gtest_color=no"};
        set_time_limits(r.limits, task.stage->test_seconds);
        VerdictChannel channel;
        r.env.insert(r.env.end(), {"RT_GRADE_NONCE_FD=" + std::to_string(kNonceFd),
                                   "RT_GRADE_RESULT_FD=" + std::to_string(kResultFd)});
        r.pass_fds = {{channel.nonce_read, kNonceFd}, {channel.child_end, kResultFd}};
        std::string worker_output;
        RunResult worker;
        const RunResult res =
            channel.ok ? run_judged(bin, task, dir, r, worker, worker_output) : RunResult{};
        g_.survivors += res.survivors;
        std::string why = channel.ok ? "" : "the grader could not open the test channel";
        const std::string records = channel.records();
        const bool passed = res.ok() && channel_passed(records, channel.nonce, task.test, why);
        out.output = trim_gtest_output(res.output);
        if (!worker_output.empty())
            out.output += "\nOutput of your code (the worker process):\n" + worker_output;
        if (!passed) {
            std::string head = res.ok() ? why : res.describe(r.limits);
            if (res.end == RunResult::End::Exited && res.exit_code == 1) {
                // GoogleTest's own verdict: say what failed in the first line.
                const std::string first = first_failure(out.output);
                head = first.empty() ? "failed (see the output below)" : "failed: " + first;
            }
            // The judge only sees the worker's socket close; the worker's end is the cause.
            if (!worker.ok()) head = worker_cause(worker, r.limits, out.output);
            if (res.output_truncated) head += " (output truncated)";
            out.output = head + "\n" + out.output;
        }
        out.status = passed ? "passed" : "failed";
        out.score = passed ? out.max_score : 0;
    }

    // A unit test: the judge (`judge`, the tests and their assertions, no student code) in one
    // jail, the worker (framework, student objects, and a GPU stage's GLSL) in another with a uid
    // of its own, joined by a socket pair and nothing else (framework/remote/remote_call.h). Each
    // end is closed here as soon as its process is gone, so the other sees the end of the stream.
    RunResult run_judged(const fs::path& bin, const GradeTask& task, const fs::path& dir,
                         RunSpec& judge, RunResult& worker_result, std::string& worker_output) {
        int ends[2];
        if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) return RunResult{};
        RunSpec worker = base_spec(bin / kWorker, child_dir(dir / "worker-out"),
                                   trusted_dir(dir / "worker-trusted"));
        worker.argv = {(bin / kWorker).string()};
        worker.env.push_back("RT_REMOTE_FD=" + std::to_string(kRemoteFd));
        worker.pass_fds = {{ends[1], kRemoteFd}};
        worker.limits = judge.limits;
        add_gpu(task, worker);
        const CpuLease cpu;  // each waits for the other's answers: one CPU for both
        judge.cpu = worker.cpu = cpu.cpu();
        std::thread serving([&] {
            worker_result = run_sandboxed(worker);
            close(ends[1]);
        });
        judge.env.push_back("RT_REMOTE_FD=" + std::to_string(kRemoteFd));
        judge.pass_fds.push_back({ends[0], kRemoteFd});
        RunResult result = run_sandboxed(judge);
        close(ends[0]);
        serving.join();
        g_.survivors += worker_result.survivors;
        worker_output = cap_output(clean_output(worker_result.output), 3000);
        if (!worker_result.ok())
            worker_output =
                "the worker " + worker_result.describe(worker.limits) + "\n" + worker_output;
        return result;
    }

  public:
    // The leaderboard of `task`'s stage on `task`'s scene: the student's renderer (in `bin`)
    // against the reference's, each run kLeaderboardRepeats times, interleaved, one thread, the
    // fastest run counting. A 1x1 render of the same scene times loading and building the BVH
    // alone. Every time is the wall clock of a sandboxed run measured here, not what the
    // student's program prints. Empty when a run fails.
    std::vector<LeaderboardEntry> time_leaderboard(const fs::path& bin, const GradeTask& task,
                                                   const fs::path& dir) {
        constexpr double kNone = std::numeric_limits<double>::infinity();
        double mine = kNone, reference = kNone, mine_setup = kNone;
        const std::vector<std::string> full = {"--width", kLeaderboardWidth, "--height",
                                               kLeaderboardHeight};
        const std::vector<std::string> tiny = {"--width", "1", "--height", "1"};
        for (int i = 0; i < kLeaderboardRepeats; ++i) {
            const std::string n = std::to_string(i);
            const Render m = render(bin / "rt", task, 0, dir, "lb-mine-" + n, full);
            const Render r = render(g_.reference_rt, task, 0, dir, "lb-ref-" + n, full);
            const Render s = render(bin / "rt", task, 0, dir, "lb-setup-" + n, tiny);
            if (!m.ok || !r.ok || !s.ok) return {};
            mine = std::min(mine, m.seconds);
            reference = std::min(reference, r.seconds);
            mine_setup = std::min(mine_setup, s.seconds);
        }
        const auto ms = [](double seconds) { return std::round(seconds * 1e4) / 10; };
        std::vector<LeaderboardEntry> board = {
            {"Speed (reference = 1)", std::round(reference / mine * 100) / 100, false},
            {"Render ms", ms(mine), true},
            {"Load and build ms", ms(mine_setup), true}};
        if (!task.stage->leaderboard_traversal_cost) return board;
        // Ranked by the first column: the traversal cost, which no timing noise reorders.
        const auto cost = traversal_cost(bin, task, dir);
        if (!cost) return {};
        board.insert(board.begin(), {"Traversal cost per ray", *cost, true});
        return board;
    }

    // The traversal cost of the student's tree on `task`'s scene (apps/bvh_cost.h): the
    // student's `rt bvh-dump` writes the tree, and the reference's `rt bvh-cost` checks it against
    // its own primitives and counts its own traversal through it. Nothing when either run fails
    // or the tree is not a valid BVH of the scene.
    std::optional<double> traversal_cost(const fs::path& bin, const GradeTask& task,
                                         const fs::path& dir) {
        const fs::path scene =
            g_.w.src / task.scene->folder / "scenes" / (task.scene->name + ".json");
        const fs::path dump_out = child_dir(dir / "bvh-dump-out");
        RunSpec dump = base_spec(bin / "rt", dump_out, trusted_dir(dir / "bvh-dump-trusted"));
        dump.argv = {(bin / "rt").string(), "bvh-dump", scene.string(), "-o",
                     (dump_out / "tree.bin").string()};
        set_time_limits(dump.limits, task.stage->render_seconds);
        // Readable by the reference's uid (the container mode has no bind mounts, only
        // permissions): it holds nothing but the student's own tree.
        const fs::path tree = trusted_dir(dir / "bvh-tree") / "tree.bin";
        fs::permissions(tree.parent_path(), fs::perms::owner_all | fs::perms::group_read |
                                                fs::perms::group_exec | fs::perms::others_read |
                                                fs::perms::others_exec);
        std::string why;
        const RunResult dumped = run_sandboxed(dump);
        g_.survivors += dumped.survivors;
        if (!dumped.ok() || !copy_out(dump_out, "tree.bin", tree, 256u << 20, why))
            return std::nullopt;
        const fs::path cost_out = child_dir(dir / "bvh-cost-out");
        RunSpec cost = base_spec(g_.reference_rt, cost_out, trusted_dir(dir / "bvh-cost-trusted"));
        cost.binds.push_back({tree, {}, false});
        cost.argv = {g_.reference_rt.string(), "bvh-cost", scene.string(), "--tree", tree.string()};
        set_time_limits(cost.limits, task.stage->render_seconds);
        const RunResult counted = run_sandboxed(cost);
        g_.survivors += counted.survivors;
        double per_ray = 0;
        const auto at = counted.output.find("traversal cost ");
        if (!counted.ok() || at == std::string::npos ||
            std::sscanf(counted.output.c_str() + at, "traversal cost %lf", &per_ray) != 1)
            return std::nullopt;
        return std::round(per_ray * 100) / 100;
    }

  private:
    Render render(const fs::path& binary, const GradeTask& task, double yaw, const fs::path& dir,
                  const std::string& tag, const std::vector<std::string>& extra = {}) {
        Render result;
        const fs::path out = child_dir(dir / (tag + "-out"));
        const fs::path trusted = trusted_dir(dir / (tag + "-trusted"));
        RunSpec r = base_spec(binary, out, trusted);
        r.argv = {
            binary.string(),
            "render",
            (g_.w.src / task.scene->folder / "scenes" / (task.scene->name + ".json")).string(),
            "-o",
            (out / "render.exr").string(),
            "--threads",
            "1",
            "-q"};
        r.argv.insert(r.argv.end(), extra.begin(), extra.end());
        // The student's renderer of a GPU stage is the shader; the reference is the CPU's.
        if (task.stage->gpu && binary != g_.reference_rt) {
            r.argv.push_back("--gpu");
            add_gpu(task, r);
        }
        if (yaw != 0) {
            char text[32];
            std::snprintf(text, sizeof text, "%.3f", yaw);
            r.argv.insert(r.argv.end(), {"--yaw", text});
        }
        set_time_limits(r.limits, task.stage->render_seconds);
        const RunResult res = run_sandboxed(r);
        g_.survivors += res.survivors;
        result.seconds = res.wall_seconds;
        result.output = clean_output(res.output);
        result.output = cap_output(result.output, 3000);
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
    }

    // The shipped view, scored against its reference, and a view no starter tree holds (the
    // camera turned by a few degrees), rendered by the student's code and by the reference
    // renderer here. The score is the lower of the two.
    void score_scene(const fs::path& bin, const GradeTask& task, const fs::path& dir,
                     TestOutcome& out) {
        const Render mine = render(bin / "rt", task, 0, dir, "shipped");
        const Image8 reference =
            read_image8(g_.w.priv / "reference_images" / fs::path(task.scene->folder).filename() /
                        (task.scene->name + ".png"));
        out.output = mine.output;
        if (!mine.ok) return;
        const ImageThresholds& th = task.scene->thresholds;
        const ImageScore sc = score_image(mine.image, reference, th);
        const fs::path pngs = trusted_dir(dir / "png");
        out.student_png = png_bytes(mine.image, pngs, "student");
        out.reference_png = png_bytes(reference, pngs, "reference");
        out.output = sc.metrics + "\n" + mine.output;
        double fraction = sc.compare.size_matches ? sc.fraction : 0;
        if (sc.compare.size_matches) {
            out.diff_png = png_bytes(sc.compare.heat_map, pngs, "diff");
            out.metrics = sc.metrics;
        }
        double yaw =
            unseen_yaw(g_.plan.secret, g_.digest, task.stage->folder + "/" + task.scene->name);
        Render truth;
        const bool need_unseen = fraction > 0 && g_.plan.has_reference;
        for (int attempt = 0; need_unseen && attempt < 3; ++attempt, yaw *= 1.8) {
            truth = render(g_.reference_rt, task, yaw, dir, "truth");
            // A turn that leaves the image as shipped would test nothing.
            if (!truth.ok || score_image(reference, truth.image, th).fraction < 1) break;
        }
        std::string unseen;
        if (fraction <= 0) {
            // The score is the lower of the two views: nothing the unseen one shows can change
            // it, so neither it nor the reference's image of it is rendered.
            unseen = "unseen view: not rendered (the shipped view already scores 0)";
        } else if (!g_.plan.has_reference) {
            unseen =
                "(a starter tree has no reference renderer: the course's grader "
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
            } else if (g_.plan.shipped_hashes.count(pixel_hash(theirs.image))) {
                unseen = std::string(head) +
                         "the image is one of the shipped reference "
                         "images, not a render of this view: 0 points";
                fraction = 0;
            } else {
                const ImageScore us = score_image(theirs.image, truth.image, th);
                unseen = head + (us.compare.size_matches ? us.metrics : std::string("wrong size"));
                fraction = std::min(fraction, us.compare.size_matches ? us.fraction : 0.0);
            }
        }
        out.output = sc.metrics + "\n" + unseen + "\n" + mine.output;
        out.score = std::round(out.max_score * fraction * 100) / 100;
        if (fraction >= 1) out.status = "passed";
    }

    Grading& g_;
    const std::vector<fs::path> hidden_;
};

}  // namespace

void time_leaderboard(Grading& g) {
    if (!g.plan.has_reference || g_interrupted) return;
    Runner runner(g);
    for (std::size_t i = 0; i < g.tasks.size(); ++i) {
        const GradeTask& task = g.tasks[i];
        const auto bin = g.stage_bins.find(task.stage->number);
        // Only a renderer that draws the scene right: a fast wrong image would lead the board.
        if (!task.scene || task.scene->name != task.stage->leaderboard_scene ||
            bin == g.stage_bins.end() || g.outcomes[task.outcome].status != "passed")
            continue;
        const fs::path dir = g.scratch / "leaderboard";
        fs::create_directories(dir);
        fs::permissions(dir, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
        g.leaderboard = runner.time_leaderboard(bin->second, task, dir);
        return;  // Gradescope has one leaderboard per assignment
    }
}

void run_tests_and_scenes(Grading& g) {
    Runner runner(g);
    const int jobs = g.o.jobs > 0 ? g.o.jobs : default_thread_count();
    g.finished.assign(g.outcomes.size(), false);
    parallel_for(g.tasks.size(), jobs, [&](std::size_t i) {
        if (g_interrupted) return;  // once interrupted, the rest are skipped
        runner.run(i);
        if (g.o.autolab_scores) print_autolab_scores(g, g.tasks[i].outcome);
    });
}

}  // namespace rt::grader
