#pragma once
// Typed, range-checked reads of one TOML table's keys. Every problem becomes a Diagnostic at
// the exact key or value; a bad or missing value reads as "no value" so validation goes on and
// the file's other errors are found in the same pass.
#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/text/toml.h"
#include "level/diagnostic.h"

namespace bz::level {

// Collects the errors of one file.
class Diagnostics {
  public:
    Diagnostics(std::string file, std::size_t max_errors)
        : file_(std::move(file)), max_(max_errors) {}
    void error(const SourcePos& pos, std::string message);
    void error(const toml::source_region& where, std::string message) {
        error(at(where), std::move(message));
    }
    SourcePos at(const toml::source_region& where) const;
    const std::string& file() const { return file_; }
    bool full() const { return errors_.size() >= max_; }
    std::vector<Diagnostic> take() { return std::move(errors_); }
    bool empty() const { return errors_.empty(); }

  private:
    std::string file_;
    std::size_t max_;
    std::vector<Diagnostic> errors_;
};

struct Range {
    double min;
    double max;
};

// "a string", "an integer", ... for messages.
std::string_view type_name(const toml::node& node);
// Shortest text that reads back as the same value, for messages ("20", "0.25", "1e+09").
std::string number_text(double value);

class TableReader {
  public:
    // `what` names the table in messages ("[field]", "obstacle 3"). Keys not in `allowed`
    // are reported at once, with a suggestion. A key from `top_level` found here was most
    // likely written below a [table] header by mistake, and the message says so.
    TableReader(const toml::table& table, std::string what,
                std::span<const std::string_view> allowed, Diagnostics& diagnostics,
                std::span<const std::string_view> top_level = {});

    const toml::node* get(std::string_view key) const { return table_.get(key); }
    bool has(std::string_view key) const { return table_.contains(key); }
    const std::string& what() const { return what_; }
    // Where the table starts: its header, or the first key of an inline/implicit table.
    SourcePos where() const;
    // Reports a missing required key at the table.
    void missing(std::string_view key);

    std::optional<double> number(std::string_view key, Range range);
    std::optional<std::int64_t> integer(std::string_view key, std::int64_t min, std::int64_t max);
    std::optional<bool> boolean(std::string_view key);
    // At most max_chars characters; no control characters.
    std::optional<std::string> text(std::string_view key, std::size_t max_chars);
    // One of `values`, with a suggestion when it is close to one.
    std::optional<std::string> choice(std::string_view key,
                                      std::span<const std::string_view> values);
    // [x, y, z] with a range per component.
    std::optional<glm::dvec3> vec3(std::string_view key, const std::array<Range, 3>& ranges);
    // "#rrggbb" (sRGB, as colour pickers give it) or [r, g, b] (linear, each 0..1).
    std::optional<glm::vec3> color(std::string_view key);

    Diagnostics& diagnostics() { return diag_; }

  private:
    const toml::table& table_;
    std::string what_;
    Diagnostics& diag_;
};

// Checks one node as a finite number within `range`; `name` is how messages call it.
std::optional<double> read_number(const toml::node& node, std::string_view name, Range range,
                                  Diagnostics& diag);

}  // namespace bz::level
