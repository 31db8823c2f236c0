#include "grading/test_output.h"

#include <algorithm>
#include <regex>
#include <sstream>

#include "util.h"

namespace rt::grader {

std::vector<std::string> handout_hints(const std::string& output) {
    std::vector<std::string> hints;
    static const std::regex read(R"(read (stages/[^\s;]+\.md#[A-Za-z0-9_-]+))");
    for (auto it = std::sregex_iterator(output.begin(), output.end(), read);
         it != std::sregex_iterator(); ++it)
        if (std::find(hints.begin(), hints.end(), (*it)[1].str()) == hints.end())
            hints.push_back((*it)[1].str());
    return hints;
}

std::string cap_output(const std::string& text, std::size_t limit) {
    if (text.size() <= limit) return text;
    // A stub's "not implemented: NAME (file:line); read HANDOUT" line (and a GPU shader's
    // "also a stub in this shader ...; read HANDOUT") says what to do: the lines a student must
    // see, and they come last (stderr, after the failures). Keep every such line, and cut the
    // rest at a line's end, so no handout link is left half.
    std::size_t cut = limit == 0 ? std::string::npos : text.rfind('\n', limit - 1);
    cut = cut == std::string::npos ? 0 : cut + 1;
    std::string pointers;
    std::istringstream rest(text.substr(cut));
    for (std::string line; std::getline(rest, line);)
        if (line.find("; read stages/") != std::string::npos) pointers += line + "\n";
    return text.substr(0, cut) + "[... output truncated]\n" + pointers;
}

std::string trim_gtest_output(const std::string& raw) {
    std::string out;
    std::istringstream lines(clean_output(raw));
    std::string line;
    while (std::getline(lines, line)) {
        if (line.starts_with("Running main()") || line.starts_with("Note: Google Test filter") ||
            line.starts_with("[==========]") || line.starts_with("[----------]") ||
            line.starts_with("[  PASSED  ]") || line.starts_with(" 1 FAILED TEST") ||
            line.starts_with("[ RUN      ]") || line.starts_with("[       OK ]"))
            continue;
        out += line + "\n";
    }
    return cap_output(out, 4000);
}

// The first failure of a GoogleTest output, as one line: where (the test's own line: a trace's
// call site when the check sits in a shared helper) and what (the test's message when it has
// one, else GoogleTest's first line): "camera_rays_test.cpp:58: top-left corner (0, 0) ...".
std::string first_failure(const std::string& output) {
    std::vector<std::string> lines;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::size_t i = 0;
    while (i < lines.size() && lines[i].find(": Failure") == std::string::npos) ++i;
    if (i == lines.size()) {
        // A stub: its "not implemented" line says what to do.
        for (const auto& line : lines)
            if (line.find("not implemented") != std::string::npos) return line;
        return "";
    }
    auto base = [](std::string path) {
        const auto slash = path.rfind('/');
        return slash == std::string::npos ? path : path.substr(slash + 1);
    };
    std::string where = base(lines[i].substr(0, lines[i].find(": Failure")));
    std::vector<std::string> block;
    std::size_t j = i + 1;
    for (; j < lines.size(); ++j) {
        const std::string& line = lines[j];
        if (line.empty() || line.starts_with("[") || line.starts_with("Google Test trace:") ||
            line.find(": Failure") != std::string::npos)
            break;
        block.push_back(line);
    }
    if (j < lines.size() && lines[j].starts_with("Google Test trace:") && j + 1 < lines.size()) {
        const std::string& call = lines[j + 1];
        const auto colon = call.find(": ");
        if (colon != std::string::npos) where = base(call.substr(0, colon));
    }
    // The test's own message follows GoogleTest's "... evaluates to ..." / "Which is: ..." lines.
    std::size_t last_gtest = std::string::npos;
    for (std::size_t k = 0; k < block.size(); ++k)
        if (block[k].find("evaluates to") != std::string::npos ||
            block[k].find("Which is:") != std::string::npos ||
            block[k].find("Expected:") != std::string::npos || block[k].starts_with("  Actual:"))
            last_gtest = k;
    std::string what;
    const std::size_t from =
        last_gtest == std::string::npos || last_gtest + 1 >= block.size() ? 0 : last_gtest + 1;
    for (std::size_t k = from; k < block.size(); ++k) {
        const auto first = block[k].find_first_not_of(' ');
        if (first == std::string::npos) continue;
        if (!what.empty()) what += " ";
        what += block[k].substr(first);
    }
    if (what.size() > 200) what = what.substr(0, 197) + "...";
    return where + ": " + what;
}

// The compiler's output from its first error on (warnings before it would bury it), with the
// "In function" line that names where it is.
std::string first_errors(const std::string& log) {
    std::vector<std::string> lines;
    std::istringstream in(log);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::size_t first = 0;
    while (first < lines.size() && lines[first].find("error") == std::string::npos) ++first;
    if (first == lines.size()) first = 0;
    std::size_t from = first;
    for (std::size_t i = first; i-- > 0;)
        if (lines[i].find("In function") != std::string::npos ||
            lines[i].find("In member function") != std::string::npos) {
            from = i;
            break;
        } else if (lines[i].find("warning:") != std::string::npos) {
            break;
        }
    std::string out;
    for (std::size_t i = from; i < lines.size() && i < from + 40; ++i) out += lines[i] + "\n";
    return out;
}

}  // namespace rt::grader
