// docs/scene-format.md against the scene schema (scene/scene_schema.h), the tables the readers
// check keys by and `rt fmt` orders keys by. A key added to a table must be documented in the
// sections its element names; a key the documentation's tables list must be one some element
// of that section takes; and "required" must agree where the documentation says it.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/source_dir.h"
#include "core/text_file.h"
#include "scene/scene_schema.h"

namespace {

using rt::SchemaElement;

// A heading of the document and its text: all of it, subsections included, and its own (up to
// its first subsection), where its tables are.
struct Section {
    std::string heading;
    int level = 0;
    std::vector<std::string> lines;
    std::vector<std::string> own_lines;
};

// One row of a Markdown table: its cells, and the header's cells of its table.
struct TableRow {
    std::vector<std::string> header;
    std::vector<std::string> cells;
};

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = text.find('\n', start);
        lines.push_back(text.substr(start, end - start));
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return lines;
}

int heading_level(const std::string& line) {
    std::size_t n = 0;
    while (n < line.size() && line[n] == '#') ++n;
    return n > 0 && n < line.size() && line[n] == ' ' ? int(n) : 0;
}

// Every heading's section: its lines up to the next heading of the same or a higher level.
std::map<std::string, Section> sections_of(const std::vector<std::string>& lines) {
    std::map<std::string, Section> sections;
    bool in_code = false;
    std::vector<Section*> open;
    for (const std::string& line : lines) {
        if (line.rfind("```", 0) == 0) in_code = !in_code;
        const int level = in_code ? 0 : heading_level(line);
        if (level > 0) {
            while (!open.empty() && open.back()->level >= level) open.pop_back();
            Section& section = sections[line.substr(std::size_t(level) + 1)];
            section.heading = line.substr(std::size_t(level) + 1);
            section.level = level;
            open.push_back(&section);
        }
        for (Section* section : open) section->lines.push_back(line);
        if (!open.empty()) open.back()->own_lines.push_back(line);
    }
    return sections;
}

// A table row's cells, split at the | outside backticks.
std::vector<std::string> cells_of(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    bool in_code = false;
    for (std::size_t i = 1; i < line.size(); ++i) {
        if (line[i] == '`') in_code = !in_code;
        if (line[i] == '|' && !in_code) {
            cells.push_back(cell);
            cell.clear();
        } else {
            cell += line[i];
        }
    }
    return cells;
}

std::vector<TableRow> table_rows(const Section& section) {
    std::vector<TableRow> rows;
    std::vector<std::string> header;
    bool after_separator = false;
    for (const std::string& line : section.own_lines) {
        if (line.rfind("|", 0) != 0) {
            header.clear();
            after_separator = false;
        } else if (header.empty()) {
            header = cells_of(line);
        } else if (!after_separator) {
            after_separator = true;  // the |---|---| line
        } else {
            rows.push_back({header, cells_of(line)});
        }
    }
    return rows;
}

// The text with everything inside parentheses left out (defaults and remarks beside a key).
std::string outside_parentheses(const std::string& text) {
    std::string kept;
    int depth = 0;
    for (char c : text) {
        if (c == '(') ++depth;
        if (depth == 0) kept += c;
        if (c == ')' && depth > 0) --depth;
    }
    return kept;
}

// The spans of `text` between backticks.
std::vector<std::string> backticked(const std::string& text) {
    std::vector<std::string> spans;
    std::size_t open = text.find('`');
    while (open != std::string::npos) {
        const std::size_t close = text.find('`', open + 1);
        if (close == std::string::npos) break;
        spans.push_back(text.substr(open + 1, close - open - 1));
        open = text.find('`', close + 1);
    }
    return spans;
}

bool identifier_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
}

bool is_identifier(const std::string& s) {
    if (s.empty()) return false;
    for (char c : s)
        if (!identifier_char(c)) return false;
    return true;
}

// The keys a cell names: its backticked identifiers, outside parentheses.
std::set<std::string> keys_in_cell(const std::string& cell) {
    std::set<std::string> keys;
    for (const std::string& span : backticked(outside_parentheses(cell)))
        if (is_identifier(span)) keys.insert(span);
    return keys;
}

// Whether `text` holds `word` with no identifier character on either side.
bool has_word(const std::string& text, const std::string& word) {
    for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
        const bool starts = at == 0 || !identifier_char(text[at - 1]);
        const std::size_t end = at + word.size();
        if (starts && (end == text.size() || !identifier_char(text[end]))) return true;
    }
    return false;
}

