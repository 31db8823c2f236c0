#include "scene/json_positions.h"

#include <nlohmann/json.hpp>

namespace rt {

TextPosition position_of_offset(const std::string& text, std::size_t offset) {
    TextPosition at;
    std::size_t start = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;  // a BOM is invisible
    std::size_t end = offset < text.size() ? offset : text.size();
    for (std::size_t i = start; i < end; ++i) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        if (c == '\n') {
            ++at.line;
            at.column = 1;
        } else if ((c & 0xC0) != 0x80) {  // UTF-8 continuation bytes do not start a character
            ++at.column;
        }
    }
    return at;
}

std::string JsonPositions::child(const std::string& parent, const std::string& key) {
    std::string escaped;
    for (char c : key) {
        if (c == '~')
            escaped += "~0";
        else if (c == '/')
            escaped += "~1";
        else
            escaped += c;
    }
    return parent + "/" + escaped;
}

std::string JsonPositions::child(const std::string& parent, std::size_t index) {
    return parent + "/" + std::to_string(index);
}

namespace {

bool is_json_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// Skips a string literal starting at the opening quote; returns the offset after its end.
std::size_t skip_string(const std::string& text, std::size_t pos) {
    for (++pos; pos < text.size(); ++pos) {
        if (text[pos] == '\\')
            ++pos;
        else if (text[pos] == '"')
            return pos + 1;
    }
    return text.size();
}

}  // namespace

JsonPositions::JsonPositions(const std::string& text) {
    // One open container: its pointer, whether it is an object, and how far we are inside it.
    struct Frame {
        std::string pointer;
        bool object = false;
        bool expect_key = false;     // objects: the next string is a key, not a value
        std::size_t next_index = 0;  // arrays: index of the next element
    };
    std::vector<Frame> open;
    std::string pending_pointer;  // the pointer of the next value (the root at first)
    std::size_t pending_key = npos;

    std::size_t pos = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    while (pos < text.size()) {
        char c = text[pos];
        if (is_json_space(c) || c == ',' || c == ':') {
            ++pos;
            continue;
        }
        if (c == '}' || c == ']') {
            if (!open.empty()) open.pop_back();
            ++pos;
            continue;
        }
        if (!open.empty() && open.back().object && open.back().expect_key) {
            // A key: remember it; the value after the ':' gets the extended pointer.
            std::size_t end = skip_string(text, pos);
            std::string raw = text.substr(pos, end - pos);
            std::string key = raw.size() >= 2 ? raw.substr(1, raw.size() - 2) : std::string();
            if (key.find('\\') != std::string::npos) {  // escapes: let nlohmann decode them
                try {
                    key = nlohmann::json::parse(raw).get<std::string>();
                } catch (const nlohmann::json::exception&) {
                }
            }
            pending_pointer = child(open.back().pointer, key);
            pending_key = pos;
            open.back().expect_key = false;
            pos = end;
            continue;
        }
        if (!open.empty() && !open.back().object) {
            pending_pointer = child(open.back().pointer, open.back().next_index++);
            pending_key = npos;
        }
        // A value starts here.
        auto [it, inserted] = where_.insert_or_assign(pending_pointer, Where{pos, pending_key});
        if (!inserted && pending_key != npos) duplicates_.push_back(it->first);
        if (!open.empty() && open.back().object) open.back().expect_key = true;
        if (c == '{' || c == '[') {
            open.push_back(Frame{pending_pointer, c == '{', c == '{', 0});
            ++pos;
        } else if (c == '"') {
            pos = skip_string(text, pos);
        } else {  // number, true, false, null
            while (pos < text.size() && !is_json_space(text[pos]) && text[pos] != ',' &&
                   text[pos] != ']' && text[pos] != '}')
                ++pos;
        }
    }
}

std::size_t JsonPositions::value_offset(const std::string& pointer) const {
    auto it = where_.find(pointer);
    return it == where_.end() ? npos : it->second.value;
}

std::size_t JsonPositions::key_offset(const std::string& pointer) const {
    auto it = where_.find(pointer);
    return it == where_.end() ? npos : it->second.key;
}

std::string JsonPositions::pointer_at(std::size_t offset) const {
    for (const auto& [pointer, where] : where_)
        if (where.value == offset) return pointer;
    return "";
}

}  // namespace rt
