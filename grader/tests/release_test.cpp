// Tests of `rt-grade release`: the marker rewriting on in-memory text, and whole releases of
// small throw-away source trees.
//
// Marker lines are always written inside string literals here, never as whole lines of this
// file: a whole-line marker outside stages/ would make the real release refuse this file.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>

#include <unistd.h>

#include "release/release.h"
#include "testing/skip.h"

namespace fs = std::filesystem;
using rt::grader::Marker;
using rt::grader::MarkerResult;
using rt::grader::process_markers;
using rt::grader::RegionMode;

namespace {

// Joins lines with "\n", with a final newline.
std::string text(std::initializer_list<std::string_view> lines) {
    std::string out;
    for (std::string_view line : lines) {
        out += line;
        out += '\n';
    }
    return out;
}

// A function with one solution region, as the stage files write it.
const std::string kSolvedFunction = text({
    "bool hit(const Ray& ray) {",
    "    // BEGIN SOLUTION",
    "    const Real a = dot(ray.d, ray.d);",
    "    return a > 0;",
    "    // STUB",
    "    // RT_NOT_IMPLEMENTED(\"stages/02-intersections/README.md#ray-sphere\");",
    "    // return false;",
    "    // END SOLUTION",
    "}",
});

// Expects exactly one error, on `line`, whose message contains `needle`.
void expect_single_error(const MarkerResult& result, int line, std::string_view needle) {
    ASSERT_EQ(result.errors.size(), 1u) << (result.errors.empty() ? "" : result.errors[0].message);
    EXPECT_EQ(result.errors[0].line, line);
    EXPECT_NE(result.errors[0].message.find(needle), std::string::npos) << result.errors[0].message;
    EXPECT_TRUE(result.errors[0].message.starts_with("error: ")) << result.errors[0].message;
    EXPECT_NE(result.errors[0].message.find("; "), std::string::npos)
        << "the message should say how to fix it: " << result.errors[0].message;
}

}  // namespace

TEST(Markers, ClassifiesWholeLinesWhateverTheIndentation) {
    EXPECT_EQ(rt::grader::classify_marker("// BEGIN SOLUTION"), Marker::Begin);
    EXPECT_EQ(rt::grader::classify_marker("\t\t  // BEGIN SOLUTION  \r"), Marker::Begin);
    EXPECT_EQ(rt::grader::classify_marker("        // STUB"), Marker::Stub);
    EXPECT_EQ(rt::grader::classify_marker("  // END SOLUTION"), Marker::End);
    // Not whole lines: text around the marker, or a different spelling.
    EXPECT_EQ(rt::grader::classify_marker("x = 1;  // BEGIN SOLUTION"), Marker::None);
    EXPECT_EQ(rt::grader::classify_marker("// BEGIN SOLUTION here"), Marker::None);
    EXPECT_EQ(rt::grader::classify_marker("//BEGIN SOLUTION"), Marker::None);
    EXPECT_EQ(rt::grader::classify_marker("// STUBS"), Marker::None);
    EXPECT_EQ(rt::grader::classify_marker("\"// END SOLUTION\""), Marker::None);
}

TEST(Markers, StripRemovesSolutionAndUncommentsStub) {
    const MarkerResult result = process_markers(kSolvedFunction, RegionMode::Strip);
    ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
    EXPECT_TRUE(result.has_markers);
    EXPECT_EQ(result.regions, 1);
    EXPECT_EQ(result.text,
              text({
                  "bool hit(const Ray& ray) {",
                  "    RT_NOT_IMPLEMENTED(\"stages/02-intersections/README.md#ray-sphere\");",
                  "    return false;",
                  "}",
              }));
}

TEST(Markers, KeepRemovesMarkersAndStub) {
    const MarkerResult result = process_markers(kSolvedFunction, RegionMode::Keep);
    ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
    EXPECT_EQ(result.regions, 1);
    EXPECT_EQ(result.text, text({
                               "bool hit(const Ray& ray) {",
                               "    const Real a = dot(ray.d, ray.d);",
                               "    return a > 0;",
                               "}",
                           }));
}

