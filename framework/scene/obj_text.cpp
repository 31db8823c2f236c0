// Line-level reading of OBJ and MTL text (scene/obj_text.h).
#include "scene/obj_text.h"

#include <charconv>
#include <cmath>
#include <cstring>

#include "core/diagnostics.h"
#include "core/text_file.h"
#include "scene/obj_loader.h"

namespace rt::obj_internal {

namespace fs = std::filesystem;

void fail(const std::string& name, std::size_t line, const std::string& what,
          const std::string& fix) {
    std::string message = "mesh \"" + name + "\"";
    if (line > 0) message += " line " + std::to_string(line);
    throw ObjError(one_line(message + ": " + what + "; " + fix));
}

std::string shown(std::string_view s) {
    std::string out = "\"";  // built step by step: GCC 12 -O3 warns falsely on "\"" + s + "\""
    out.append(s.substr(0, 40));
    out += '"';
    return out;
}

std::string read_mesh_file(
    const fs::path& file, std::uintmax_t max_bytes, const char* what_it_should_be,
    const std::function<void(const std::string& what, const std::string& fix)>& complain) {
    return read_text_file(file, max_bytes, [&](const FileProblem& problem) {
        switch (problem.kind) {
            case FileProblem::Missing:
                complain("file not found (looked for \"" + file.string() + "\")",
                         "check the path, which is relative to the folder of the file that names "
                         "it");
                break;
            case FileProblem::Directory:
                complain(std::string("is a directory, not ") + what_it_should_be,
                         "name the file itself");
                break;
            case FileProblem::CannotOpen:
                complain(
                    std::string("cannot be opened (") + std::strerror(problem.open_errno) + ")",
                    "check the file's permissions");
                break;
            case FileProblem::TooLarge:
                complain("is larger than " + std::to_string(max_bytes >> 20) + " MiB",
                         "use a smaller file");
                break;
            case FileProblem::ReadError:
                complain("could not be read", "check the file");
                break;
        }
    });
}

std::vector<std::string_view> words(std::string_view s) {
    std::vector<std::string_view> out;
    std::size_t pos = 0;
    while ((pos = s.find_first_not_of(" \t", pos)) != std::string_view::npos) {
        std::size_t end = s.find_first_of(" \t", pos);
        if (end == std::string_view::npos) end = s.size();
        out.push_back(s.substr(pos, end - pos));
        pos = end;
    }
    return out;
}

bool is_directive(std::string_view line, std::string_view keyword) {
    return line.size() > keyword.size() && line.substr(0, keyword.size()) == keyword &&
           (line[keyword.size()] == ' ' || line[keyword.size()] == '\t');
}

Number parse_number(std::string_view word, double& value) {
    std::string_view digits = word.substr(!word.empty() && word[0] == '+' ? 1 : 0);
    value = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    bool whole_word = end == digits.data() + digits.size();
    if (ec == std::errc::result_out_of_range && whole_word) {
        // from_chars says this for overflow (1e999) and for underflow (1e-999); only the first
        // is a problem, the second reads as 0.
        std::size_t e = digits.find_first_of("eE");
        if (e != std::string_view::npos && e + 1 < digits.size() && digits[e + 1] == '-')
            return Number::Ok;
        return Number::NotFinite;
    }
    if (ec != std::errc() || !whole_word) return Number::NotANumber;
    return std::isfinite(value) ? Number::Ok : Number::NotFinite;
}

std::string_view directive_argument(std::string_view s, std::size_t keyword_size) {
    std::string_view rest = s.substr(std::min(keyword_size, s.size()));
    const std::size_t first = rest.find_first_not_of(" \t");
    if (first == std::string_view::npos) return {};
    const std::size_t last = rest.find_last_not_of(" \t");
    return rest.substr(first, last - first + 1);
}

bool is_wide_text(const std::string& text) {
    const auto byte = [&](std::size_t i) {
        return i < text.size() ? (unsigned char)text[i] : 0x100u;
    };
    if ((byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF)) return true;
    // Without a mark: ASCII in UTF-16 is a zero byte beside each character, in the first
    // 16 code units at least (binary files with stray zero bytes do not look like that).
    const std::size_t units = std::min<std::size_t>(text.size() / 2, 16);
    if (units < 4) return false;
    bool little = true, big = true;
    for (std::size_t u = 0; u < units; ++u) {
        const unsigned lo = byte(2 * u), hi = byte(2 * u + 1);
        const auto ascii = [](unsigned c) {
            return c == '\t' || c == '\n' || c == '\r' || (c >= 32 && c < 127);
        };
        little = little && hi == 0 && ascii(lo);
        big = big && lo == 0 && ascii(hi);
    }
    return little || big;
}

}  // namespace rt::obj_internal
