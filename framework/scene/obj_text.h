// Line-level reading of OBJ and MTL text, shared by the OBJ checks, the MTL reader and load_obj:
// ObjError messages, the capped file read, lines, words and numbers as tinyobjloader sees them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace rt::obj_internal {

// Throws ObjError: `mesh "<name>"`, the line where known, then `what; fix` (obj_loader.h).
[[noreturn]] void fail(const std::string& name, std::size_t line, const std::string& what,
                       const std::string& fix);

// A word of the file as messages show it: quoted and cut to 40 characters.
std::string shown(std::string_view s);

// Reads a whole OBJ or MTL file; `complain(what, fix)` reports (and throws) a problem with it.
// `what_it_should_be` completes "is a directory, not ...".
std::string read_mesh_file(
    const std::filesystem::path& file, std::uintmax_t max_bytes, const char* what_it_should_be,
    const std::function<void(const std::string& what, const std::string& fix)>& complain);

// The lines of an OBJ or MTL file the way tinyobjloader sees them: "\n", "\r\n" and "\r" all
// end a line, and leading blanks are ignored.
template <typename Visit>
void for_each_line(const std::string& text, Visit visit) {
    std::size_t line = 1, start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find_first_of("\r\n", start);
        if (end == std::string::npos) end = text.size();
        std::string_view content(text.data() + start, end - start);
        std::size_t first = content.find_first_not_of(" \t");
        visit(line, first == std::string_view::npos ? std::string_view() : content.substr(first));
        if (end == text.size()) break;
        start = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
        ++line;
    }
}

// The blank-separated words of `s`.
std::vector<std::string_view> words(std::string_view s);

// What follows a directive of `keyword_size` characters, without surrounding blanks: the whole
// name of "newmtl my glass" or "usemtl my glass" (names may hold spaces, as Blender writes them).
std::string_view directive_argument(std::string_view s, std::size_t keyword_size);

// True when `text` is UTF-16 or UTF-32 (a byte-order mark, or zero bytes among the first ones),
// which OBJ and MTL readers cannot read: the file would look empty.
bool is_wide_text(const std::string& text);

// `line` starts with `keyword` followed by a blank (as tinyobjloader tests it).
bool is_directive(std::string_view line, std::string_view keyword);

enum class Number { Ok, NotANumber, NotFinite };

// A decimal number as OBJ and MTL write it ("1", "-2.5e3", "+0.5").
Number parse_number(std::string_view word, double& value);

}  // namespace rt::obj_internal
