// How scene messages show words and choices: quoted values, lists of options, "did you mean".
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rt::scene_internal {

// A string shown in a message: JSON-quoted (so odd characters are visible) and kept short.
std::string quote(const std::string& s);

// "a", "a" or "b", "a", "b" or "c".
std::string list_of(const std::vector<std::string>& options);

// The option closest to `word`, if it is close enough to be a plausible typo.
std::optional<std::string> closest(const std::string& word,
                                   const std::vector<std::string>& options);

// "did you mean "x"?" or "use one of ...".
std::string suggestion(const std::string& word, const std::vector<std::string>& options);

}  // namespace rt::scene_internal
