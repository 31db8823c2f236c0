// The pages of `rt-grade similarity`: index.html for people, pairs.csv for scripts.
#include "cmd/similarity_report.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "util.h"

namespace fs = std::filesystem;

namespace rt::grader {
namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:1.5em;background:#fafafa;color:#222}"
    "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:2px 8px}"
    "th{background:#eee}td.n{text-align:right}"
    "table.side{width:100%;table-layout:fixed}table.side td{vertical-align:top;padding:0}"
    "pre{margin:0;padding:4px;font-size:12px;overflow-x:auto;background:#fff}"
    "h2{margin-top:2em;border-top:2px solid #999;padding-top:.5em}h3{font-size:1em}"
    ".muted{color:#666}";

// Pairs whose regions the page shows: a cohort sharing one solution flags thousands, and the
// page must still open (pairs.csv lists them all).
constexpr std::size_t kShownPairs = 100;
// Rows of the ranked table: a class that shares one solution flags a number of pairs that grows
// with the square of the class (300 such submissions wrote a 6.8 MB page), so the page stops
// here and pairs.csv holds the rest.
constexpr std::size_t kRankedRows = 1000;

std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

// Lines first..last of `text` (1-based, inclusive), numbered and HTML-escaped.
std::string excerpt(const std::string& text, int first, int last) {
    const std::vector<std::string> lines = split_lines(text);
    std::string out;
    char number[16];
    for (int n = std::max(first, 1); n <= last && n <= int(lines.size()); ++n) {
        std::snprintf(number, sizeof number, "%5d  ", n);
        out += number + html_escape(lines[std::size_t(n - 1)]) + "\n";
    }
    return out;
}

std::string percent(int value) {
    return std::to_string(value) + "%";
}

int tokens_of(const CohortMember& m, const std::string& file) {
    const auto t = m.tokens.find(file);
    return t == m.tokens.end() ? 0 : t->second;
}

// The ranked table of the pairs at or above the threshold, each row linking to its regions.
std::string ranking(const SimilarityReport& r, std::size_t flagged) {
    if (flagged == 0) return "<p>No pair reaches " + std::to_string(int(r.threshold)) + "%.</p>\n";
    std::string html =
        "<table><tr><th>#</th><th>score</th><th>file</th><th>A</th><th>B</th>"
        "<th>A's code in B</th><th>B's code in A</th><th>regions</th></tr>\n";
    const std::size_t rows = std::min(flagged, kRankedRows);
    for (std::size_t i = 0; i < rows; ++i) {
        const SimilarityPair& p = r.pairs[i];
        const std::string n = std::to_string(i + 1);
        html += "<tr><td class=\"n\"><a href=\"#pair-" + n + "\">" + n +
                "</a></td><td class=\"n\">" + percent(p.score()) + "</td><td>" +
                html_escape(p.file) + "</td><td>" + html_escape(r.cohort[p.a].name) + "</td><td>" +
                html_escape(r.cohort[p.b].name) + "</td><td class=\"n\">" + percent(p.a_in_b) +
                "</td><td class=\"n\">" + percent(p.b_in_a) + "</td><td class=\"n\">" +
                std::to_string(p.runs.size()) + "</td></tr>\n";
    }
    html += "</table>\n";
    if (flagged > rows)
        html += "<p>" + std::to_string(flagged - rows) +
                " more pairs reach the threshold; pairs.csv lists every pair.</p>\n";
    return html;
}

// One pair: each matching region as the lines of both files, side by side.
std::string pair_section(const SimilarityReport& r, const SimilarityPair& p, std::size_t rank) {
    const CohortMember& a = r.cohort[p.a];
    const CohortMember& b = r.cohort[p.b];
    const std::string& a_text = a.files.at(p.file);
    const std::string& b_text = b.files.at(p.file);
    std::string html = "<h2 id=\"pair-" + std::to_string(rank) + "\">" + std::to_string(rank) +
                       ". " + percent(p.score()) + " &mdash; " + html_escape(p.file) + ": " +
                       html_escape(a.name) + " and " + html_escape(b.name) + "</h2>\n";
    html += "<p>" + percent(p.a_in_b) + " of " + html_escape(a.name) + "'s own code (" +
            std::to_string(tokens_of(a, p.file)) + " tokens) is found in " + html_escape(b.name) +
            "'s; " + percent(p.b_in_a) + " of " + html_escape(b.name) + "'s (" +
            std::to_string(tokens_of(b, p.file)) + " tokens) in " + html_escape(a.name) +
            "'s.</p>\n";
    for (const SimilarityRun& run : p.runs) {
        html += "<h3>" + html_escape(a.name) + " lines " + std::to_string(run.a_first) + "-" +
                std::to_string(run.a_last) + " &harr; " + html_escape(b.name) + " lines " +
                std::to_string(run.b_first) + "-" + std::to_string(run.b_last) + " (" +
                std::to_string(run.tokens) + " tokens)</h3>\n";
        html += "<table class=\"side\"><tr><td><pre>" + excerpt(a_text, run.a_first, run.a_last) +
                "</pre></td><td><pre>" + excerpt(b_text, run.b_first, run.b_last) +
                "</pre></td></tr></table>\n";
    }
    return html;
}

// What could not be compared, per submission.
std::string notes(const SimilarityReport& r) {
    std::string html;
    for (const CohortMember& m : r.cohort)
        for (const std::string& note : m.notes)
            html += "<li>" + html_escape(m.name) + ": " + html_escape(note) + "</li>\n";
    return html.empty() ? "" : "<h2>Not compared</h2>\n<ul>\n" + html + "</ul>\n";
}

std::string index_page(const SimilarityReport& r, std::size_t flagged) {
    std::string html = html_page_start("rt-grade similarity", kStyle) +
                       "<h1>Similarity: " + html_escape(r.dir.string()) + "</h1>\n";
    html += "<p>" + std::to_string(r.cohort.size()) + " submissions; " +
            std::to_string(r.pairs.size()) + " file pairs share some code; " +
            std::to_string(flagged) + " at or above " + std::to_string(int(r.threshold)) +
            "%, highest first.</p>\n<p class=\"muted\">A pair's score is the larger of two "
            "shares: how much of one student's own code (what the starter file does not "
            "already hold: its stubs, comments and the code around the solutions are taken "
            "out) the similarity tester finds in the other's, ignoring layout, comments and "
            "names. Tool: " +
            html_escape(r.tool) + ". Regions of 24 tokens or more.</p>\n";
    html += ranking(r, flagged);
    if (flagged > kShownPairs)
        html += "<p>The regions of the first " + std::to_string(kShownPairs) +
                " pairs follow; pairs.csv lists every pair.</p>\n";
    for (std::size_t i = 0; i < std::min(flagged, kShownPairs); ++i)
        html += pair_section(r, r.pairs[i], i + 1);
    return html + notes(r) + kHtmlPageEnd;
}

std::string pairs_csv(const SimilarityReport& r) {
    std::string csv = "file,a,b,a_in_b,b_in_a,score,a_tokens,b_tokens\n";
    for (const SimilarityPair& p : r.pairs) {
        const CohortMember& a = r.cohort[p.a];
        const CohortMember& b = r.cohort[p.b];
        csv += csv_cell(p.file) + "," + csv_cell(a.name) + "," + csv_cell(b.name) + "," +
               std::to_string(p.a_in_b) + "," + std::to_string(p.b_in_a) + "," +
               std::to_string(p.score()) + "," + std::to_string(tokens_of(a, p.file)) + "," +
               std::to_string(tokens_of(b, p.file)) + "\n";
    }
    return csv;
}

}  // namespace

void write_similarity_report(const SimilarityReport& report, const fs::path& out) {
    std::size_t flagged = 0;
    while (flagged < report.pairs.size() && report.pairs[flagged].score() >= report.threshold)
        ++flagged;
    write_text_atomically(out / "index.html", index_page(report, flagged));
    write_text_atomically(out / "pairs.csv", pairs_csv(report));
}

}  // namespace rt::grader