// The keys a row of a key table names ("| key | ...", "| `sky` key | ...", "| step | ...", or
// "| where | key | ..."), in the order written; none for another kind of table.
std::vector<std::string> keys_of_row(const TableRow& row) {
    const std::string first = row.header.empty() ? "" : row.header[0];
    const bool keyed = first.find("key") != std::string::npos || first == " step ";
    const bool where_key = row.header.size() > 1 && row.header[1] == " key ";
    if (!keyed && !where_key) return {};
    std::vector<std::string> keys;
    for (const std::string& span : backticked(outside_parentheses(row.cells[where_key ? 1 : 0])))
        if (is_identifier(span)) keys.push_back(span);
    return keys;
}

// Whether a row is about `element`: always, unless its table has a "where" column, which names
// the element ("render", "material", "sphere", "light `rectangle`", "instance").
bool row_is_for(const TableRow& row, const SchemaElement& element) {
    const auto where = std::find(row.header.begin(), row.header.end(), " where ");
    if (where == row.header.end()) return true;
    std::string said;
    for (char c : row.cells[std::size_t(where - row.header.begin())])
        if (c != '`') said += c;
    const std::string what = element.what;
    if (what.find(" light") != std::string::npos)
        return said == " light " + std::string(element.type) + " ";
    const std::size_t space = what.rfind(' ');
    std::string name = space == std::string::npos ? what : what.substr(space + 1);
    name.erase(std::remove(name.begin(), name.end(), '"'), name.end());
    return said == " " + name + " ";
}

// Whether the section names `key` as a word inside some backticked span.
bool mentions(const Section& section, const std::string& key) {
    for (const std::string& line : section.lines)
        for (const std::string& span : backticked(line))
            if (has_word(span, key)) return true;
    return false;
}

std::string lowercase_first(std::string s) {
    if (!s.empty()) s[0] = char(std::tolower(static_cast<unsigned char>(s[0])));
    return s;
}

class SceneSchema : public ::testing::Test {
  protected:
    void SetUp() override {
        sections_ = sections_of(lines_of(rt::read_text(rt::source_dir() / kDoc)));
    }

    const Section* section(const std::string& heading) const {
        const auto it = sections_.find(heading);
        return it == sections_.end() ? nullptr : &it->second;
    }

    // The elements that name `heading` among their sections.
    std::vector<const SchemaElement*> documented_in(const std::string& heading) const {
        std::vector<const SchemaElement*> elements;
        for (const SchemaElement* element : rt::schema::all())
            for (const std::string& name : element->doc_sections)
                if (name == heading) elements.push_back(element);
        return elements;
    }

    // The keys named `key` of the elements documented in `heading` are required as the docs say.
    void expect_required_as_said(const std::string& heading, const std::string& key,
                                 bool says_required) const {
        for (const SchemaElement* element : documented_in(heading)) {
            for (const rt::SchemaKey& k : element->keys) {
                if (key != k.name) continue;
                EXPECT_EQ(k.required, says_required)
                    << kDoc << ", section \"" << heading << "\": \"" << key << "\" of "
                    << element->what << " is " << (k.required ? "required" : "optional")
                    << " in scene/scene_schema.h's table but "
                    << (says_required ? "required" : "optional") << " in the docs";
            }
        }
    }

    static constexpr const char* kDoc = "docs/scene-format.md";
    std::map<std::string, Section> sections_;
};

TEST_F(SceneSchema, EveryKeyIsDocumentedInItsSections) {
    for (const SchemaElement* element : rt::schema::all()) {
        std::vector<const Section*> sections;
        for (const std::string& heading : element->doc_sections) {
            const Section* s = section(heading);
            ASSERT_NE(s, nullptr) << element->what << " names the section \"" << heading
                                  << "\", which " << kDoc << " has no heading for";
            sections.push_back(s);
        }
        for (const std::string& key : element->key_names()) {
            bool found = false;
            for (const Section* s : sections) found = found || mentions(*s, key);
            EXPECT_TRUE(found) << "\"" << key << "\" of " << element->what
                               << " (scene/scene_schema.h) is not in backticks in " << kDoc
                               << "'s section \"" << element->doc_sections[0]
                               << "\": document it there";
        }
    }
}

