#include "util.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <stdexcept>

namespace fs = std::filesystem;

namespace rt::grader {

std::string_view trim(std::string_view s) {
    const auto blank = [](char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
    };
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

std::string shell_quote(const std::string& word) {
    std::string out = "'";
    for (char c : word) {
        if (c == '\'')
            out += "'\\''";
        else
            out += c;
    }
    return out + "'";
}

// Runs argv without a shell; output and error in `output`.
int run_argv(const std::vector<std::string>& argv, const fs::path& cwd, std::string& output) {
    int p[2];
    if (pipe2(p, O_CLOEXEC) != 0) return -1;
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(p[1], 1);
        dup2(p[1], 2);
        if (chdir(cwd.c_str()) != 0) _exit(126);
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execv(args[0], args.data());
        _exit(127);
    }
    close(p[1]);
    char buffer[4096];
    ssize_t n;
    while ((n = read(p[0], buffer, sizeof buffer)) > 0) output.append(buffer, std::size_t(n));
    close(p[0]);
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) != pid) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int run_trusted(const std::string& command, std::string* output) {
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return -1;
    char buffer[4096];
    std::size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0)
        if (output) output->append(buffer, n);
    const int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::optional<std::string> command_output(const std::string& command) {
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return std::nullopt;
    std::string output;
    char buffer[65536];
    std::size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, n);
    if (pclose(pipe) != 0) return std::nullopt;
    return output;
}

std::string two_digits(int n) {
    char text[8];
    std::snprintf(text, sizeof text, "%02d", n);
    return text;
}

std::uint64_t fnv1a(std::string_view data, std::uint64_t hash) {
    for (unsigned char c : data) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    return hash;
}

std::string hex(std::uint64_t value) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}

bool glob_match(std::string_view pattern, std::string_view text) {
    std::size_t p = 0, t = 0, star = std::string_view::npos, mark = 0;
    while (t < text.size()) {
        if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
            ++p;
            ++t;
        } else if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            mark = t;
        } else if (star != std::string_view::npos) {
            p = star + 1;
            t = ++mark;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

std::string clean_output(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = text[i];
        if (c == 0x1b) {  // ESC [ ... letter
            while (i + 1 < text.size() && !std::isalpha((unsigned char)text[i + 1])) ++i;
            ++i;
            continue;
        }
        if (c == '\n' || c == '\t' || (c >= 0x20 && c != 0x7f)) out += char(c);
    }
    // Invalid UTF-8 would make the JSON writer throw: keep ASCII only beyond this point.
    std::string ascii;
    for (unsigned char c : out) ascii += c < 0x80 ? char(c) : '?';
    return ascii;
}

std::optional<std::int64_t> parse_iso8601(const std::string& text) {
    int y = 0, mo = 0, d = 0, h = 0, mi = 0, s = 0, used = 0;
    // The metadata JSON writes "2018-07-01T14:22:32.365935-07:00", an export's YAML
    // "2018-07-01 14:22:32.365935000 -0700".
    if (text.size() < 19 || (text[10] != 'T' && text[10] != ' ') ||
        std::sscanf(text.c_str(), "%4d-%2d-%2d%*c%2d:%2d:%2d%n", &y, &mo, &d, &h, &mi, &s, &used) !=
            6 ||
        used != 19)
        return std::nullopt;
    std::size_t i = 19;
    if (i < text.size() && text[i] == '.') {  // fractions of a second: ignored
        ++i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    }
    if (i < text.size() && text[i] == ' ') ++i;
    int offset = 0;  // seconds east of UTC
    const bool colon = i + 6 == text.size() && text[i + 3] == ':';
    if (i < text.size() && text[i] == 'Z') {
        ++i;
    } else if ((colon || i + 5 == text.size()) && (text[i] == '+' || text[i] == '-')) {
        int oh = 0, om = 0;
        if (std::sscanf(text.c_str() + i + 1, colon ? "%2d:%2d" : "%2d%2d", &oh, &om) != 2)
            return std::nullopt;
        offset = (text[i] == '-' ? -1 : 1) * (oh * 3600 + om * 60);
        i += colon ? 6 : 5;
    }
    const std::chrono::year_month_day date{std::chrono::year(y), std::chrono::month(unsigned(mo)),
                                           std::chrono::day(unsigned(d))};
    if (i != text.size() || !date.ok() || h > 23 || mi > 59 || s > 60) return std::nullopt;
    const std::int64_t days = std::chrono::sys_days(date).time_since_epoch().count();
    return days * 86400 + h * 3600 + mi * 60 + s - offset;
}

std::string csv_cell(std::string_view text) {
    std::string cell = "\"";
    const bool formula =
        !text.empty() && std::string_view("=+-@\t\r").find(text[0]) != std::string_view::npos;
    if (formula) cell += '\'';
    for (const char c : text) cell += c == '"' ? std::string("\"\"") : std::string(1, c);
    return cell + "\"";
}

}  // namespace rt::grader
