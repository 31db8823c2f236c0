// Reading a whole text file with a size cap (core/text_file.h).
#include "core/text_file.h"

#include <cerrno>
#include <fstream>
#include <stdexcept>

namespace rt {

namespace fs = std::filesystem;

std::string read_text_file(const fs::path& file, std::uintmax_t max_bytes,
                           const std::function<void(const FileProblem&)>& complain) {
    // `complain` is documented to throw; should it return anyway, stop rather than read on.
    auto report = [&](FileProblem problem) {
        complain(problem);
        throw std::logic_error("read_text_file: the problem handler returned");
    };
    std::error_code ec;
    fs::file_status status = fs::status(file, ec);
    if (!fs::exists(status)) report({FileProblem::Missing});
    if (fs::is_directory(status)) report({FileProblem::Directory});
    std::ifstream in(file, std::ios::binary);
    if (!in) report({FileProblem::CannotOpen, errno});
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
        if (text.size() > max_bytes) report({FileProblem::TooLarge});
    }
    if (in.bad()) report({FileProblem::ReadError});
    return text;
}

}  // namespace rt