TEST_F(SceneSchema, KeysTheDocsListAreKeysOfTheirSection) {
    for (const auto& [heading, s] : sections_) {
        const std::vector<const SchemaElement*> elements = documented_in(heading);
        for (const TableRow& row : table_rows(s)) {
            for (const std::string& key : keys_of_row(row)) {
                bool known = false;
                for (const SchemaElement* element : elements)
                    known = known || (row_is_for(row, *element) && element->has(key));
                EXPECT_TRUE(known) << kDoc << ", section \"" << heading << "\": its table lists \""
                                   << key << "\", which no element documented there takes "
                                   << "(scene/scene_schema.h): remove the row or add the key";
            }
        }
    }
}

// `rt fmt` writes keys in the order of the tables (docs/scene-format.md#canonical-form): each
// element's keys come in its table's order in the key tables of its sections.
TEST_F(SceneSchema, KeyTablesListKeysInTheSchemaOrder) {
    for (const auto& [heading, s] : sections_) {
        for (const SchemaElement* element : documented_in(heading)) {
            const std::vector<std::string> order = element->key_names();
            std::size_t last = 0;
            std::string last_key;
            for (const TableRow& row : table_rows(s)) {
                if (!row_is_for(row, *element)) continue;
                for (const std::string& key : keys_of_row(row)) {
                    const auto at = std::find(order.begin(), order.end(), key);
                    if (at == order.end()) continue;
                    const std::size_t index = std::size_t(at - order.begin());
                    EXPECT_GE(index, last)
                        << kDoc << ", section \"" << heading << "\": \"" << key << "\" of "
                        << element->what << " comes after \"" << last_key
                        << "\", but before it in scene/scene_schema.h's table, the order rt fmt "
                        << "writes: list them in one order";
                    last = std::max(last, index);
                    last_key = key;
                }
            }
        }
    }
}

// A "| key | default | notes |" row whose default says "required" is a required key, and the
// other way round.
TEST_F(SceneSchema, RequiredAgreesWithTheKeyTables) {
    for (const auto& [heading, s] : sections_) {
        for (const TableRow& row : table_rows(s)) {
            if (row.header.size() < 2 || row.header[0] != " key " || row.header[1] != " default ")
                continue;
            const bool says_required = row.cells[1].find("required") != std::string::npos;
            for (const std::string& key : keys_in_cell(row.cells[0]))
                expect_required_as_said(heading, key, says_required);
        }
    }
}

// A "| type | required | optional |" row (surfaces, lights): the required cell names exactly the
// type's required keys (but "type"), unless it offers a choice ("`file` or `procedural`"); every
// key the row names is one the type takes.
TEST_F(SceneSchema, TypeTablesAgreeWithTheTypes) {
    int rows_checked = 0;
    for (const auto& [heading, s] : sections_) {
        for (const TableRow& row : table_rows(s)) {
            if (row.header.size() < 3 || row.header[0] != " type " || row.header[1] != " required ")
                continue;
            const std::set<std::string> type = keys_in_cell(row.cells[0]);
            ASSERT_EQ(type.size(), 1u)
                << kDoc << ", section \"" << heading << "\": " << row.cells[0];
            const SchemaElement* element = nullptr;
            for (const SchemaElement* e : documented_in(heading))
                if (*type.begin() == e->type) element = e;
            ASSERT_NE(element, nullptr)
                << kDoc << ", section \"" << heading << "\": no " << lowercase_first(heading)
                << " type \"" << *type.begin() << "\" in scene/scene_schema.h";
            std::set<std::string> required;
            for (const rt::SchemaKey& k : element->keys)
                if (k.required && std::string(k.name) != "type") required.insert(k.name);
            const std::set<std::string> listed = keys_in_cell(row.cells[1]);
            if (row.cells[1].find(" or ") == std::string::npos) {
                EXPECT_EQ(listed, required) << kDoc << ", section \"" << heading << "\", "
                                            << element->what << ": the required keys differ";
            }
            std::set<std::string> named = listed;
            named.merge(keys_in_cell(row.cells[2]));
            for (const std::string& key : named)
                EXPECT_TRUE(element->has(key))
                    << kDoc << ", section \"" << heading << "\": " << element->what
                    << " takes no \"" << key << "\"";
            ++rows_checked;
        }
    }
    EXPECT_EQ(rows_checked, 11) << "the surface and light type tables: 7 surfaces, 4 lights";
}

}  // namespace