TEST(Markers, UncommentKeepsEachLinesIndentation) {
    const std::string input = text({
        "\tint f() {",
        "\t\t// BEGIN SOLUTION",
        "\t\treturn 1;",
        "  // STUB",  // the markers' own indentation does not matter
        "\t\t// if (x) {",
        "\t\t//     y();",  // only the first "// " goes: inner indentation stays
        "\t\t// }",
        "\t\t//return 0; // why",  // no space after "//": remove just "//"
        "\t\t//",                  // an empty comment becomes an empty line
        "",                        // blank lines in a stub are kept
        "        // END SOLUTION",
        "\t}",
    });
    const MarkerResult result = process_markers(input, RegionMode::Strip);
    ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
    EXPECT_EQ(result.text, text({
                               "\tint f() {",
                               "\t\tif (x) {",
                               "\t\t    y();",
                               "\t\t}",
                               "\t\treturn 0; // why",
                               "",
                               "",
                               "\t}",
                           }));
}

TEST(Markers, SeveralRegionsAndUnmarkedTextUntouched) {
    const std::string input = kSolvedFunction + "\n// a comment that stays\n" + kSolvedFunction;
    const MarkerResult stripped = process_markers(input, RegionMode::Strip);
    ASSERT_TRUE(stripped.errors.empty());
    EXPECT_EQ(stripped.regions, 2);
    EXPECT_NE(stripped.text.find("\n// a comment that stays\n"), std::string::npos);
    EXPECT_EQ(stripped.text.find("SOLUTION"), std::string::npos);
    EXPECT_EQ(stripped.text.find("dot("), std::string::npos);

    const MarkerResult kept = process_markers(input, RegionMode::Keep);
    ASSERT_TRUE(kept.errors.empty());
    EXPECT_EQ(kept.regions, 2);
    EXPECT_EQ(kept.text.find("RT_NOT_IMPLEMENTED"), std::string::npos);
    EXPECT_EQ(kept.text.find("SOLUTION"), std::string::npos);
}

TEST(Markers, PreservesCrlfAndMissingFinalNewline) {
    const std::string input =
        "a\r\n  // BEGIN SOLUTION\r\n  x;\r\n  // STUB\r\n  // y;\r\n  // END SOLUTION\r\nlast";
    const MarkerResult result = process_markers(input, RegionMode::Strip);
    ASSERT_TRUE(result.errors.empty()) << result.errors[0].message;
    EXPECT_EQ(result.text, "a\r\n  y;\r\nlast");
}

TEST(Markers, FileWithoutMarkersIsUnchanged) {
    const std::string input = "int main() {}\n// STUB is a word here\nno newline at the end";
    for (RegionMode mode : {RegionMode::Strip, RegionMode::Keep}) {
        const MarkerResult result = process_markers(input, mode);
        EXPECT_FALSE(result.has_markers);
        EXPECT_TRUE(result.errors.empty());
        EXPECT_EQ(result.text, input);
    }
}

TEST(MarkerErrors, NestedBegin) {
    const MarkerResult result = process_markers(text({
                                                    "f() {",                // 1
                                                    "  // BEGIN SOLUTION",  // 2
                                                    "  a;",                 // 3
                                                    "  // BEGIN SOLUTION",  // 4
                                                    "  // STUB",            // 5
                                                    "  // b;",              // 6
                                                    "  // END SOLUTION",    // 7
                                                    "}",
                                                }),
                                                RegionMode::Strip);
    expect_single_error(result, 4, "opened at line 2");
}

TEST(MarkerErrors, NestedBeginInsideStub) {
    const MarkerResult result = process_markers(text({"  // BEGIN SOLUTION", "  a;", "  // STUB",
                                                      "  // BEGIN SOLUTION", "  // END SOLUTION"}),
                                                RegionMode::Strip);
    expect_single_error(result, 4, "cannot nest");
}

