// `rt-grade release`: turns the instructor's source tree (solutions included) into a student
// starter tree. Solution regions in stage files look like
//
//     <indent>// BEGIN SOLUTION
//     ...solution lines...
//     <indent>// STUB
//     <indent>// RT_NOT_IMPLEMENTED("stages/NN-name/README.md#section");
//     <indent>// return ...;
//     <indent>// END SOLUTION
//
// A released (unsolved) region keeps only the stub lines, un-commented; a solved region keeps
// only the solution lines. The markers are recognised as whole lines, whatever the indentation.
//
// This file is part of the trusted grader: it never includes or links student code.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace rt::grader {

// Where a starter tree keeps its student files' stubs as released (`rt-grade .` reads them).
inline constexpr const char* kStarterStubs = ".rt-grade/stubs";

// What to do with the solution regions of one file.
enum class RegionMode {
    Strip,  // remove the solution, un-comment the stub (stage not solved)
    Keep,   // keep the solution, drop the stub (stage solved)
};

// One problem found in a file. `line` is 1-based; `message` reads "error: ...; fix".
struct MarkerError {
    int line = 0;
    std::string message;
};

struct MarkerResult {
    std::string text;                 // the rewritten file (meaningless when errors is non-empty)
    int regions = 0;                  // complete regions found
    bool has_markers = false;         // any marker line at all, even a misplaced one
    int first_marker_line = 0;        // where to point errors about the file as a whole
    std::vector<MarkerError> errors;  // in line order
};

// The marker a line is, if it is one (whole line, surrounding whitespace ignored).
enum class Marker { None, Begin, Stub, End };
Marker classify_marker(std::string_view line);

// Rewrites the solution regions of one file held in memory. Line endings (LF or CRLF) and a
// missing final newline are preserved. Never throws on malformed input: problems go to errors.
MarkerResult process_markers(std::string_view text, RegionMode mode);

// "path:line: error: ...; fix" -- the form compilers use, so editors can jump to it.
std::string format_error(const std::string& path, const MarkerError& error);

// The stage a path (relative to the source root, '/'-separated) belongs to: stages/NN-name/...
struct StageRef {
    int number = 0;
    std::string folder;    // "stages/NN-name"
    std::string relative;  // the path inside that folder
};
std::optional<StageRef> stage_of(std::string_view relative_path);

struct ReleaseOptions {
    std::filesystem::path source;
    std::filesystem::path out;
    int solved_through = 0;          // stages 1..N keep their solutions
    bool force = false;              // allow a non-empty existing out directory
    bool include_untracked = false;  // git checkout: also copy untracked, non-ignored files
};

// Validates everything, then writes the starter tree. Returns the process exit code:
// 0 success, 2 refused (bad markers, bad --out, ...). Messages go to `log` / `errors`.
int run_release(const ReleaseOptions& options, std::ostream& log, std::ostream& errors);

}  // namespace rt::grader
