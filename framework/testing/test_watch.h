// What a stage test says when the student's code crashes it or never lets it end.
//
// ctest alone prints "SEGFAULT" for a crash and "Timeout" after minutes for a loop that never
// ends. A stage test (StageTest::SetUp) calls watch_test, and then:
// - a crash (SIGSEGV, SIGBUS, SIGFPE, SIGILL) prints the test, what such a crash means and the
//   per-stage sanitizer build that names the line, before the default action;
// - a test that has used kTestCpuSeconds of CPU time stops with the test, the functions it was
//   in (the student's first) and why a function may not return.
#pragma once

#include <gtest/gtest.h>

namespace rt::testing {

// CPU seconds a stage test may use: the slowest honest one uses under 3; ten times that under
// the sanitizers, which slow code down.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr int kTestCpuSeconds = 300;
#else
inline constexpr int kTestCpuSeconds = 30;
#endif

void watch_test(const ::testing::TestInfo& test);

}  // namespace rt::testing
