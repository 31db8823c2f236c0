// The typed reader over a scene file's JSON: values to numbers, vectors, colours and words, each
// checked, with `file:line:col: error:` messages pointing at the offending value.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/real.h"
#include "scene/json_positions.h"
#include "scene/scene.h"
#include "scene/scene_schema.h"

namespace rt::scene_internal {

using json = nlohmann::json;

// How a value is described in "must be ..., got <it>": "null", "the string "x"", "an array"...
std::string describe(const json& value);

// The value of `key` in `object`, or null when it is absent.
const json* member(const json& object, const char* key);

class SceneReader {
  public:
    // `name` starts every message; `text` must outlive the reader.
    SceneReader(const std::string& text, const std::string& name) : text_(text), name_(name) {}

    // Parses the text into document() (scene_syntax.cpp): an empty file, brackets nested absurdly
    // deep, invalid JSON, a number beyond double and a duplicate key are errors.
    void parse();
    const json& document() const { return root_; }

    // ---- errors (all throw SceneError) ----
    [[noreturn]] void fail_at(std::size_t offset, const std::string& what_and_fix) const;
    [[noreturn]] void fail_at(std::size_t offset, const std::string& what,
                              const std::string& fix) const;
    // At the value `pointer` names (the enclosing object for a missing field).
    [[noreturn]] void fail_value(const std::string& pointer, const std::string& what,
                                 const std::string& fix) const;
    // The same with a message already in `what; fix` form (from the OBJ reader).
    [[noreturn]] void fail_value(const std::string& pointer, const std::string& what_and_fix) const;
    // At the key of `pointer` (unknown and duplicate keys).
    [[noreturn]] void fail_key(const std::string& pointer, const std::string& what,
                               const std::string& fix) const;

    // ---- warnings (to stderr, loading goes on) ----
    // At the key of `pointer`: "scene.json:12:5: warning: what; fix".
    void warn_key(const std::string& pointer, const std::string& what,
                  const std::string& fix) const;

    // How a value is named in messages: "radius", "center"[1], "surfaces"[3].
    static std::string label(const std::string& pointer);
    // The text of a scalar value as written in the file (to show 1e999 rather than "inf").
    std::string source_text(const std::string& pointer) const;

    // ---- typed fields ----
    void check_keys(const json& object, const std::string& pointer, const std::string& what,
                    const std::vector<std::string>& known) const;
    // The keys of `element`'s table (scene_schema.h), named in messages as element.what.
    void check_keys(const json& object, const std::string& pointer,
                    const SchemaElement& element) const;
    void require_object(const json& value, const std::string& pointer,
                        const std::string& example) const;
    void require_array(const json& value, const std::string& pointer,
                       const std::string& example) const;
    // An array of exactly `size` `entries` ("numbers", "points"); a wrong count is told in
    // `counted` ("got 2 points").
    void require_array_of(const json& value, const std::string& pointer, std::size_t size,
                          const std::string& entries, const std::string& counted,
                          const std::string& fix) const;
    const json& required(const json& object, const std::string& pointer, const char* key,
                         const std::string& what, const std::string& example) const;
    double number(const json& value, const std::string& pointer) const;
    // A number that must also fit in Real (float by default).
    Real real(const json& value, const std::string& pointer) const;
    double whole_number(const json& value, const std::string& pointer) const;
    // A number checked against a range; `rule` reads like "> 0" or "between 1 and 16384".
    Real real_in(const json& value, const std::string& pointer, bool ok_if(double),
                 const std::string& rule, const std::string& fix) const;
    Vec3 vec3(const json& value, const std::string& pointer) const;
    Color color(const json& value, const std::string& pointer) const;
    bool boolean(const json& value, const std::string& pointer) const;
    std::string string(const json& value, const std::string& pointer,
                       const std::string& example) const;
    // One of a fixed set of words; returns its position in `options`.
    std::size_t choice(const json& value, const std::string& pointer,
                       const std::vector<std::string>& options) const;
    Vec3 unit_direction(const json& value, const std::string& pointer,
                        const std::string& fix) const;

  protected:
    const std::string& text_;
    std::string name_;

  private:
    void check_nesting() const;
    std::size_t first_overflowing_number() const;
    std::string syntax_message(const json::parse_error& e) const;

    json root_;
    std::optional<JsonPositions> positions_;
};

}  // namespace rt::scene_internal
