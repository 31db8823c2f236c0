// Work shared by threads: each thread takes the next item from one counter, so which thread does
// an item never changes the item's arithmetic (images stay bit-identical for any thread count).
// Used by the render loop (tiles), the grader (sandboxed runs) and rt-bench (ray chunks).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace rt {

// The threads "all cores" means: the hardware's count, at least 1 (the standard may answer 0).
inline int default_thread_count() {
    return int(std::max(1u, std::thread::hardware_concurrency()));
}

// Calls work(i) for every i in [0, count) on `threads` threads at most (the caller's one among
// them, and never more threads than items); returns when every item is done.
template <typename Work>
void parallel_for(std::size_t count, int threads, Work&& work) {
    std::atomic<std::size_t> next{0};
    const auto worker = [&] {
        for (std::size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < count;) work(i);
    };
    const std::size_t helpers =
        std::min(std::size_t(std::max(threads, 1)), std::max(count, std::size_t(1))) - 1;
    std::vector<std::jthread> pool;  // joined when it goes out of scope
    pool.reserve(helpers);
    for (std::size_t t = 0; t < helpers; ++t) pool.emplace_back(worker);
    worker();
}

}  // namespace rt
