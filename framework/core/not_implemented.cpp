#include "core/not_implemented.h"
#include "core/source_dir.h"

#include <cstdio>
#include <string>

namespace rt {
namespace {
std::atomic<std::uint64_t> g_total{0};
thread_local std::uint64_t t_this_thread = 0;
thread_local QuietStubs* t_quiet = nullptr;

// __FILE__ is absolute in CMake builds; show it relative to the source tree so the message reads
// the same on every machine and names the path a student knows.
std::string relative_to_source(const char* file) {
    std::string path(file);
    const std::string root = source_dir().string() + "/";
    if (path.rfind(root, 0) == 0) path.erase(0, root.size());
    return path;
}
}  // namespace

void report_not_implemented(const char* function, const char* file, int line, const char* handout,
                            std::atomic<bool>& reported) {
    g_total.fetch_add(1, std::memory_order_relaxed);
    ++t_this_thread;
    if (t_quiet) {  // counted, but the call site's one message is kept for a real use
        t_quiet->reached_ = true;
        return;
    }
    if (!reported.exchange(true)) {
        std::fprintf(stderr, "not implemented: %s (%s:%d); read %s\n", function,
                     relative_to_source(file).c_str(), line, handout);
        std::fflush(stderr);
    }
}

void report_endless_loop(const char* file, int line, int limit, std::atomic<bool>& reported) {
    g_total.fetch_add(1, std::memory_order_relaxed);
    ++t_this_thread;
    if (!reported.exchange(true)) {
        std::fprintf(stderr,
                     "%s:%d: this loop ran %d times for one pixel and was stopped: does it ever "
                     "end? (llvmpipe would have ended it silently, with wrong values)\n",
                     relative_to_source(file).c_str(), line, limit);
        std::fflush(stderr);
    }
}

QuietStubs::QuietStubs() : outer_(t_quiet) {
    t_quiet = this;
}
QuietStubs::~QuietStubs() {
    t_quiet = outer_;
}

std::uint64_t stub_calls_total() {
    return g_total.load(std::memory_order_relaxed);
}
std::uint64_t stub_calls_this_thread() {
    return t_this_thread;
}
void count_stub_calls(std::uint64_t n) {
    g_total.fetch_add(n, std::memory_order_relaxed);
    t_this_thread += n;
}

}  // namespace rt
