// GLSL assembled on the host: `#include "file"` expanded (each file once), `#line N K` after
// every switch of file so the driver's messages carry our line numbers, and the source-string
// number K mapped back to a path, so an error reads
//   stages/09-gpu/intersect.glsl:12:5: error: ...
// Mesa 22 prints every message as source string 0, whatever #line says, so the line number
// carries the file as well (file k's line n is k * 100000 + n). Plain integers work with every
// compiler; file names in #line would need GL_ARB_shading_language_include (Mesa) or
// GL_GOOGLE_cpp_style_line_directive (glslang), which not every driver has.
//
// No line of a file is changed: the compiler sees the student's text as written. A student stub
// is `RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#section` (C++'s, with the section in a
// comment: GLSL has no strings), and every `while` loop is guarded; both are macros of
// shaders/student_checks.glsl that pass __LINE__. The
// assembler lists each stub and loop it reads as entry k of `stubs` (function, file, line,
// section), for the one-line report (core/not_implemented.h), and ends the shader with
// rt_stub_index, which maps the line back to k.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rt {

struct ShaderStub {
    std::string function, file;  // file as shown in messages
    int line = 0;
    std::string handout;
    // Not a stub but a `while` loop, guarded: it reports when it runs kLoopLimit times in one
    // invocation (llvmpipe would end it silently and go on with wrong values).
    bool loop = false;
    long key = 0;   // __LINE__ on its line: the file's number * 100000 + the line
    int lines = 1;  // the lines it spans (a while head may go on over several)
};

struct AssembledShader {
    std::string text;
    std::vector<std::string> files;  // by source-string number (0: the entry file)
    std::vector<ShaderStub> stubs;   // by rt_not_implemented's argument
    std::size_t code_size = 0;       // the text before rt_stub_index, which ends it
    std::string error;               // one line when an include cannot be read
};

// `entry` starts with #version; `defines` (lines of "#define X") go right after it (when it has
// no #version line, they only decide the guarded includes).
// Includes are looked up beside the including file, then in `include_dirs` in order. An include
// on the line right after `#ifdef NAME` is expanded only when `defines` defines NAME (so a file
// of one feature, such as stage 10's sampling.glsl, and its stubs are in only the shaders of
// scenes with that feature); other conditionals are left to the GLSL preprocessor.
// A do-while loop is refused with a one-line error (the `while` macro cannot guard it).
AssembledShader assemble_shader(const std::filesystem::path& entry,
                                const std::vector<std::filesystem::path>& include_dirs,
                                const std::string& defines);

// rt_stub_index (shaders/student_checks.glsl): entry k of `stubs` for __LINE__ == lines[k], -1
// for any other line (an entry whose line is 0 or less is left out). assemble_shader ends its
// text with the one for its own numbering (ShaderStub::key); an export that numbers its lines
// otherwise writes its own.
std::string stub_index_function(const std::vector<ShaderStub>& stubs,
                                const std::vector<long>& lines);

// A path as messages show it: relative to the course tree when inside it.
std::string display_path(const std::filesystem::path& path);

// Where line `line` of an assembled shader's numbering (its #line directives', hence __LINE__'s)
// is: the file (as `files` names it) and its line. Lines below the first file's code are in
// source string `source_string`.
struct ShaderLocation {
    std::string file;
    int line = 0;
};
ShaderLocation shader_location(long line, const std::vector<std::string>& files,
                               std::size_t source_string = 0);

// A compiler log (Mesa's "K:L(C): error: msg" or glslang's "ERROR: K:L: msg") with each source
// string K replaced by its file: "file:L:C: error: msg". Lines it does not recognise are kept.
std::string map_compile_log(const std::string& log, const std::vector<std::string>& files);

}  // namespace rt
