// Random edits of a file's text, for fuzzing the scene and OBJ readers.
#pragma once

#include <random>
#include <string>

namespace rt::testing {

// A random edit of `text` for fuzzing a parser: 1 to 4 single edits, each replacing, inserting
// (a character of `alphabet`) or erasing (1 to 8 characters). Deterministic for a seeded engine.
inline std::string mutate(const std::string& text, const std::string& alphabet,
                          std::mt19937& random) {
    std::string mutant = text;
    const int edits = 1 + int(random() % 4);
    for (int e = 0; e < edits && !mutant.empty(); ++e) {
        const std::size_t at = random() % mutant.size();
        const char c = alphabet[random() % alphabet.size()];
        switch (random() % 3) {
            case 0:
                mutant[at] = c;
                break;
            case 1:
                mutant.insert(mutant.begin() + long(at), c);
                break;
            default:
                mutant.erase(at, 1 + random() % 8);
                break;
        }
    }
    return mutant;
}

}  // namespace rt::testing
