#include "grading/gradescope_results.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>

#include "util.h"

namespace rt::grader {
namespace {

using json = nlohmann::json;

json test_json(const GradescopeTest& t) {
    json entry = {{"name", t.name}};
    if (!t.number.empty()) entry["number"] = t.number;
    entry["score"] = t.score;
    entry["max_score"] = t.max_score;
    entry["status"] = t.passed ? "passed" : "failed";
    entry["output"] = clean_output(t.output);
    entry["output_format"] = "text";
    entry["tags"] = t.tags;
    if (!t.visibility.empty()) entry["visibility"] = t.visibility;
    return entry;
}

double number(const json& j, const char* key) {
    const auto it = j.find(key);
    if (it == j.end()) return 0;
    if (it->is_number()) return it->get<double>();
    if (it->is_string()) return std::atof(it->get<std::string>().c_str());
    return 0;
}

std::string text(const json& j, const char* key) {
    const auto it = j.find(key);
    return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

std::vector<std::string> strings(const json& j, const char* key) {
    std::vector<std::string> out;
    const auto it = j.find(key);
    if (it == j.end() || !it->is_array()) return out;
    for (const json& item : *it)
        if (item.is_string()) out.push_back(item.get<std::string>());
    return out;
}

bool read_test(const json& j, GradescopeTest& t, std::string& why) {
    if (!j.is_object() || !j.contains("name") || !j["name"].is_string()) {
        why = "a test without a name";
        return false;
    }
    t.name = j["name"].get<std::string>();
    t.number = text(j, "number");
    t.passed = text(j, "status") == "passed";
    t.score = number(j, "score");
    t.max_score = number(j, "max_score");
    t.output = text(j, "output");
    t.tags = strings(j, "tags");
    t.visibility = text(j, "visibility");
    return true;
}

void read_leaderboard(const json& j, std::vector<LeaderboardEntry>& leaderboard) {
    const auto it = j.find("leaderboard");
    if (it == j.end() || !it->is_array()) return;
    for (const json& e : *it)
        if (e.is_object())
            leaderboard.push_back({text(e, "name"), number(e, "value"), text(e, "order") == "asc"});
}

}  // namespace

std::string results_json_text(const GradescopeResults& r) {
    json tests = json::array();
    for (const GradescopeTest& t : r.tests) tests.push_back(test_json(t));
    json results = {
        {"score", r.score},
        {"execution_time", int(std::ceil(r.execution_time))},
        {"output", clean_output(r.output)},
        {"output_format", "text"},
        {"stdout_visibility", "hidden"},  // build logs and hidden test names stay private
        {"visibility", "visible"},
    };
    if (!r.next_graded_at.empty())
        results["extra_data"] = {{"rate_limited", true}, {"next_graded_at", r.next_graded_at}};
    results["tests"] = tests;
    for (const LeaderboardEntry& e : r.leaderboard) {
        json entry = {{"name", e.name}, {"value", e.value}};
        if (e.ascending) entry["order"] = "asc";
        results["leaderboard"].push_back(entry);
    }
    return results.dump(2) + "\n";
}

std::optional<GradescopeResults> read_results_json(const std::string& body, std::string& why) {
    const json j = json::parse(body, nullptr, false);
    if (j.is_discarded()) {
        why = "not valid JSON";
        return std::nullopt;
    }
    return read_results_json(j, why);
}

std::optional<GradescopeResults> read_results_json(const json& j, std::string& why) {
    if (!j.is_object()) {
        why = "not valid JSON";
        return std::nullopt;
    }
    if (!j.contains("tests") || !j["tests"].is_array()) {
        why = "no \"tests\" list (not a Gradescope results.json)";
        return std::nullopt;
    }
    GradescopeResults r;
    r.score = number(j, "score");
    r.execution_time = number(j, "execution_time");
    r.output = text(j, "output");
    for (const json& entry : j["tests"]) {
        GradescopeTest t;
        if (!read_test(entry, t, why)) return std::nullopt;
        r.tests.push_back(std::move(t));
    }
    read_leaderboard(j, r.leaderboard);
    if (j.contains("extra_data") && j["extra_data"].is_object())
        r.next_graded_at = text(j["extra_data"], "next_graded_at");
    return r;
}

}  // namespace rt::grader
