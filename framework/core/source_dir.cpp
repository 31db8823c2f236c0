#include "core/source_dir.h"

namespace rt {

const std::filesystem::path& source_dir() {
    static const std::filesystem::path dir = RT_SOURCE_DIR;
    return dir;
}

}  // namespace rt
