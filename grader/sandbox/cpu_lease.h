// One CPU shared by a judged test's two processes (the judge and the worker, which call each
// other thousands of times a test, each waiting for the other's answer).
//
// On different CPUs every call wakes the other process on its own CPU, and where that CPU is
// idle the wake-up costs more than the call: on this project's 2-core virtual machine stage 10's
// callback test took 22 s, and 2 s with both processes on one CPU, where a call is a plain
// switch between them (docs/grading.md, "Why a test's two processes share a CPU"). Lending the
// CPU with the fewest tests on it spreads the tests of concurrent gradings (`--jobs`, batch)
// over the CPUs the grader may use.
#pragma once

namespace rt::grader {

class CpuLease {
  public:
    CpuLease();  // the allowed CPU with the fewest leases (on a tie, the caller's CPU)
    ~CpuLease();
    CpuLease(const CpuLease&) = delete;
    CpuLease& operator=(const CpuLease&) = delete;
    int cpu() const { return cpu_; }  // -1: none (the grader's allowed CPUs are unknown)

  private:
    int cpu_ = -1;
};

// In a sandboxed child before exec: keeps the program and everything it starts on `cpu`
// (nothing when it is -1 or the kernel refuses; the program may move itself, which costs only
// its own speed).
void pin_to_cpu(int cpu);

}  // namespace rt::grader
