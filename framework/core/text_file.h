// Reading a whole text file with a size cap, for the scene and OBJ/MTL readers.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

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

}  // namespace rt
