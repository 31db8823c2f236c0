// What a test's output becomes in the report (grader/test_output.h): the handout sections, and
// the cap on its length, which must never cut a handout link in half or drop a stub's line.
#include <gtest/gtest.h>

#include <string>

#include "grading/test_output.h"

namespace rt::grader {
namespace {

TEST(TestOutput, HandoutHintsAreWholeSectionsOnce) {
    const std::string out =
        "not implemented: f (stages/09-gpu/a.glsl:3); read stages/09-gpu/README.md#camera-rays\n"
        "also a stub in this shader, not reached yet: g (stages/09-gpu/b.glsl:9); read "
        "stages/09-gpu/README.md#reflection-and-refraction\n"
        "not implemented: f (stages/09-gpu/a.glsl:3); read stages/09-gpu/README.md#camera-rays\n";
    EXPECT_EQ(handout_hints(out),
              (std::vector<std::string>{"stages/09-gpu/README.md#camera-rays",
                                        "stages/09-gpu/README.md#reflection-and-refraction"}));
}

TEST(TestOutput, TheCapKeepsWholeLinesAndEveryHandoutPointer) {
    std::string out;
    for (int k = 0; k < 200; ++k) out += "line " + std::to_string(k) + " of a long failure\n";
    const std::string late =
        "also a stub in this shader, not reached yet: g (stages/09-gpu/b.glsl:9); read "
        "stages/09-gpu/README.md#reflection-and-refraction\n";
    out += late;
    for (std::size_t limit : {std::size_t(100), std::size_t(1000), std::size_t(3000)}) {
        const std::string capped = cap_output(out, limit);
        EXPECT_LT(capped.size(), limit + 200) << "limit " << limit;
        EXPECT_NE(capped.find("[... output truncated]\n"), std::string::npos);
        // Every kept line is a whole line of the output.
        const std::string head = capped.substr(0, capped.find("[... output truncated]"));
        EXPECT_EQ(out.compare(0, head.size(), head), 0);
        EXPECT_TRUE(head.empty() || head.back() == '\n') << "limit " << limit;
        EXPECT_EQ(handout_hints(capped),
                  std::vector<std::string>{"stages/09-gpu/README.md#reflection-and-refraction"})
            << "limit " << limit;
    }
    EXPECT_EQ(cap_output("short\n", 100), "short\n");
}

}  // namespace
}  // namespace rt::grader
