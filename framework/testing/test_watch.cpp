// A stage test's crash and CPU-time notes (testing/test_watch.h).
#include "testing/test_watch.h"

#include <cxxabi.h>
#include <execinfo.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace rt::testing {
namespace {

// Prepared in watch_test, written by the handlers: a handler only writes bytes it was given.
char g_test_name[512];
char g_crash_note[1024];
std::size_t g_crash_note_size = 0;

void write_text(const char* text, std::size_t size) {
    [[maybe_unused]] const ssize_t n = write(2, text, size);
}

void on_crash(int signal) {
    const char* name = sigabbrev_np(signal);
    const char head[] = "\n*** SIG";
    write_text(head, sizeof head - 1);
    write_text(name ? name : "?", name ? std::strlen(name) : 1);
    write_text(g_crash_note, g_crash_note_size);
    std::signal(signal, SIG_DFL);
    raise(signal);
}

// The function of a backtrace_symbols line, "prog(_ZN2rt13path_radiance...+0x1f) [0x...]",
// demangled without its parameters; "" when the line names none.
std::string function_of(const char* line) {
    const char* open = std::strchr(line, '(');
    const char* plus = open ? std::strchr(open, '+') : nullptr;
    if (!open || !plus || plus == open + 1) return "";
    const std::string mangled(open + 1, plus);
    int status = 0;
    char* plain = abi::__cxa_demangle(mangled.c_str(), nullptr, nullptr, &status);
    std::string name = status == 0 && plain ? plain : mangled;
    std::free(plain);
    return name.substr(0, name.find('('));
}

// The CPU limit: the process is past saving, so this handler may allocate and format (should
// that deadlock, in the rare case the loop was inside malloc, ctest's own timeout ends it).
void on_cpu_limit(int) {
    void* frames[64];
    const int count = backtrace(frames, 64);
    char** lines = backtrace_symbols(frames, count);
    std::string where;
    for (int i = 0; lines && i < count; ++i) {
        const std::string f = function_of(lines[i]);
        const bool ours = f.starts_with("rt::") && !f.starts_with("rt::testing") &&
                          f.find("on_cpu_limit") == std::string::npos;
        if (ours && where.find(f) == std::string::npos) where += (where.empty() ? "" : " <- ") + f;
    }
    std::fprintf(stderr,
                 "\n*** %s has used %d s of CPU time and not finished%s%s. A function that does "
                 "not return: a loop whose counter never advances (a bounce or depth that is never "
                 "incremented), a while whose condition the loop never changes, or recursion "
                 "that never reaches its end (README.md#when-a-test-crashes-or-does-not-end)\n",
                 g_test_name, kTestCpuSeconds, where.empty() ? "" : "; it was in ", where.c_str());
    std::_Exit(1);
}

// The crash note of the test named in g_test_name, ready for on_crash.
void prepare_crash_note() {
    const std::string stage = program_invocation_short_name;  // stageNN_tests, stageNN_x_tests
    const std::string label = stage.substr(0, std::min<std::size_t>(7, stage.size()));
    const std::string note =
        std::string(" in the test ") + g_test_name +
        ": your code read or wrote memory it does not own (an index past the end, a dangling "
        "reference or pointer) or recursed without end. The sanitizer build names the line: "
        "cmake --preset debug && cmake --build --preset debug --target " +
        label + " && ctest --preset debug -L " + label +
        " --output-on-failure (README.md#when-a-test-crashes-or-does-not-end)\n";
    g_crash_note_size = std::min(note.size(), sizeof g_crash_note);
    std::memcpy(g_crash_note, note.data(), g_crash_note_size);
}

// A stack of its own for the handlers: a stack overflow leaves none to report on.
void use_alternate_stack() {
    static char stack[64 * 1024];
    static const bool done = [] {
        stack_t s{};
        s.ss_sp = stack;
        s.ss_size = sizeof stack;
        return sigaltstack(&s, nullptr) == 0;
    }();
    (void)done;
}

// kTestCpuSeconds more than this process has used, unless a limit is already set (the grader's
// sandbox sets its own, lower one).
void limit_cpu_time() {
    rlimit limit{};
    if (getrlimit(RLIMIT_CPU, &limit) != 0 || limit.rlim_max != RLIM_INFINITY) return;
    rusage used{};
    getrusage(RUSAGE_SELF, &used);
    const rlim_t so_far = rlim_t(used.ru_utime.tv_sec + used.ru_stime.tv_sec) + 1;
    limit.rlim_cur = so_far + kTestCpuSeconds;
    limit.rlim_max = RLIM_INFINITY;
    setrlimit(RLIMIT_CPU, &limit);
}

}  // namespace

void watch_test(const ::testing::TestInfo& test) {
    std::snprintf(g_test_name, sizeof g_test_name, "%s.%s", test.test_suite_name(), test.name());
    prepare_crash_note();
    use_alternate_stack();
    struct sigaction action {};
    action.sa_handler = on_crash;
    action.sa_flags = SA_ONSTACK;
    for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) sigaction(signal, &action, nullptr);
    action.sa_handler = on_cpu_limit;
    sigaction(SIGXCPU, &action, nullptr);
    limit_cpu_time();
}

}  // namespace rt::testing
