// The processor's model name (machine.h), for the accuracy report and the BVH benchmark.
#include "bench/machine.h"

#include <fstream>

namespace rt::bench {

std::string cpu_model(const std::string& unknown) {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            const std::size_t colon = line.find(':');
            if (colon != std::string::npos) return line.substr(colon + 2);
        }
    return unknown;
}

}  // namespace rt::bench
