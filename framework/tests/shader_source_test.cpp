// GLSL assembly on the host (gpu/gl/shader_source.h): includes expanded once each, #line numbers that
// carry the file, stubs and loops listed (never rewritten), compiler logs mapped to file:line.
#include <gtest/gtest.h>

#include <fstream>

#include "gpu/gl/shader_source.h"
#include "gpu/shader_constants.h"
#include "testing/temp_dir.h"

namespace fs = std::filesystem;

namespace rt {
namespace {

class ShaderSource : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("rt-shader-source-" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "student");
    }
    void TearDown() override { fs::remove_all(dir_); }
    void write(const std::string& name, const std::string& text) {
        std::ofstream(dir_ / name) << text;
    }
    fs::path dir_;
};

TEST_F(ShaderSource, IncludesGetLineDirectivesAndStubsAreListed) {
    write("main.comp", "#version 430\n#include \"a.glsl\"\n#include \"a.glsl\"\nvoid main() {}\n");
    write("student/a.glsl",
          "float f(float x) {\n    // RT_NOT_IMPLEMENTED();  // x.md#commented\n"
          "    RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#f\n    return x;\n}\n");
    const AssembledShader s =
        assemble_shader(dir_ / "main.comp", {dir_ / "student"}, "#define A\n");
    ASSERT_EQ(s.error, "");
    ASSERT_EQ(s.files.size(), 2u);  // a.glsl once, however often it is included
    // After #version: the constants C++ and GLSL share, the host's defines, then line 2 of main.
    EXPECT_EQ(s.text.rfind("#version 430\n" + gpu::shader_prelude() + "#define A\n#line 2 0\n", 0),
              0u)
        << s.text;
    EXPECT_NE(s.text.find("#line 100001 1\nfloat f"), std::string::npos) << s.text;
    // The stub's line as written (the macro of shaders/student_checks.glsl reports it).
    EXPECT_NE(s.text.find("\n    RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#f\n"),
              std::string::npos)
        << s.text;
    EXPECT_NE(s.text.find("#line 4 0\nvoid main"), std::string::npos) << s.text;
    ASSERT_EQ(s.stubs.size(), 1u);  // the commented one is not live
    EXPECT_EQ(s.stubs[0].function, "f");
    EXPECT_EQ(s.stubs[0].line, 3);
    EXPECT_EQ(s.stubs[0].key, 100003);  // __LINE__ there: file 1, line 3
    EXPECT_EQ(s.stubs[0].handout, "stages/09-gpu/README.md#f");
    // The table that maps __LINE__ back to the entry ends the shader.
    EXPECT_NE(s.text.find("int rt_stub_index(int line) {\n    if (line == 100003) return 0;"),
              std::string::npos)
        << s.text;
}

// A while loop is listed, as written, for the guard's report; a do-while, which the `while`
// macro cannot guard, is refused in one line that names the file and line.
TEST_F(ShaderSource, LoopsAreListedAndDoWhileIsRefused) {
    write("main.comp", "#version 430\n#include \"a.glsl\"\nvoid main() {}\n");
    write("student/a.glsl", "int f(int n) {\n    while (n > 1) n /= 2;\n    return n;\n}\n");
    const AssembledShader s = assemble_shader(dir_ / "main.comp", {dir_ / "student"}, "");
    ASSERT_EQ(s.error, "");
    ASSERT_EQ(s.stubs.size(), 1u);
    EXPECT_TRUE(s.stubs[0].loop);
    EXPECT_EQ(s.stubs[0].key, 100002);
    EXPECT_NE(s.text.find("\n    while (n > 1) n /= 2;\n"), std::string::npos) << s.text;

    // A head over two lines: Mesa's __LINE__ in the macro call is its last line, so the entry
    // covers both.
    write("student/a.glsl",
          "int f(int n) {\n    while (n >\n           1) n /= 2;\n    return n;\n}\n");
    const AssembledShader two = assemble_shader(dir_ / "main.comp", {dir_ / "student"}, "");
    ASSERT_EQ(two.stubs.size(), 1u);
    EXPECT_EQ(two.stubs[0].lines, 2);
    EXPECT_NE(two.text.find("if (line >= 100002 && line < 100002 + 2) return 0;"),
              std::string::npos)
        << two.text;

    write("student/a.glsl",
          "int f(int n) {\n    do {\n        n /= 2;\n    } while (n > 1);\n"
          "    return n;\n}\n");
    const AssembledShader refused = assemble_shader(dir_ / "main.comp", {dir_ / "student"}, "");
    EXPECT_NE(refused.error.find("student/a.glsl:2: error: a do-while loop; write it as a while"),
              std::string::npos)
        << refused.error;
}

// An include right under a guard the host's defines (or the shader's own #defines under their
// guards) do not satisfy is left out, with its stubs: a scene without textures is not told about
// texture stubs.
TEST_F(ShaderSource, GuardedIncludesAndTheirStubsFollowTheDefines) {
    write("main.comp",
          "#version 430\n#if defined(A) || defined(B)\n#define MAPS\n#endif\n"
          "#if defined(MAPS) || defined(ENV)\n#include \"t.glsl\"\n#include \"u.glsl\"\n#endif\n"
          "#ifdef ENV\n#include \"e.glsl\"\n#endif\nvoid main() {}\n");
    for (const char* f : {"t", "u", "e"})
        write(std::string("student/") + f + ".glsl",
              std::string("void ") + f + "() {\n    RT_NOT_IMPLEMENTED();  // x.md#y\n}\n");
    const auto stubs = [&](const std::string& defines) {
        std::string names;
        for (const ShaderStub& s :
             assemble_shader(dir_ / "main.comp", {dir_ / "student"}, defines).stubs)
            names += s.function;
        return names;
    };
    EXPECT_EQ(stubs(""), "");
    EXPECT_EQ(stubs("#define B\n"), "tu");  // through the shader's own MAPS
    EXPECT_EQ(stubs("#define ENV\n"), "tue");
}

TEST_F(ShaderSource, MissingIncludeNamesTheLine) {
    write("main.comp", "#version 430\n\n#include \"nowhere.glsl\"\n");
    const AssembledShader s = assemble_shader(dir_ / "main.comp", {dir_ / "student"}, "");
    EXPECT_NE(s.error.find("main.comp:3: error: include \"nowhere.glsl\" not found"),
              std::string::npos)
        << s.error;
}

TEST(ShaderLog, MesaAndGlslangMessagesBecomeFileLine) {
    const std::vector<std::string> files = {"shaders/trace.comp", "stages/09-gpu/intersect.glsl"};
    EXPECT_EQ(map_compile_log("0:100012(5): error: `x' undeclared\n", files),
              "stages/09-gpu/intersect.glsl:12:5: error: `x' undeclared\n");
    EXPECT_EQ(map_compile_log("0:7(1): warning: w\n", files),
              "shaders/trace.comp:7:1: warning: w\n");
    EXPECT_EQ(map_compile_log("ERROR: 1:100012: 'x' : undeclared identifier\nERROR: 1 compilation "
                              "errors.  No code generated.\n",
                              files),
              "stages/09-gpu/intersect.glsl:12: error: 'x' : undeclared identifier\nERROR: 1 "
              "compilation errors.  No code generated.\n");
}

}  // namespace
}  // namespace rt
