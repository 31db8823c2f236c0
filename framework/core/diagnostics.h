// One-line diagnostics: every error the framework reports is a single line in compiler form
// (`file:line:col: error: what; fix`), so messages from libraries that span lines are folded.
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

}  // namespace rt
