// MTL material libraries: reading the libraries an OBJ file names, checked line by line, into
// scene materials for the usemtl names the scene does not supply.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/obj_check.h"
#include "scene/obj_loader.h"

namespace rt::obj_internal {

// Reads the libraries the file names and fills in the definitions of `wanted` materials (the
// first library defining a name wins). Throws ObjError for a missing or malformed library and
// for a wanted name that no library defines.
void read_libraries(const std::filesystem::path& obj_file, const std::string& name,
                    const ObjSummary& summary, std::vector<ObjMaterial>& materials,
                    const std::vector<bool>& wanted);

}  // namespace rt::obj_internal