TEST(MarkerErrors, EndWithoutBegin) {
    const MarkerResult result =
        process_markers(text({"int x;", "", "  // END SOLUTION", "int y;"}), RegionMode::Strip);
    expect_single_error(result, 3, "without");
}

TEST(MarkerErrors, StubWithoutBegin) {
    const MarkerResult result = process_markers(text({"int x;", "// STUB"}), RegionMode::Keep);
    expect_single_error(result, 2, "without");
}

TEST(MarkerErrors, TwoStubsInOneRegion) {
    const MarkerResult result = process_markers(text({
                                                    "  // BEGIN SOLUTION",  // 1
                                                    "  a;",                 // 2
                                                    "  // STUB",            // 3
                                                    "  // b;",              // 4
                                                    "  // STUB",            // 5
                                                    "  // c;",              // 6
                                                    "  // END SOLUTION",    // 7
                                                }),
                                                RegionMode::Strip);
    expect_single_error(result, 5, "first at line 3");
}

TEST(MarkerErrors, RegionWithoutStub) {
    const MarkerResult result = process_markers(
        text({"x;", "x;", "  // BEGIN SOLUTION", "  a;", "  // END SOLUTION"}), RegionMode::Strip);
    expect_single_error(result, 5, "opened at line 3 has no");
}

TEST(MarkerErrors, StubLineNotAComment) {
    const MarkerResult result = process_markers(text({
                                                    "  // BEGIN SOLUTION",  // 1
                                                    "  a;",                 // 2
                                                    "  // STUB",            // 3
                                                    "  // fine;",           // 4
                                                    "  return false;",      // 5
                                                    "  // END SOLUTION",    // 6
                                                }),
                                                RegionMode::Keep);
    expect_single_error(result, 5, "not a comment");
}

TEST(MarkerErrors, EndOfFileInsideRegion) {
    const MarkerResult in_solution =
        process_markers(text({"x;", "  // BEGIN SOLUTION", "  a;", "  b;"}), RegionMode::Strip);
    expect_single_error(in_solution, 2, "end of the file (line 4)");
    const MarkerResult in_stub = process_markers(
        text({"  // BEGIN SOLUTION", "  a;", "  // STUB", "  // b;"}), RegionMode::Strip);
    expect_single_error(in_stub, 1, "end of the file");
}

TEST(MarkerErrors, AllErrorsReportedInLineOrder) {
    const MarkerResult result = process_markers(text({
                                                    "  // BEGIN SOLUTION",  // 1: never closed
                                                    "  // STUB",            // 2
                                                    "  // STUB",            // 3: second stub
                                                    "  oops;",              // 4: not a comment
                                                }),
                                                RegionMode::Strip);
    ASSERT_EQ(result.errors.size(), 3u);
    EXPECT_EQ(result.errors[0].line, 1);
    EXPECT_EQ(result.errors[1].line, 3);
    EXPECT_EQ(result.errors[2].line, 4);
    EXPECT_EQ(rt::grader::format_error("stages/02-x/y.cpp", result.errors[1])
                  .rfind("stages/02-x/y.cpp:3: error: ", 0),
              0u);
}

TEST(Stages, StageOfPath) {
    const auto stage = rt::grader::stage_of("stages/02-intersections/intersections.cpp");
    ASSERT_TRUE(stage);
    EXPECT_EQ(stage->number, 2);
    EXPECT_EQ(stage->folder, "stages/02-intersections");
    EXPECT_EQ(stage->relative, "intersections.cpp");
    EXPECT_EQ(rt::grader::stage_of("stages/13-bvh/sub/x.cpp")->number, 13);
    EXPECT_FALSE(rt::grader::stage_of("stages/CMakeLists.txt"));
    EXPECT_FALSE(rt::grader::stage_of("stages/misc/x.cpp"));
    EXPECT_FALSE(rt::grader::stage_of("framework/stages/01-a/x.cpp"));
}

