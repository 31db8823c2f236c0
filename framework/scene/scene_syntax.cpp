// Parsing a scene file's text into JSON, with the syntax messages (scene/scene_reader.h).
#include "scene/scene_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace rt::scene_internal {

namespace {

constexpr int kMaxNesting = 100;  // a scene needs 5 levels; this stops pathological input early

}  // namespace

void SceneReader::parse() {
    std::size_t first = text_.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || text_.compare(first, std::string::npos, "\xEF\xBB\xBF") == 0)
        fail_at(0, "the file is empty",
                "a scene file holds a JSON object such as {\"surfaces\": []}");
    check_nesting();
    try {
        root_ = json::parse(text_);
    } catch (const json::parse_error& e) {
        fail_at(e.byte > 0 ? e.byte - 1 : 0, syntax_message(e));
    } catch (const json::out_of_range&) {
        // nlohmann refuses numbers beyond double (1e999) without saying where: find it.
        positions_.emplace(text_);
        std::size_t offset = first_overflowing_number();
        std::string pointer = positions_->pointer_at(offset);
        fail_at(
            offset,
            label(pointer) + " must be a finite number, got " +
                text_.substr(offset, std::min<std::size_t>(
                                         40, text_.find_first_of(" \t\r\n,]}", offset) - offset)),
            "use an ordinary number");
    }
    positions_.emplace(text_);
    if (!positions_->duplicate_keys().empty()) {
        const std::string& pointer = positions_->duplicate_keys().front();
        fail_key(pointer, "duplicate key " + label(pointer),
                 "remove one of them (only the last one would count)");
    }
}

// nlohmann's parser copes with deep nesting, but nothing in a scene is deeper than a few
// levels, and refusing early keeps every later step cheap.
void SceneReader::check_nesting() const {
    int depth = 0;
    for (std::size_t i = 0; i < text_.size(); ++i) {
        char c = text_[i];
        if (c == '"') {
            for (++i; i < text_.size() && text_[i] != '"'; ++i)
                if (text_[i] == '\\') ++i;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxNesting)
                fail_at(i, "brackets nested more than " + std::to_string(kMaxNesting) + " deep",
                        "a scene file needs only a few levels; check the brackets");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

// The offset of the first number (outside strings) too large for a double.
std::size_t SceneReader::first_overflowing_number() const {
    for (std::size_t i = 0; i < text_.size(); ++i) {
        char c = text_[i];
        if (c == '"') {
            for (++i; i < text_.size() && text_[i] != '"'; ++i)
                if (text_[i] == '\\') ++i;
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            std::size_t end = text_.find_first_of(" \t\r\n,]}", i);
            if (end == std::string::npos) end = text_.size();
            if (std::isinf(std::strtod(text_.substr(i, end - i).c_str(), nullptr))) return i;
            i = end - 1;
        }
    }
    return 0;
}

std::string SceneReader::syntax_message(const json::parse_error& e) const {
    // nlohmann: "[json.exception.parse_error.101] parse error at line 1, column 5: syntax
    // error while parsing value - <detail>"; keep <detail>, we give the position ourselves.
    std::string detail = e.what();
    std::size_t dash = detail.find(" - ");
    if (dash != std::string::npos) detail = detail.substr(dash + 3);
    std::size_t semicolon = detail.find("; expected");  // keep ';' for separating the fix
    if (semicolon != std::string::npos) detail[semicolon] = ',';
    // "; last read: '...'" helps only when it is plain text (not binary or broken UTF-8).
    std::size_t last_read = detail.find("; last read: ");
    if (last_read != std::string::npos) {
        bool plain = std::all_of(detail.begin() + long(last_read), detail.end(),
                                 [](char c) { return c >= 0x20 && c < 0x7f; });
        if (plain)
            detail[last_read] = ',';
        else
            detail.erase(last_read);
    }
    if (detail.size() > 160) detail = detail.substr(0, 157) + "...";
    std::size_t at = e.byte > 0 ? e.byte - 1 : 0;
    std::string fix = "check the JSON syntax here (keys need double quotes, items need commas)";
    if (detail.find("UTF-8") != std::string::npos) {
        fix = "save the file as UTF-8 text";
    } else if (at >= text_.size()) {
        fix = "the file ends too early: check for a missing closing bracket, brace or quote";
    } else if (text_[at] == ']' || text_[at] == '}') {
        std::size_t before = text_.find_last_not_of(" \t\r\n", at == 0 ? 0 : at - 1);
        if (at > 0 && before != std::string::npos && text_[before] == ',')
            fix = "remove the trailing comma before it";
    }
    return "invalid JSON: " + detail + "; " + fix;
}

}  // namespace rt::scene_internal
