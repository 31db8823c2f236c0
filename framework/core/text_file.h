// Whole text files: read with a size cap (the scene and OBJ/MTL readers) or without one (the
// grader's own files), written whole or atomically; and escaping text for HTML pages.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rt {

// Why read_text_file could not return the text. Each caller words its own message.
struct FileProblem {
    enum Kind { Missing, Directory, CannotOpen, TooLarge, ReadError } kind;
    int open_errno = 0;  // errno right after the failed open (CannotOpen), saved before it changes
};

// The whole of `file`, read in binary mode. A file that does not exist, is a directory, cannot
// be opened, holds more than `max_bytes` or fails while being read is reported through
// `complain`, which must throw (the callers turn the problem into their own error type).
std::string read_text_file(const std::filesystem::path& file, std::uintmax_t max_bytes,
                           const std::function<void(const FileProblem&)>& complain);

// The whole of `file` in binary mode, however large: false when it cannot be opened or read
// (then `text` is unspecified).
bool read_text_if(const std::filesystem::path& file, std::string& text);
// The same, throwing std::runtime_error("cannot read FILE") when it cannot.
std::string read_text(const std::filesystem::path& file);

// Writes `text` to `file` (creating its folder), throwing std::runtime_error when it cannot.
void write_text(const std::filesystem::path& file, std::string_view text);

// How write_text_atomically treats what is at `file` already.
struct AtomicWrite {
    // true: a symbolic link at `file` keeps pointing at the rewritten file; false: the link itself
    // is replaced, never followed (a link planted by a sandboxed child leads nowhere).
    bool follow_link = false;
    bool keep_permissions = false;  // true: the new file gets the old one's permissions
};

// Why write_text_atomically failed: writing the temporary file, or renaming it over `file`.
struct AtomicWriteError : std::runtime_error {
    AtomicWriteError(const std::string& what, bool renaming, std::string reason)
        : std::runtime_error(what), renaming(renaming), reason(std::move(reason)) {}
    bool renaming;
    std::string reason;  // the system's words, when renaming
};

// Writes `text` to a temporary file beside `file` and renames it over `file`, so readers never
// see half a file. Creates `file`'s folder; a directory at `file` is removed first. On failure the
// temporary file is removed and AtomicWriteError thrown.
void write_text_atomically(const std::filesystem::path& file, std::string_view text,
                           const AtomicWrite& how = {});

// `text` with & < > " as HTML entities, for element text and quoted attribute values.
std::string html_escape(std::string_view text);

// The start and the end of a self-contained HTML page (the gallery, a grading's report, the class
// dashboard, the similarity report): UTF-8, English, `title` (escaped here) and the page's CSS
// inline; the body follows the start.
std::string html_page_start(const std::string& title, const std::string& css);
inline constexpr const char* kHtmlPageEnd = "</body></html>\n";

}  // namespace rt
