#include "cmd/gradescope_export.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "util.h"  // parse_iso8601: Gradescope's times

namespace rt::grader {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMetadata = "submission_metadata.yml";

[[noreturn]] void malformed(const fs::path& file, const std::string& where,
                            const std::string& what) {
    throw std::runtime_error(file.string() + ": " + where + ": " + what +
                             " (is this the submission_metadata.yml of Gradescope's "
                             "\"Export Submissions\"?)");
}

// "; "-joined values of `key` over the submitters.
std::string joined(const YAML::Node& submitters, const char* key) {
    std::string out;
    for (const YAML::Node& s : submitters)
        if (s[key] && s[key].IsScalar())
            out += (out.empty() ? "" : "; ") + s[key].as<std::string>();
    return out;
}

ExportedSubmission read_one(const fs::path& file, const fs::path& root, const std::string& folder,
                            const YAML::Node& record) {
    ExportedSubmission s;
    s.folder = folder;
    s.path = root / folder;
    if (!record.IsMap()) malformed(file, folder, "not a mapping");
    const YAML::Node submitters = record[":submitters"];
    if (!submitters || !submitters.IsSequence() || submitters.size() == 0)
        malformed(file, folder, "no :submitters list");
    s.names = joined(submitters, ":name");
    s.sids = joined(submitters, ":sid");
    s.emails = joined(submitters, ":email");
    s.student = !s.sids.empty() ? s.sids : !s.emails.empty() ? s.emails : s.names;
    const YAML::Node created = record[":created_at"];
    const auto time =
        created && created.IsScalar() ? parse_iso8601(created.as<std::string>()) : std::nullopt;
    if (!time) malformed(file, folder, ":created_at is not a time");
    s.time = *time;
    const YAML::Node score = record[":score"];
    if (score && score.IsScalar() && !score.as<std::string>().empty() && !score.IsNull()) {
        try {
            s.old_score = score.as<double>();
        } catch (const YAML::Exception&) {
            malformed(file, folder, ":score is not a number");
        }
    }
    return s;
}

}  // namespace

std::optional<fs::path> export_root(const fs::path& dir) {
    if (fs::exists(dir / kMetadata)) return dir;
    std::optional<fs::path> inner;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        if (!e.is_directory()) continue;
        if (inner) return std::nullopt;  // more than one folder: not a wrapped export
        inner = e.path();
    }
    if (inner && fs::exists(*inner / kMetadata)) return inner;
    return std::nullopt;
}

std::vector<ExportedSubmission> read_gradescope_export(const fs::path& root) {
    const fs::path file = root / kMetadata;
    YAML::Node metadata;
    try {
        metadata = YAML::LoadFile(file.string());
    } catch (const YAML::Exception& e) {
        malformed(file, "line " + std::to_string(e.mark.line + 1), e.msg);
    }
    if (!metadata.IsMap()) malformed(file, "top level", "not a mapping of submission folders");
    std::vector<ExportedSubmission> all;
    for (const auto& entry : metadata) {
        const std::string folder = entry.first.as<std::string>();
        // A folder name from the file must stay inside the export.
        if (folder.empty() || folder.find('/') != std::string::npos || folder == "." ||
            folder == "..")
            malformed(file, folder, "not a folder name");
        ExportedSubmission s = read_one(file, root, folder, entry.second);
        if (fs::is_directory(s.path)) all.push_back(std::move(s));
    }
    std::stable_sort(all.begin(), all.end(),
                     [](const auto& a, const auto& b) { return a.time < b.time; });
    return all;
}

std::vector<ExportedSubmission> latest_per_student(const std::vector<ExportedSubmission>& all) {
    std::map<std::string, std::size_t> newest;  // student -> index into all
    for (std::size_t i = 0; i < all.size(); ++i) {
        const auto [it, fresh] = newest.emplace(all[i].student, i);
        if (!fresh && all[i].time >= all[it->second].time) it->second = i;
    }
    std::vector<ExportedSubmission> out;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (newest.at(all[i].student) == i) out.push_back(all[i]);
    return out;
}

}  // namespace rt::grader
