// Small helpers of the trusted grader: hashing, shell commands it runs itself. Files and HTML
// escaping: core/text_file.h; base64 and seconds_since: core/.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base64.h"
#include "core/seconds_since.h"
#include "core/text_file.h"

namespace rt::grader {

// Without leading and trailing white space (' ', \t, \n, \r, \v, \f).
std::string_view trim(std::string_view s);

std::string shell_quote(const std::string& word);
// Runs a trusted command line through /bin/sh; returns its exit code, output in `output`.
int run_trusted(const std::string& command, std::string* output = nullptr);
// A trusted shell command's standard output (standard error untouched), or nullopt when it
// could not run or exited non-zero.
std::optional<std::string> command_output(const std::string& command);
// Runs argv (argv[0] an absolute path) in `cwd` without a shell; stdout and stderr in `output`.
int run_argv(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
             std::string& output);

std::uint64_t fnv1a(std::string_view data, std::uint64_t hash = 1469598103934665603ull);
std::string hex(std::uint64_t value);

std::string two_digits(int n);  // "07": stage numbers as folders and test names spell them

// gtest-style pattern: '*' any run, '?' one character.
bool glob_match(std::string_view pattern, std::string_view text);

// A CSV cell: quoted, quotes doubled, and text a spreadsheet would run as a formula (a first
// character of = + - @, a tab or a carriage return: OWASP's CSV injection list) behind a ' that
// makes it text. Every cell a student's text reaches goes through it (scores.csv, changes.csv,
// pairs.csv).
std::string csv_cell(std::string_view text);

// Drops ANSI escapes and bytes that are not printable UTF-8-ish text.
std::string clean_output(std::string_view text);

// A Gradescope time as seconds since the epoch, UTC: "2018-07-01T14:22:32.365935-07:00" (ISO 8601
// with an offset or Z, as submission_metadata.json writes it) or "2018-07-01 14:22:32.365935000
// -0700" (an export's submission_metadata.yml); nothing when the text is not such a time.
std::optional<std::int64_t> parse_iso8601(const std::string& text);

}  // namespace rt::grader
