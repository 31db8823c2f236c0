#include "core/source_dir.h"

#include <cstdlib>

namespace rt {

const std::filesystem::path& source_dir() {
    static const std::filesystem::path dir = [] {
        const char* moved = std::getenv("RT_SOURCE_DIR");
        return std::filesystem::path(moved && *moved ? moved : RT_SOURCE_DIR);
    }();
    return dir;
}

}  // namespace rt
