// Solution markers (BEGIN SOLUTION / STUB / END SOLUTION): pure text processing, no files.
#include "release.h"
#include "util.h"

#include <algorithm>
#include <cctype>

namespace fs = std::filesystem;

namespace rt::grader {

namespace {

constexpr std::string_view kBegin = "// BEGIN SOLUTION";
constexpr std::string_view kStub = "// STUB";
constexpr std::string_view kEnd = "// END SOLUTION";

// One line of a file: its content and its terminator ("\n", "\r\n" or "" on a last line
// without newline), kept apart so rewriting a line never changes the file's line endings.
struct Line {
    std::string_view content;
    std::string_view ending;
};

std::vector<Line> split_lines(std::string_view text) {
    std::vector<Line> lines;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t newline = text.find('\n', start);
        std::size_t end = newline == std::string_view::npos ? text.size() : newline;
        std::size_t content_end = end;
        if (newline != std::string_view::npos && content_end > start &&
            text[content_end - 1] == '\r')
            --content_end;
        std::size_t next = newline == std::string_view::npos ? text.size() : newline + 1;
        lines.push_back({text.substr(start, content_end - start),
                         text.substr(content_end, next - content_end)});
        start = next;
    }
    return lines;
}

// "<indent>// code" -> "<indent>code": the stub was written as a comment so the solved tree
// compiles; releasing it turns it back into code at the same indentation.
std::string uncomment(std::string_view content) {
    std::size_t indent = 0;
    while (indent < content.size() && (content[indent] == ' ' || content[indent] == '\t')) ++indent;
    std::string_view rest = content.substr(indent);
    rest.remove_prefix(rest.starts_with("// ") ? 3 : 2);  // caller checked it starts with "//"
    if (trim(rest).empty()) return {};                    // an empty comment line
    std::string out(content.substr(0, indent));
    out += rest;
    return out;
}

// Appends rather than `"'" + string`, which trips a GCC 12 -Wrestrict false positive.
std::string quote(std::string_view s) {
    std::string out;
    out += '\'';
    out += s;
    out += '\'';
    return out;
}

}  // namespace

Marker classify_marker(std::string_view line) {
    const std::string_view t = trim(line);
    if (t == kBegin) return Marker::Begin;
    if (t == kStub) return Marker::Stub;
    if (t == kEnd) return Marker::End;
    return Marker::None;
}

MarkerResult process_markers(std::string_view text, RegionMode mode) {
    MarkerResult result;
    result.text.reserve(text.size());
    enum class State { Outside, Solution, Stub } state = State::Outside;
    int begin_line = 0;
    int stub_line = 0;
    auto error = [&](int line, std::string message) {
        result.errors.push_back({line, "error: " + std::move(message)});
    };
    auto emit = [&](std::string_view content, std::string_view ending) {
        result.text += content;
        result.text += ending;
    };

    const std::vector<Line> lines = split_lines(text);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const int number = static_cast<int>(i) + 1;
        const Line& line = lines[i];
        const Marker marker = classify_marker(line.content);
        if (marker != Marker::None) {
            result.has_markers = true;
            if (result.first_marker_line == 0) result.first_marker_line = number;
        }
        switch (marker) {
            case Marker::Begin:
                if (state != State::Outside) {
                    // Stay in the outer region: its END will close it, so one mistake gives one
                    // error.
                    error(number, quote(kBegin) + " inside the region opened at line " +
                                      std::to_string(begin_line) +
                                      " (regions cannot nest); close that region with " +
                                      quote(kEnd) + " before opening another");
                } else {
                    state = State::Solution;
                    begin_line = number;
                    stub_line = 0;
                }
                break;
            case Marker::Stub:
                if (state == State::Outside) {
                    error(number, quote(kStub) + " without " + quote(kBegin) + "; add " +
                                      quote(kBegin) +
                                      " above the solution lines, or delete this line");
                } else if (state == State::Stub) {
                    error(number, "second " + quote(kStub) + " in the region opened at line " +
                                      std::to_string(begin_line) + " (first at line " +
                                      std::to_string(stub_line) + "); keep only one");
                } else {
                    state = State::Stub;
                    stub_line = number;
                }
                break;
            case Marker::End:
                if (state == State::Outside) {
                    error(number, quote(kEnd) + " without " + quote(kBegin) + "; add " +
                                      quote(kBegin) +
                                      " where the solution starts, or delete this line");
                } else if (state == State::Solution) {
                    error(number, "the region opened at line " + std::to_string(begin_line) +
                                      " has no " + quote(kStub) + " section; add " + quote(kStub) +
                                      " followed by the commented stub (RT_NOT_IMPLEMENTED and a "
                                      "return) before " +
                                      quote(kEnd));
                    state = State::Outside;
                } else {
                    ++result.regions;
                    state = State::Outside;
                }
                break;
            case Marker::None:
                if (state == State::Outside) {
                    emit(line.content, line.ending);
                } else if (state == State::Solution) {
                    if (mode == RegionMode::Keep) emit(line.content, line.ending);
                } else if (trim(line.content).empty()) {
                    if (mode == RegionMode::Strip)
                        emit({}, line.ending);  // spacing inside the stub
                } else if (!trim(line.content).starts_with("//")) {
                    error(number, "stub line is not a comment (in the region opened at line " +
                                      std::to_string(begin_line) + "); write it as '// " +
                                      std::string(trim(line.content)) +
                                      "' so the solved tree compiles -- release un-comments it");
                } else if (mode == RegionMode::Strip) {
                    emit(uncomment(line.content), line.ending);
                }
                break;
        }
    }
    if (state != State::Outside) {
        error(begin_line, "the region opened here is still open at the end of the file (line " +
                              std::to_string(lines.size()) + "); add " + quote(kEnd) +
                              " after its stub");
    }
    std::stable_sort(result.errors.begin(), result.errors.end(),
                     [](const MarkerError& a, const MarkerError& b) { return a.line < b.line; });
    return result;
}

std::string format_error(const std::string& path, const MarkerError& error) {
    return path + ":" + std::to_string(error.line) + ": " + error.message;
}

std::optional<StageRef> stage_of(std::string_view relative_path) {
    constexpr std::string_view prefix = "stages/";
    if (!relative_path.starts_with(prefix)) return std::nullopt;
    std::string_view rest = relative_path.substr(prefix.size());
    const std::size_t slash = rest.find('/');
    if (slash == std::string_view::npos) return std::nullopt;  // a file directly in stages/
    const std::string_view folder = rest.substr(0, slash);
    // Stage folders are "NN-name": two digits, a dash.
    if (folder.size() < 4 || !std::isdigit(static_cast<unsigned char>(folder[0])) ||
        !std::isdigit(static_cast<unsigned char>(folder[1])) || folder[2] != '-')
        return std::nullopt;
    StageRef ref;
    ref.number = (folder[0] - '0') * 10 + (folder[1] - '0');
    ref.folder = std::string(prefix) + std::string(folder);
    ref.relative = std::string(rest.substr(slash + 1));
    return ref;
}

}  // namespace rt::grader
