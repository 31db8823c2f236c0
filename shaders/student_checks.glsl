// How a student's GLSL reports a stub or an endless loop without the host editing its text: two
// macros of GLSL's own preprocessor. Included after the file that defines
// rt_not_implemented(int stub) (compute_io.glsl, or shadertoy.glsl for the exports).
//
// __LINE__ names the file and the line together: the assembler's #line directives number file
// k's line n as k * 100000 + n (framework/gpu/gl/shader_source.h). The assembler lists every stub
// and loop it reads, by that number, and writes rt_stub_index at the end of the shader.

int rt_stub_index(int line);  // the entry of the host's table for that line; -1 if none

// A stub in a student file: `RT_NOT_IMPLEMENTED();  // stages/09-gpu/README.md#section`. GLSL has
// no strings, and Mesa's preprocessor refuses a '#' inside a line even in a macro's argument, so
// the handout section is a comment, which the host reads.
#define RT_NOT_IMPLEMENTED() rt_not_implemented(rt_stub_index(__LINE__))

// llvmpipe ends a loop silently after some tens of thousands of iterations and goes on with wrong
// values, and a hardware driver may hang; every `while` loop of the shader therefore ends after
// kLoopLimit iterations (framework/gpu/shader_constants.h) and reports its line like a stub.
bool rt_loop_guard(int iteration, int line) {
    if (iteration < kLoopLimit) return true;
    rt_not_implemented(rt_stub_index(line));
    return false;
}
#define while(condition) for (int rt_loop = 0; rt_loop_guard(rt_loop++, __LINE__) && (condition);)
