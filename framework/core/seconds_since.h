// Wall-clock seconds since a point in time: for progress lines, timeouts and timings that are
// reported, never for anything an image depends on.
#pragma once

#include <chrono>

namespace rt {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace rt
