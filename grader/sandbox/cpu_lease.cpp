#include "sandbox/cpu_lease.h"

#include <sched.h>

#include <mutex>

namespace rt::grader {
namespace {

std::mutex g_mutex;
int g_leases[CPU_SETSIZE] = {};  // per CPU number: the leases held now

}  // namespace

CpuLease::CpuLease() {
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    if (sched_getaffinity(0, sizeof allowed, &allowed) != 0) return;
    // On a tie, the CPU this thread runs on now: the scheduler put it where there was room, so
    // two graders on one machine (CTest's parallel tests) do not both start on CPU 0.
    const int here = sched_getcpu();
    std::lock_guard lock(g_mutex);
    if (here >= 0 && here < CPU_SETSIZE && CPU_ISSET(here, &allowed)) cpu_ = here;
    for (int c = 0; c < CPU_SETSIZE; ++c)
        if (CPU_ISSET(c, &allowed) && (cpu_ < 0 || g_leases[c] < g_leases[cpu_])) cpu_ = c;
    if (cpu_ >= 0) ++g_leases[cpu_];
}

CpuLease::~CpuLease() {
    if (cpu_ < 0) return;
    std::lock_guard lock(g_mutex);
    --g_leases[cpu_];
}

void pin_to_cpu(int cpu) {
    if (cpu < 0 || cpu >= CPU_SETSIZE) return;
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpu, &one);
    sched_setaffinity(0, sizeof one, &one);
}

}  // namespace rt::grader
