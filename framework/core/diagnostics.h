// One-line diagnostics: every error the framework reports is a single line in compiler form
// (`file:line:col: error: what; fix`), so messages from libraries that span lines are folded.
// Library code names the place it knows (a file, a file and line) and never the program: a
// message with no place gets the program's name where it is printed (error_line).
#pragma once

#include <string>

namespace rt {

// Control characters (newlines, tabs, ...) become spaces; trailing spaces are dropped.
inline std::string one_line(std::string text) {
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

// The line `program` prints for an error `message` it caught: the message as it is when it says
// where in compiler form ("scene.json:3:5: error: ..."), else "program: error: message".
inline std::string error_line(const std::string& program, const std::string& message) {
    const std::size_t end = message.find('\n');
    if (message.substr(0, end).find(": error: ") != std::string::npos) return message;
    return program + ": error: " + message;
}

}  // namespace rt
