// Command-line parsing shared by the course's programs (rt, rt-bench): CLI11 with usage errors
// reported the way compilers report errors, on one line, with exit code 2.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <optional>

namespace rt {

// Parses argv into `app`. Returns the exit code when the program should stop now (help was
// printed: 0; a usage error was reported: 2), nothing when it should go on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv,
                                             const char* program, const char* help_hint) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line instead of CLI11's two.
        std::fprintf(stderr, "%s: error: %s; run %s\n", program, e.what(), help_hint);
        return 2;
    }
    return std::nullopt;
}

}  // namespace rt
