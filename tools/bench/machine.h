// What the benchmark reports say about the machine they ran on.
#pragma once

#include <string>

namespace rt::bench {

// The processor's model name from /proc/cpuinfo, or `unknown` when it names none.
std::string cpu_model(const std::string& unknown);

}  // namespace rt::bench
