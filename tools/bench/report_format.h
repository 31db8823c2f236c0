// printf-style formatting of one number, shared by the accuracy report's markdown and SVG writers.
#pragma once

#include <cstdio>
#include <string>

namespace rt::bench::detail {

inline std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

}  // namespace rt::bench::detail
