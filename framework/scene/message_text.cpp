// How scene messages show words and choices (scene/message_text.h).
#include "scene/message_text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>

namespace rt::scene_internal {

namespace {

using json = nlohmann::json;

// Case-insensitive Levenshtein distance, for "did you mean ...?".
std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t above = row[j];
            bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string quote(const std::string& s) {
    std::string shown = json(s.size() > 60 ? s.substr(0, 57) + "..." : s)
                            .dump(-1, ' ', false, json::error_handler_t::replace);
    return shown;
}

std::string list_of(const std::vector<std::string>& options) {
    std::string out;
    for (std::size_t i = 0; i < options.size(); ++i) {
        if (i > 0) out += i + 1 == options.size() ? " or " : ", ";
        out += "\"" + options[i] + "\"";
    }
    return out;
}

std::optional<std::string> closest(const std::string& word,
                                   const std::vector<std::string>& options) {
    if (word.size() > 64) return std::nullopt;
    auto lower = [](std::string s) {
        for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    if (word.size() >= 3)  // an abbreviation such as "ortho"
        for (const std::string& option : options)
            if (lower(option).rfind(lower(word), 0) == 0) return option;
    std::optional<std::string> best;
    std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
    for (const std::string& option : options) {
        std::size_t d = edit_distance(word, option);
        if (d < best_distance) {
            best = option;
            best_distance = d;
        }
    }
    return best;
}

std::string suggestion(const std::string& word, const std::vector<std::string>& options) {
    if (auto near = closest(word, options)) return "did you mean \"" + *near + "\"?";
    return "use " + list_of(options);
}

}  // namespace rt::scene_internal
