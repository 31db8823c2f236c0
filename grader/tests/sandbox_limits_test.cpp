// The sandbox's two time limits, each on the kind of child it exists for: CPU time stops a
// child that works too long, the wall clock one that waits (grading/grade_run.cpp sets the wall
// limit to a multiple of the CPU limit, so a loaded machine never times out honest work).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "sandbox/sandbox.h"
#include "testing/skip.h"

namespace {

namespace fs = std::filesystem;

rt::grader::RunSpec sandbox_limits_spec(const char* script, int cpu, double wall) {
    rt::grader::RunSpec spec;
    spec.argv = {"/bin/sh", "-c", script};
    spec.working_dir = "/";
    spec.capture_dir =
        fs::temp_directory_path() /
        ("rt-sandbox-limits-" + std::to_string(getpid()) + "-" + std::to_string(cpu));
    spec.limits.cpu_seconds = cpu;
    spec.limits.wall_seconds = wall;
    return spec;
}

TEST(SandboxLimits, TheCpuLimitStopsAChildThatWorks) {
    // Far below the wall limit: a spinning child ends on its CPU time, however busy the host.
    const auto spec = sandbox_limits_spec("while :; do :; done", 1, 120);
    const auto result = rt::grader::run_sandboxed(spec);
    EXPECT_NE(result.end, rt::grader::RunResult::End::TimedOut) << result.describe(spec.limits);
    EXPECT_NE(result.describe(spec.limits).find("CPU"), std::string::npos)
        << result.describe(spec.limits);
    EXPECT_LT(result.wall_seconds, 100);
    fs::remove_all(spec.capture_dir);
}

TEST(SandboxLimits, TheCpuLimitCountsEveryProcessOfTheRun) {
    // Four spinners, each far below the limit on its own: together they pass it.
    const auto spec =
        sandbox_limits_spec("for i in 1 2 3 4; do (while :; do :; done) & done; wait", 3, 120);
    const auto result = rt::grader::run_sandboxed(spec);
    if (result.uid == 0)
        RT_SKIP_IN_STARTER_TREE() << "no sandbox uid (not root): per-process limits only";
    EXPECT_EQ(result.end, rt::grader::RunResult::End::CpuLimit) << result.describe(spec.limits);
    EXPECT_EQ(result.describe(spec.limits), "CPU time limit hit (3 s, all its processes)");
    EXPECT_LT(result.wall_seconds, 100);
    fs::remove_all(spec.capture_dir);
}

TEST(SandboxLimits, TheWallClockStopsAChildThatWaits) {
    // A sleeping child uses no CPU time: only the wall clock ends it.
    const auto spec = sandbox_limits_spec("sleep 600", 5, 1);
    const auto result = rt::grader::run_sandboxed(spec);
    EXPECT_EQ(result.end, rt::grader::RunResult::End::TimedOut) << result.describe(spec.limits);
    EXPECT_EQ(result.describe(spec.limits), "timed out after 1 s");
    EXPECT_LT(result.wall_seconds, 60);
    fs::remove_all(spec.capture_dir);
}

}  // namespace
