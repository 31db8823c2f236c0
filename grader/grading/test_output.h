// What a test's output says, boiled down for the report: the handout sections it names, the
// GoogleTest noise removed, the first failure as one line, the compiler's first errors.
#pragma once

#include <string>
#include <vector>

namespace rt::grader {

std::vector<std::string> handout_hints(const std::string& output);  // "stages/...md#section"
std::string trim_gtest_output(const std::string& raw);
// `text` cut to about `limit` characters at a line's end, every handout pointer line ("; read
// stages/...") after the cut kept.
std::string cap_output(const std::string& text, std::size_t limit);
std::string first_failure(const std::string& output);
std::string first_errors(const std::string& compiler_log);

}  // namespace rt::grader