// --- Whole releases of small source trees -------------------------------------------------

namespace {

class ReleaseTree : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root_ = fs::temp_directory_path() /
                ("rt-grade-test-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(root_);
        source_ = root_ / "src";
        out_ = root_ / "out";
        write("CMakeLists.txt", "project(x)\n");
        write("stages/01-rays/stage.json",
              R"({"number": 1, "title": "Rays", "student_files": ["rays.cpp"]})");
        write("stages/01-rays/rays.cpp", kSolvedFunction);
        write("stages/02-hits/stage.json", R"({"number": 2, "student_files": ["hits.cpp"]})");
        write("stages/02-hits/hits.cpp", kSolvedFunction);
        write("stages/02-hits/tests/hits_test.cpp", "TEST(A, B) {}\n");
        write("build/junk.o", "object");
    }
    void TearDown() override { fs::remove_all(root_); }

    void write(const std::string& relative, const std::string& content) {
        const fs::path path = source_ / relative;
        fs::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary) << content;
    }
    static std::string read(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream buffer;
        buffer << in.rdbuf();
        return buffer.str();
    }
    int release(int solved_through = 0, bool force = false, bool include_untracked = false) {
        rt::grader::ReleaseOptions options;
        options.source = source_;
        options.out = out_;
        options.solved_through = solved_through;
        options.force = force;
        options.include_untracked = include_untracked;
        log_.str("");
        errors_.str("");
        return rt::grader::run_release(options, log_, errors_);
    }

    fs::path root_, source_, out_;
    std::ostringstream log_, errors_;
};

TEST_F(ReleaseTree, StripsEveryStageAndSkipsBuildDirs) {
    ASSERT_EQ(release(), 0) << errors_.str();
    EXPECT_NE(log_.str().find("2 regions stripped, 0 regions kept"), std::string::npos)
        << log_.str();
    const std::string rays = read(out_ / "stages/01-rays/rays.cpp");
    EXPECT_NE(rays.find("    RT_NOT_IMPLEMENTED("), std::string::npos);
    EXPECT_EQ(rays.find("SOLUTION"), std::string::npos);
    EXPECT_EQ(read(out_ / "stages/02-hits/tests/hits_test.cpp"), "TEST(A, B) {}\n");
    EXPECT_TRUE(fs::exists(out_ / "stages/01-rays/stage.json"));
    EXPECT_TRUE(fs::exists(out_ / "CMakeLists.txt"));
    EXPECT_FALSE(fs::exists(out_ / "build"));
    const std::string notes = read(out_ / "RELEASE.txt");
    EXPECT_NE(notes.find("01-rays (Rays): not solved"), std::string::npos) << notes;
    EXPECT_NE(notes.find("02-hits: not solved"), std::string::npos) << notes;
    // The instructor's path stays on the instructor's machine.
    EXPECT_EQ(notes.find(source_.string()), std::string::npos) << notes;
}

// The folders that quote the solutions outside their markers (the tuned BVH back-end, the
// mutation corpus) are not in a starter tree; the rest of tools/ and grader/tests/ is.
TEST_F(ReleaseTree, LeavesOutFoldersThatQuoteTheSolutions) {
    write("tools/bench/tuned_bvh.cpp", "// the old reference, tuned\n");
    write("grader/tests/mutations/01/fov_not_halved.mutation", "find:\n  solved();\n");
    write("tools/rehearsal.sh", "echo rehearsal\n");
    write("grader/tests/trust.sh", "echo trust\n");
    ASSERT_EQ(release(), 0) << errors_.str();
    EXPECT_FALSE(fs::exists(out_ / "tools/bench"));
    EXPECT_FALSE(fs::exists(out_ / "grader/tests/mutations"));
    EXPECT_TRUE(fs::exists(out_ / "tools/rehearsal.sh"));
    EXPECT_TRUE(fs::exists(out_ / "grader/tests/trust.sh"));
}

