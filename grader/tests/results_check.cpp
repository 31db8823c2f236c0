// Validates a results.json against Gradescope's documented schema
// (https://gradescope-autograders.readthedocs.io/en/latest/specs/#output-format) and checks
// expectations of the grader tests:
//   results_check FILE [--score-min X] [--score-max X] [--max-score X] [--contains TEXT]...
//                      [--not-contains TEXT]... [--test-failed NAME]... [--test-passed NAME]...
//                      [--full-marks] [--has-tag TAG]... [--full-marks-tag TAG]...
//                      [--has-leaderboard] [--no-leaderboard] [--leaderboard-first NAME]
// Exits 0 when everything holds; prints each violation otherwise.
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using json = nlohmann::json;

namespace {

std::vector<std::string> problems;
void fail(const std::string& what) {
    problems.push_back(what);
}

const std::set<std::string> kVisibility = {"hidden", "after_due_date", "after_published",
                                           "visible"};
const std::set<std::string> kFormats = {"text", "html", "simple_format", "md", "ansi"};
const std::set<std::string> kTopLevel = {"score",         "execution_time",     "output",
                                         "output_format", "test_output_format", "test_name_format",
                                         "visibility",    "stdout_visibility",  "extra_data",
                                         "tests",         "leaderboard"};
const std::set<std::string> kTestKeys = {"score",       "max_score",  "status",    "name",
                                         "name_format", "number",     "output",    "output_format",
                                         "tags",        "visibility", "extra_data"};

// "leaderboard": [{"name": "Time", "value": 15, "order": "asc"}, ...]; order defaults to desc.
void check_leaderboard(const json& board) {
    if (!board.is_array()) return fail("leaderboard is not an array");
    for (const auto& e : board) {
        if (!e.is_object()) {
            fail("a leaderboard entry is not an object");
            continue;
        }
        for (const auto& [key, value] : e.items())
            if (key != "name" && key != "value" && key != "order")
                fail("leaderboard entry: unknown key " + key);
        if (!e.contains("name") || !e["name"].is_string()) fail("leaderboard entry without a name");
        if (!e.contains("value") || !(e["value"].is_number() || e["value"].is_string()))
            fail("leaderboard entry: value is not a number or a string");
        if (e.contains("order") && e["order"] != "asc" && e["order"] != "desc")
            fail("leaderboard entry: order is not asc or desc");
    }
}

void check_schema(const json& r) {
    if (!r.is_object()) return fail("top level is not an object");
    for (const auto& [key, value] : r.items())
        if (!kTopLevel.count(key)) fail("unknown top-level key " + key);
    // Fields this grader always writes, with their documented types.
    for (const char* key : {"score", "execution_time", "output", "output_format",
                            "stdout_visibility", "visibility", "tests"})
        if (!r.contains(key)) fail(std::string("missing top-level ") + key);
    if (r.contains("score") && !r["score"].is_number()) fail("score is not a number");
    if (r.contains("execution_time") && !r["execution_time"].is_number_integer())
        fail("execution_time is not an integer (seconds)");
    if (r.contains("execution_time") && r["execution_time"].is_number() && r["execution_time"] < 0)
        fail("execution_time is negative");
    if (r.contains("output") && !r["output"].is_string()) fail("output is not a string");
    for (const char* key : {"output_format", "test_output_format"})
        if (r.contains(key) && (!r[key].is_string() || !kFormats.count(r[key])))
            fail(std::string(key) + " is not one of text, html, simple_format, md, ansi");
    for (const char* key : {"visibility", "stdout_visibility"})
        if (r.contains(key) && (!r[key].is_string() || !kVisibility.count(r[key])))
            fail(std::string(key) + " is not a documented visibility");
    if (r.contains("leaderboard")) check_leaderboard(r["leaderboard"]);
    if (!r.contains("tests") || !r["tests"].is_array()) return fail("tests is not an array");
    double total = 0;
    std::set<std::string> names;
    for (const auto& t : r["tests"]) {
        const std::string name = t.value("name", std::string("?"));
        auto bad = [&](const std::string& what) { fail("test \"" + name + "\": " + what); };
        if (!t.is_object()) {
            bad("not an object");
            continue;
        }
        for (const auto& [key, value] : t.items())
            if (!kTestKeys.count(key)) bad("unknown key " + key);
        for (const char* key : {"name", "number", "score", "max_score", "status", "output",
                                "output_format", "tags", "visibility"})
            if (!t.contains(key)) bad(std::string("missing ") + key);
        if (t.contains("name") && (!t["name"].is_string() || t["name"].get<std::string>().empty()))
            bad("name is not a non-empty string");
        if (!names.insert(name).second) bad("duplicate name");
        if (t.contains("number") && !t["number"].is_string()) bad("number is not a string");
        if (!t["score"].is_number() || !t["max_score"].is_number()) {
            bad("score or max_score is not a number");
            continue;
        }
        const double score = t["score"], max = t["max_score"];
        if (max < 0 || score < 0 || score > max + 1e-9) bad("score outside [0, max_score]");
        total += score;
        const std::string status = t.value("status", "");
        if (status != "passed" && status != "failed") bad("status is not passed or failed");
        if (status == "passed" && std::abs(score - max) > 1e-9) bad("passed without full score");
        if (t.contains("output") && !t["output"].is_string()) bad("output is not a string");
        if (t.contains("output_format") && !kFormats.count(t.value("output_format", "")))
            bad("output_format is not documented");
        if (t.contains("tags")) {
            if (!t["tags"].is_array())
                bad("tags is not an array");
            else
                for (const auto& tag : t["tags"])
                    if (!tag.is_string()) bad("a tag is not a string");
        }
        if (t.contains("visibility") && !kVisibility.count(t.value("visibility", "")))
            bad("visibility is not documented");
    }
    if (r.contains("score") && r["score"].is_number() &&
        std::abs(r["score"].get<double>() - total) > 0.011)
        fail("score is not the sum of the test scores");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: results_check FILE [checks...]\n";
        return 2;
    }
    json r;
    try {
        std::ifstream in(argv[1]);
        if (!in) {
            std::cerr << argv[1] << ": missing\n";
            return 1;
        }
        r = json::parse(in);
    } catch (const std::exception& e) {
        std::cerr << argv[1] << ": not JSON: " << e.what() << "\n";
        return 1;
    }
    check_schema(r);
    std::string everything = r.value("output", "");
    double max_total = 0;
    for (const auto& t : r.value("tests", json::array())) {
        everything += "\n" + t.value("name", "") + "\n" + t.value("output", "");
        if (t.contains("max_score") && t["max_score"].is_number())
            max_total += t["max_score"].get<double>();
    }
    const double score = r.value("score", -1.0);
    for (int i = 2; i < argc; ++i) {
        const std::string flag = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) {
                fail(flag + " needs a value");
                return "";
            }
            return argv[++i];
        };
        if (flag == "--score-min") {
            const double v = std::stod(next());
            if (score < v - 1e-9)
                fail("score " + std::to_string(score) + " < " + std::to_string(v));
        } else if (flag == "--score-max") {
            const double v = std::stod(next());
            if (score > v + 1e-9)
                fail("score " + std::to_string(score) + " > " + std::to_string(v));
        } else if (flag == "--max-score") {
            const double v = std::stod(next());
            if (std::abs(max_total - v) > 1e-9)
                fail("max score " + std::to_string(max_total) + " != " + std::to_string(v));
        } else if (flag == "--full-marks") {
            if (max_total <= 0 || std::abs(score - max_total) > 1e-9) {
                fail("score " + std::to_string(score) + " is not full marks " +
                     std::to_string(max_total));
                // Which tests lost points, and why: the JSON itself may be too long to print.
                for (const auto& t : r.value("tests", json::array()))
                    if (std::abs(t.value("score", 0.0) - t.value("max_score", 0.0)) > 1e-9)
                        fail("  " + t.value("name", std::string("?")) + ": " +
                             std::to_string(t.value("score", 0.0)) + " of " +
                             std::to_string(t.value("max_score", 0.0)) + ": " +
                             t.value("output", std::string()).substr(0, 600));
            }
        } else if (flag == "--full-marks-tag") {
            // Every test tagged TAG has full points (and there is at least one).
            const std::string tag = next();
            int seen = 0;
            for (const auto& t : r.value("tests", json::array())) {
                bool tagged = false;
                for (const auto& g : t.value("tags", json::array()))
                    tagged = tagged || (g.is_string() && g.get<std::string>() == tag);
                if (!tagged) continue;
                ++seen;
                if (t.value("score", -1.0) != t.value("max_score", -2.0))
                    fail(t.value("name", "") + " (" + tag + ") has no full points");
            }
            if (!seen) fail("no test has the tag " + tag);
        } else if (flag == "--has-leaderboard" || flag == "--no-leaderboard") {
            const bool has = r.contains("leaderboard") && !r["leaderboard"].empty();
            if (has != (flag == "--has-leaderboard"))
                fail(has ? "a leaderboard is written" : "no leaderboard is written");
        } else if (flag == "--leaderboard-first") {
            const std::string name = next();
            const json board = r.value("leaderboard", json::array());
            if (board.empty() || !board[0].is_object() || board[0].value("name", "") != name ||
                !board[0].contains("value") || !board[0]["value"].is_number())
                fail("the leaderboard's first column is not a number named " + name);
        } else if (flag == "--has-tag") {
            const std::string tag = next();
            bool seen = false;
            for (const auto& t : r.value("tests", json::array()))
                for (const auto& g : t.value("tags", json::array()))
                    seen = seen || (g.is_string() && g.get<std::string>() == tag);
            if (!seen) fail("no test has the tag " + tag);
        } else if (flag == "--contains") {
            const std::string text = next();
            if (everything.find(text) == std::string::npos)
                fail("no output contains \"" + text + "\"");
        } else if (flag == "--not-contains") {
            const std::string text = next();
            if (everything.find(text) != std::string::npos)
                fail("some output contains \"" + text + "\"");
        } else if (flag == "--test-failed" || flag == "--test-passed") {
            // Every test whose name contains TEXT has that status (and at least one exists).
            const std::string text = next(), want = flag == "--test-failed" ? "failed" : "passed";
            int seen = 0;
            for (const auto& t : r.value("tests", json::array()))
                if (t.value("name", "").find(text) != std::string::npos) {
                    ++seen;
                    if (t.value("status", "") != want)
                        fail(t.value("name", "") + " is not " + want);
                }
            if (!seen) fail("no test named like \"" + text + "\"");
        } else {
            fail("unknown check " + flag);
        }
    }
    for (const auto& p : problems) std::cerr << argv[1] << ": " << p << "\n";
    if (problems.empty())
        std::cout << argv[1] << ": valid, score " << score << " / " << max_total << "\n";
    return problems.empty() ? 0 : 1;
}
