// Solution markers (BEGIN SOLUTION / STUB / END SOLUTION): pure text processing, no files.
#include "release/release.h"
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

namespace {

// The marker state machine over one file: each line either a marker, which moves the state (or is
// an error), or content, which is kept, dropped or un-commented as the state and mode say.
class MarkerScanner {
  public:
    explicit MarkerScanner(RegionMode mode) : mode_(mode) {}

    void begin(int number) {
        if (state_ != State::Outside) {
            // Stay in the outer region: its END will close it, so one mistake gives one error.
            error(number, quote(kBegin) + " inside the region opened at line " +
                              std::to_string(begin_line_) +
                              " (regions cannot nest); close that region with " + quote(kEnd) +
                              " before opening another");
            return;
        }
        state_ = State::Solution;
        begin_line_ = number;
        stub_line_ = 0;
    }

    void stub(int number) {
        if (state_ == State::Outside)
            error(number, quote(kStub) + " without " + quote(kBegin) + "; add " + quote(kBegin) +
                              " above the solution lines, or delete this line");
        else if (state_ == State::Stub)
            error(number, "second " + quote(kStub) + " in the region opened at line " +
                              std::to_string(begin_line_) + " (first at line " +
                              std::to_string(stub_line_) + "); keep only one");
        else {
            state_ = State::Stub;
            stub_line_ = number;
        }
    }

    void end(int number) {
        if (state_ == State::Outside) {
            error(number, quote(kEnd) + " without " + quote(kBegin) + "; add " + quote(kBegin) +
                              " where the solution starts, or delete this line");
            return;
        }
        if (state_ == State::Solution)
            error(number, "the region opened at line " + std::to_string(begin_line_) + " has no " +
                              quote(kStub) + " section; add " + quote(kStub) +
                              " followed by the commented stub (RT_NOT_IMPLEMENTED and a "
                              "return) before " +
                              quote(kEnd));
        else
            ++result_.regions;
        state_ = State::Outside;
    }

    void content(int number, const Line& line) {
        const std::string_view text = trim(line.content);
        if (state_ == State::Outside) {
            emit(line.content, line.ending);
        } else if (state_ == State::Solution) {
            if (mode_ == RegionMode::Keep) emit(line.content, line.ending);
        } else if (text.empty()) {
            if (mode_ == RegionMode::Strip) emit({}, line.ending);  // spacing inside the stub
        } else if (!text.starts_with("//")) {
            error(number, "stub line is not a comment (in the region opened at line " +
                              std::to_string(begin_line_) + "); write it as '// " +
                              std::string(text) +
                              "' so the solved tree compiles -- release un-comments it");
        } else if (mode_ == RegionMode::Strip) {
            emit(uncomment(line.content), line.ending);
        }
    }

    // The result, with a region left open reported and the errors in line order.
    MarkerResult finish(std::size_t line_count) {
        if (state_ != State::Outside)
            error(begin_line_,
                  "the region opened here is still open at the end of the file (line " +
                      std::to_string(line_count) + "); add " + quote(kEnd) + " after its stub");
        std::stable_sort(
            result_.errors.begin(), result_.errors.end(),
            [](const MarkerError& a, const MarkerError& b) { return a.line < b.line; });
        return std::move(result_);
    }

    MarkerResult& result() { return result_; }

  private:
    enum class State { Outside, Solution, Stub };
    void error(int line, std::string message) {
        result_.errors.push_back({line, "error: " + std::move(message)});
    }
    void emit(std::string_view content, std::string_view ending) {
        result_.text += content;
        result_.text += ending;
    }

    RegionMode mode_;
    State state_ = State::Outside;
    int begin_line_ = 0, stub_line_ = 0;
    MarkerResult result_;
};

}  // namespace

MarkerResult process_markers(std::string_view text, RegionMode mode) {
    MarkerScanner scanner(mode);
    scanner.result().text.reserve(text.size());
    const std::vector<Line> lines = split_lines(text);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const int number = static_cast<int>(i) + 1;
        const Marker marker = classify_marker(lines[i].content);
        if (marker != Marker::None) {
            scanner.result().has_markers = true;
            if (scanner.result().first_marker_line == 0)
                scanner.result().first_marker_line = number;
        }
        switch (marker) {
            case Marker::Begin:
                scanner.begin(number);
                break;
            case Marker::Stub:
                scanner.stub(number);
                break;
            case Marker::End:
                scanner.end(number);
                break;
            case Marker::None:
                scanner.content(number, lines[i]);
                break;
        }
    }
    return scanner.finish(lines.size());
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
