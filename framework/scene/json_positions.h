// Where each value of a JSON text is, so scene-file errors can say "file:line:col".
//
// Why this exists: nlohmann::json 3.11 (Debian 12) parses text into values but forgets where
// they came from (source positions only arrived in 3.12). So the scene loader first lets nlohmann
// parse and validate the text, then runs this small scanner over the same, known-valid text to
// map every JSON pointer (e.g. "/surfaces/3/radius") to the byte offset of the value and of its
// key. Offsets become 1-based line:column only when an error is reported.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace rt {

struct TextPosition {
    int line = 1;    // 1-based
    int column = 1;  // 1-based, counted in characters (UTF-8 code points), a tab counts as one
};

// The line and column of byte `offset` in `text` (offsets past the end give the end position).
TextPosition position_of_offset(const std::string& text, std::size_t offset);

class JsonPositions {
  public:
    static constexpr std::size_t npos = std::string::npos;

    // Scans `text`, which must already have been accepted by a JSON parser. Never throws on
    // odd input; positions it cannot work out are simply missing.
    explicit JsonPositions(const std::string& text);

    // Byte offset of the first character of the value at `pointer`, or npos if unknown.
    std::size_t value_offset(const std::string& pointer) const;
    // Byte offset of the opening quote of the key that names the value at `pointer`, or npos
    // (array elements and the root have no key).
    std::size_t key_offset(const std::string& pointer) const;

    // The pointer of the value starting at byte `offset`, or "" (the root) if none does.
    std::string pointer_at(std::size_t offset) const;

    // Pointers of keys that appeared a second time in the same object (nlohmann silently keeps
    // the last one, which hides mistakes), in text order. The offsets stored are of the repeat.
    const std::vector<std::string>& duplicate_keys() const { return duplicates_; }

    // The JSON pointer of `parent` extended by an object key (escaping '~' and '/').
    static std::string child(const std::string& parent, const std::string& key);
    static std::string child(const std::string& parent, std::size_t index);

  private:
    struct Where {
        std::size_t value = npos;
        std::size_t key = npos;
    };
    std::map<std::string, Where> where_;
    std::vector<std::string> duplicates_;
};

}  // namespace rt
