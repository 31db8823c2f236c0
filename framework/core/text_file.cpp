// Whole text files, read and written, and HTML escaping (core/text_file.h).
#include "core/text_file.h"

#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <sstream>
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

bool read_text_if(const fs::path& file, std::string& text) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return false;
    std::ostringstream s;
    s << in.rdbuf();
    text = std::move(s).str();
    return !in.bad();
}

std::string read_text(const fs::path& file) {
    std::string text;
    if (!read_text_if(file, text)) throw std::runtime_error("cannot read " + file.string());
    return text;
}

void write_text(const fs::path& file, std::string_view text) {
    if (file.has_parent_path()) fs::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(text.data(), std::streamsize(text.size()));
    out.close();
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

void write_text_atomically(const fs::path& file, std::string_view text, const AtomicWrite& how) {
    const fs::path target = how.follow_link && fs::is_symlink(file) ? fs::canonical(file) : file;
    fs::path temporary = target;
    temporary += ".tmp" + std::to_string(getpid());
    std::error_code ignored;
    fs::remove_all(temporary, ignored);
    try {
        write_text(temporary, text);
    } catch (const std::exception& e) {
        fs::remove(temporary, ignored);
        throw AtomicWriteError(e.what(), false, "");
    }
    if (how.keep_permissions) fs::permissions(temporary, fs::status(target).permissions(), ignored);
    if (fs::is_directory(fs::symlink_status(target))) fs::remove_all(target);  // a planted one
    std::error_code ec;
    fs::rename(temporary, target, ec);
    if (ec) {
        fs::remove(temporary, ignored);
        throw AtomicWriteError("cannot replace " + target.string() + " (" + ec.message() + ")",
                               true, ec.message());
    }
}

std::string html_escape(std::string_view text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string html_page_start(const std::string& title, const std::string& css) {
    return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
           html_escape(title) + "</title><style>" + css + "</style></head><body>\n";
}

}  // namespace rt
