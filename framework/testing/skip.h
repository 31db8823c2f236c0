// RT_SKIP_IN_STARTER_TREE() << "why": a test that cannot run here stops and says why.
//
// In a starter tree (RELEASE.txt) that is a skip: a student's machine may lack a tool
// (glslangValidator, git), or the student has written the stub a test renders. In the instructor
// tree scripts/install-deps.sh installs every tool and the solutions are there, so a test that
// would skip has not run: it fails instead, with the same words. Decided at run time, so the
// test objects of both trees compile alike (the starter-tree check shares the compiler cache).
// Use it in place of GTEST_SKIP(): Format.NoPlainSkips checks.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>

#include "core/source_dir.h"

namespace rt::testing {

inline bool in_starter_tree() {
    return std::filesystem::exists(rt::source_dir() / "RELEASE.txt");
}

inline ::testing::TestPartResult::Type skip_result() {
    return in_starter_tree() ? ::testing::TestPartResult::kSkip
                             : ::testing::TestPartResult::kFatalFailure;
}

inline const char* skip_words() {
    constexpr const char* kInstructorTree =
        "skipped in the instructor tree, where every test must run (a skip is for a starter "
        "tree only); why: ";
    return in_starter_tree() ? "" : kInstructorTree;
}

}  // namespace rt::testing

// GTEST_SKIP() with the result type chosen above (GoogleTest's own macros differ only in it).
#define RT_SKIP_IN_STARTER_TREE() \
    return GTEST_MESSAGE_(::rt::testing::skip_words(), ::rt::testing::skip_result())
