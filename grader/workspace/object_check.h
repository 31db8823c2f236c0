// What the grader reads out of object files: their defined global symbols (nm), and the check
// and localization of a student's object before it is linked (object_check.cpp).
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "workspace/workspace.h"

namespace rt::grader {

// Defined global symbols of an object or archive: {name, nm type letter}.
std::vector<std::pair<std::string, std::string>> defined_symbols(const std::filesystem::path& file);
// A strong definition (text, data, bss, read-only data).
bool strong(const std::string& type);

// Refuses what must not reach the link (main, test or framework symbols, code that runs before
// main), then writes `out` with every global symbol but the API localized. Returns the problems,
// one per line ("" when the object is fine).
std::string check_and_localize(const std::filesystem::path& object,
                               const std::set<std::string>& api, const BuildPlan& plan,
                               const std::filesystem::path& out);

}  // namespace rt::grader
