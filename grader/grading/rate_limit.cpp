#include "grading/rate_limit.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "grading/gradescope_results.h"
#include "util.h"  // parse_iso8601

namespace rt::grader {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

// One earlier submission that was graded, inside the window.
struct Graded {
    std::int64_t time = 0;
    double score = 0;
    const json* results = nullptr;  // its results.json, when the metadata has it
};

[[noreturn]] void unreadable(const fs::path& file, const std::string& what) {
    throw std::runtime_error(file.string() + ": " + what +
                             " (Gradescope writes this file before run_autograder; without it, "
                             "grade with no --max-per-day)");
}

json read_metadata(const fs::path& file) {
    std::ifstream in(file);
    if (!in) unreadable(file, "cannot read the submission metadata");
    try {
        return json::parse(in);
    } catch (const json::exception& e) {
        unreadable(file, std::string("not JSON: ") + e.what());
    }
}

std::int64_t time_field(const json& object, const char* key, const fs::path& file,
                        const std::string& where) {
    const auto it = object.find(key);
    const std::optional<std::int64_t> t = it != object.end() && it->is_string()
                                              ? parse_iso8601(it->get<std::string>())
                                              : std::nullopt;
    if (!t) unreadable(file, where + "\"" + key + "\" is not an ISO 8601 time");
    return *t;
}

double score_field(const json& submission) {
    const auto it = submission.find("score");
    if (it == submission.end()) return 0;
    if (it->is_number()) return it->get<double>();
    if (it->is_string()) return std::atof(it->get<std::string>().c_str());  // "20.0"
    return 0;
}

bool was_refused(const json* results) {
    if (!results || !results->is_object()) return false;
    const auto extra = results->find("extra_data");
    return extra != results->end() && extra->is_object() && extra->value("rate_limited", false);
}

// The earlier graded submissions in (now - window, now), oldest first.
std::vector<Graded> graded_in_window(const json& metadata, std::int64_t now, const RateLimit& limit,
                                     const fs::path& file) {
    std::vector<Graded> graded;
    const auto previous = metadata.find("previous_submissions");
    if (previous == metadata.end() || !previous->is_array()) return graded;
    for (std::size_t i = 0; i < previous->size(); ++i) {
        const json& p = (*previous)[i];
        const std::string where = "previous_submissions[" + std::to_string(i) + "].";
        const std::int64_t t = time_field(p, "submission_time", file, where);
        if (t >= now || t <= now - limit.window.count()) continue;  // later, or out of the window
        const json* results = p.contains("results") ? &p["results"] : nullptr;
        if (was_refused(results)) continue;
        graded.push_back({t, score_field(p), results});
    }
    std::stable_sort(graded.begin(), graded.end(),
                     [](const Graded& a, const Graded& b) { return a.time < b.time; });
    return graded;
}

std::string utc_text(std::int64_t t) {
    const std::time_t time = t;
    std::tm tm{};
    gmtime_r(&time, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &tm);
    return text;
}

std::string wait_text(std::int64_t seconds) {
    const std::int64_t minutes = (seconds + 59) / 60;
    return std::to_string(minutes / 60) + " h " + std::to_string(minutes % 60) + " min";
}

std::string refusal(const std::vector<Graded>& graded, std::int64_t now, std::int64_t next,
                    const RateLimit& limit) {
    const std::int64_t hours = limit.window.count() / 3600;
    return "This submission was not graded: the course allows " + std::to_string(limit.max_graded) +
           " graded submissions in any " + std::to_string(hours) + " hours, and you made " +
           std::to_string(graded.size()) + " (the earliest at " + utc_text(graded.front().time) +
           ").\nYour next graded submission is possible from " + utc_text(next) + " (" +
           wait_text(next - now) + " after this one).\nThe score and tests below are those of " +
           "your graded submission of " + utc_text(graded.back().time) + ".\n";
}

}  // namespace

std::optional<std::string> rate_limited_results(const fs::path& metadata_file,
                                                const RateLimit& limit) {
    if (limit.max_graded <= 0) return std::nullopt;
    const json metadata = read_metadata(metadata_file);
    if (!metadata.is_object()) unreadable(metadata_file, "not a JSON object");
    const std::int64_t now = time_field(metadata, "created_at", metadata_file, "");
    const std::vector<Graded> graded = graded_in_window(metadata, now, limit, metadata_file);
    if (graded.size() < std::size_t(limit.max_graded)) return std::nullopt;
    // The next graded submission is possible once the max_graded-th latest leaves the window.
    const std::int64_t next =
        graded[graded.size() - std::size_t(limit.max_graded)].time + limit.window.count();
    const Graded& latest = graded.back();
    GradescopeResults out;
    out.score = latest.score;
    out.output = refusal(graded, now, next, limit);
    std::string why;
    if (latest.results) {  // its tests and leaderboard, when Gradescope kept its results
        if (const auto earlier = read_results_json(*latest.results, why)) {
            out.tests = earlier->tests;
            out.leaderboard = earlier->leaderboard;
        } else {
            out.output +=
                "(Its tests cannot be shown: Gradescope's copy of its results is "
                "unreadable: " +
                why + ".)\n";
        }
    }
    out.next_graded_at = utc_text(next);
    return results_json_text(out);
}

}  // namespace rt::grader
