// A folder under the system temp dir for one test, removed when the test ends.
#pragma once

#include <filesystem>
#include <fstream>
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

class TempDir {
  public:
    explicit TempDir(const std::string& name)
        : path_(std::filesystem::temp_directory_path() /
                ("rt-scene-test-" + name + "-" + std::to_string(std::random_device{}()))) {
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    // Writes `text` (bytes as given) to `name` inside the folder and returns its path.
    std::filesystem::path write(const std::string& name, const std::string& text) const {
        std::filesystem::path file = path_ / name;
        std::filesystem::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

  private:
    std::filesystem::path path_;
};

}  // namespace rt::testing