// GLSL student files (stage 09) carry the same markers in the same // comments: stripped and
// un-commented like C++, and a .glsl file with markers must be listed in student_files too.
TEST_F(ReleaseTree, StripsGlslStudentFiles) {
    write("stages/09-gpu/stage.json", R"({"number": 9, "student_files": ["shade.glsl"]})");
    write("stages/09-gpu/shade.glsl",
          text({"vec3 shade(vec3 n, vec3 l) {", "    // BEGIN SOLUTION",
                "    return vec3(max(0.0, dot(n, l)));", "    // STUB",
                "    // RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#direct-light",
                "    // return vec3(0);", "    // END SOLUTION", "}"}));
    write("stages/09-gpu/helper.glsl", text({"// BEGIN SOLUTION", "// STUB", "// END SOLUTION"}));
    ASSERT_EQ(release(), 2);
    EXPECT_NE(errors_.str().find("stages/09-gpu/helper.glsl:1: error: file has solution markers "
                                 "but is not listed in stages/09-gpu/stage.json"),
              std::string::npos)
        << errors_.str();
    fs::remove(source_ / "stages/09-gpu/helper.glsl");
    ASSERT_EQ(release(), 0) << errors_.str();
    EXPECT_EQ(read(out_ / "stages/09-gpu/shade.glsl"),
              text({"vec3 shade(vec3 n, vec3 l) {",
                    "    RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#direct-light",
                    "    return vec3(0);", "}"}));
    fs::remove_all(out_);
    ASSERT_EQ(release(9), 0) << errors_.str();
    EXPECT_EQ(read(out_ / "stages/09-gpu/shade.glsl"),
              text({"vec3 shade(vec3 n, vec3 l) {", "    return vec3(max(0.0, dot(n, l)));", "}"}));
}

TEST_F(ReleaseTree, SolvedThroughKeepsEarlierStages) {
    ASSERT_EQ(release(1), 0) << errors_.str();
    EXPECT_NE(log_.str().find("1 regions stripped, 1 regions kept"), std::string::npos)
        << log_.str();
    const std::string rays = read(out_ / "stages/01-rays/rays.cpp");
    EXPECT_NE(rays.find("return a > 0;"), std::string::npos);
    EXPECT_EQ(rays.find("RT_NOT_IMPLEMENTED"), std::string::npos);
    EXPECT_EQ(rays.find("SOLUTION"), std::string::npos);
    EXPECT_NE(read(out_ / "stages/02-hits/hits.cpp").find("RT_NOT_IMPLEMENTED"), std::string::npos);
    const std::string notes = read(out_ / "RELEASE.txt");
    EXPECT_NE(notes.find("01-rays (Rays): solved"), std::string::npos) << notes;
    EXPECT_NE(notes.find("02-hits: not solved"), std::string::npos) << notes;
}

