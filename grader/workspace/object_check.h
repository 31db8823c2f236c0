// What the grader reads out of object files: their defined global symbols (nm), and the check
// and localization of a student's object before it is linked (declared in workspace.h).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace rt::grader {

// Defined global symbols of an object or archive: {name, nm type letter}.
std::vector<std::pair<std::string, std::string>> defined_symbols(const std::filesystem::path& file);
// A strong definition (text, data, bss, read-only data).
bool strong(const std::string& type);

}  // namespace rt::grader
