// The stub mechanism: what a released starter tree runs where a solution was removed.
//
//   RT_NOT_IMPLEMENTED("stages/02-intersections/README.md#ray-sphere");
//
// prints once per call site, on stderr,
//   not implemented: intersect_sphere (stages/02-intersections/intersections.cpp:57);
//   read stages/02-intersections/README.md#ray-sphere
// and counts the call, so the renderer paints the pixel magenta (visibly wrong) and the stage
// tests fail even where a stub's return value happens to be right.
#pragma once

#include <atomic>
#include <cstdint>

namespace rt {

void report_not_implemented(const char* function, const char* file, int line, const char* handout,
                            std::atomic<bool>& reported);

// A GPU loop of the student's that ran `limit` times in one invocation (gpu/gl/shader_source.h's
// guard): reported once per loop like a stub, and counted as one, so the tests fail.
void report_endless_loop(const char* file, int line, int limit, std::atomic<bool>& reported);

// Stubs reached so far, by all threads / by the calling thread.
std::uint64_t stub_calls_total();
std::uint64_t stub_calls_this_thread();

// While one lives, this thread's stubs are counted and tell it they were reached, but print
// nothing (the call site's one message is kept for a real use). For a framework probe of optional student work (the viewer tries stage 06's build_bvh on a big
// scene), so a starter tree that has not reached that stage hears nothing of it.
class QuietStubs {
  public:
    QuietStubs();
    ~QuietStubs();
    QuietStubs(const QuietStubs&) = delete;
    QuietStubs& operator=(const QuietStubs&) = delete;
    bool reached() const { return reached_; }

  private:
    friend void report_not_implemented(const char*, const char*, int, const char*,
                                       std::atomic<bool>&);
    QuietStubs* outer_;
    bool reached_ = false;
};

// Counts `n` stub calls made on this thread's behalf by another process: the grading worker
// that runs the student's code for a judge (framework/remote/).
void count_stub_calls(std::uint64_t n);

}  // namespace rt

#define RT_NOT_IMPLEMENTED(handout)                                                        \
    do {                                                                                   \
        static std::atomic<bool> rt_reported_{false};                                      \
        ::rt::report_not_implemented(__func__, __FILE__, __LINE__, handout, rt_reported_); \
    } while (0)