TEST_F(ReleaseTree, ErrorsWriteNothing) {
    write("framework/x.cpp",
          text({"int x;", "  // BEGIN SOLUTION", "  // STUB", "  // END SOLUTION"}));
    write("stages/02-hits/tests/hits_test.cpp", kSolvedFunction);  // not a student file
    write("stages/02-hits/hits.cpp", text({"a;", "  // END SOLUTION"}));
    ASSERT_EQ(release(), 2);
    const std::string errors = errors_.str();
    EXPECT_NE(errors.find("framework/x.cpp:2: error: solution markers outside a stage folder"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find("stages/02-hits/tests/hits_test.cpp:2: error: file has solution markers "
                          "but is not listed in stages/02-hits/stage.json"),
              std::string::npos)
        << errors;
    EXPECT_NE(errors.find("stages/02-hits/hits.cpp:2: error:"), std::string::npos) << errors;
    EXPECT_NE(errors.find("nothing written"), std::string::npos) << errors;
    EXPECT_FALSE(fs::exists(out_));
}

TEST_F(ReleaseTree, MissingStageJsonIsAnError) {
    fs::remove(source_ / "stages/02-hits/stage.json");
    ASSERT_EQ(release(), 2);
    EXPECT_NE(
        errors_.str().find("stages/02-hits/hits.cpp:2: error: stages/02-hits/stage.json missing"),
        std::string::npos)
        << errors_.str();
    EXPECT_FALSE(fs::exists(out_));
}

TEST_F(ReleaseTree, RefusesOutInsideSource) {
    out_ = source_ / "starter";
    ASSERT_EQ(release(), 2);
    EXPECT_NE(errors_.str().find("inside the source tree"), std::string::npos) << errors_.str();
    EXPECT_FALSE(fs::exists(out_));
    out_ = source_;
    EXPECT_EQ(release(0, true), 2);
}

TEST_F(ReleaseTree, RefusesNonEmptyOutWithoutForce) {
    fs::create_directories(out_);
    std::ofstream(out_ / "keep.txt") << "mine";
    ASSERT_EQ(release(), 2);
    EXPECT_NE(errors_.str().find("--force"), std::string::npos) << errors_.str();
    EXPECT_FALSE(fs::exists(out_ / "CMakeLists.txt"));
    ASSERT_EQ(release(0, true), 0) << errors_.str();
    EXPECT_TRUE(fs::exists(out_ / "CMakeLists.txt"));
    EXPECT_TRUE(fs::exists(out_ / "keep.txt"));  // --force writes over, never deletes
}

TEST_F(ReleaseTree, GitCheckoutCopiesOnlyTrackedFiles) {
    if (std::system("git --version > /dev/null 2>&1") != 0)
        RT_SKIP_IN_STARTER_TREE() << "git not installed";
    write(".gitignore", "/build*/\n");
    const std::string git = "git -C '" + source_.string() + "' ";
    ASSERT_EQ(
        std::system((git + "init -q && " + git + "add CMakeLists.txt stages .gitignore").c_str()),
        0);
    write("notes-untracked.txt", "private");
    write("ignored.log", "x");
    write(".gitignore", "/build*/\n*.log\n");

    ASSERT_EQ(release(), 0) << errors_.str();
    EXPECT_TRUE(fs::exists(out_ / "stages/01-rays/rays.cpp"));
    EXPECT_FALSE(fs::exists(out_ / "notes-untracked.txt"));
    EXPECT_FALSE(fs::exists(out_ / ".git"));
    EXPECT_FALSE(fs::exists(out_ / "build"));
    EXPECT_EQ(read(out_ / "stages/01-rays/rays.cpp").find("SOLUTION"), std::string::npos);

    ASSERT_EQ(release(0, true, true), 0) << errors_.str();
    EXPECT_TRUE(fs::exists(out_ / "notes-untracked.txt"));
    EXPECT_FALSE(fs::exists(out_ / "ignored.log"));
}

TEST_F(ReleaseTree, ForceRewritesOnlyChangedFiles) {
    ASSERT_EQ(release(), 0) << errors_.str();
    // Age every written file, so a rewrite shows as a newer timestamp.
    const auto old_time = fs::file_time_type::clock::now() - std::chrono::hours(1);
    for (const auto& entry : fs::recursive_directory_iterator(out_))
        if (entry.is_regular_file()) fs::last_write_time(entry.path(), old_time);
    ASSERT_EQ(release(1, true), 0) << errors_.str();
    EXPECT_EQ(fs::last_write_time(out_ / "CMakeLists.txt"), old_time);
    EXPECT_EQ(fs::last_write_time(out_ / "stages/02-hits/hits.cpp"), old_time);
    EXPECT_GT(fs::last_write_time(out_ / "stages/01-rays/rays.cpp"), old_time);  // now solved
    EXPECT_NE(read(out_ / "stages/01-rays/rays.cpp").find("return a > 0;"), std::string::npos);
}

}  // namespace
