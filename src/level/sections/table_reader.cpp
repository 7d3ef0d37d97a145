#include "level/sections/table_reader.h"

#include <cmath>
#include <cstdio>

#include "level/sections/suggest.h"

namespace bz::level {

void Diagnostics::error(const SourcePos& pos, std::string message) {
    if (full()) return;
    errors_.push_back({pos, std::move(message)});
    if (full()) {
        errors_.push_back({pos, "too many errors (" + std::to_string(max_) + "); stopping here"});
    }
}

SourcePos Diagnostics::at(const toml::source_region& where) const {
    return SourcePos{file_, static_cast<int>(where.begin.line),
                     static_cast<int>(where.begin.column)};
}

std::string_view type_name(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a number";
        case toml::node_type::boolean:
            return "a boolean";
        case toml::node_type::array:
            return "an array";
        case toml::node_type::table:
            return "a table";
        case toml::node_type::date:
            return "a date";
        case toml::node_type::time:
            return "a time";
        case toml::node_type::date_time:
            return "a date-time";
        case toml::node_type::none:
            break;
    }
    return "nothing";
}

std::string number_text(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buf[32];
    for (int digits = 6; digits <= 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, value);
        if (std::strtod(buf, nullptr) == value) break;
    }
    return buf;
}

std::optional<double> read_number(const toml::node& node, std::string_view name, Range range,
                                  Diagnostics& diag) {
    double value = 0.0;
    if (const auto* i = node.as_integer()) {
        value = static_cast<double>(i->get());
    } else if (const auto* f = node.as_floating_point()) {
        value = f->get();
    } else {
        diag.error(node.source(),
                   std::string(name) + " must be a number, not " + std::string(type_name(node)));
        return std::nullopt;
    }
    if (!std::isfinite(value)) {
        diag.error(node.source(),
                   std::string(name) + " must be a finite number, not " + number_text(value));
        return std::nullopt;
    }
    if (value < range.min || value > range.max) {
        diag.error(node.source(), std::string(name) + " must be between " + number_text(range.min) +
                                      " and " + number_text(range.max) + ", not " +
                                      number_text(value));
        return std::nullopt;
    }
    return value;
}

TableReader::TableReader(const toml::table& table, std::string what,
                         std::span<const std::string_view> allowed, Diagnostics& diagnostics,
                         std::span<const std::string_view> top_level)
    : table_(table), what_(std::move(what)), diag_(diagnostics) {
    const auto contains = [](std::span<const std::string_view> keys, std::string_view k) {
        for (const auto a : keys) {
            if (a == k) return true;
        }
        return false;
    };
    for (const auto& [key, value] : table_) {
        if (contains(allowed, key.str())) continue;
        if (contains(top_level, key.str())) {
            // TOML puts every key after a [header] into that table, a classic trap.
            diag_.error(key.source(), "unknown key " + quote(key.str()) + " in " + what_ + "; '" +
                                          std::string(key.str()) +
                                          "' belongs at the top level: move it above the first "
                                          "[table] header");
            continue;
        }
        diag_.error(key.source(), "unknown key " + quote(key.str()) + " in " + what_ +
                                      did_you_mean(key.str(), allowed));
    }
}

SourcePos TableReader::where() const {
    return diag_.at(table_.source());
}

void TableReader::missing(std::string_view key) {
    diag_.error(where(), what_ + " needs the key '" + std::string(key) + "'");
}

std::optional<double> TableReader::number(std::string_view key, Range range) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    return read_number(*node, "'" + std::string(key) + "'", range, diag_);
}

std::optional<std::int64_t> TableReader::integer(std::string_view key, std::int64_t min,
                                                 std::int64_t max) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    const std::string name = "'" + std::string(key) + "'";
    const auto* i = node->as_integer();
    if (!i) {
        diag_.error(node->source(),
                    name + " must be a whole number, not " + std::string(type_name(*node)));
        return std::nullopt;
    }
    if (i->get() < min || i->get() > max) {
        diag_.error(node->source(), name + " must be between " + std::to_string(min) + " and " +
                                        std::to_string(max) + ", not " + std::to_string(i->get()));
        return std::nullopt;
    }
    return i->get();
}

std::optional<bool> TableReader::boolean(std::string_view key) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    if (const auto* b = node->as_boolean()) return b->get();
    diag_.error(node->source(), "'" + std::string(key) + "' must be true or false, not " +
                                    std::string(type_name(*node)));
    return std::nullopt;
}

std::optional<std::string> TableReader::text(std::string_view key, std::size_t max_chars) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    const std::string name = "'" + std::string(key) + "'";
    const auto* s = node->as_string();
    if (!s) {
        diag_.error(node->source(),
                    name + " must be a string, not " + std::string(type_name(*node)));
        return std::nullopt;
    }
    const std::string& value = s->get();
    std::size_t chars = 0;
    for (const char ch : value) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x20 || c == 0x7f) {
            diag_.error(node->source(),
                        name + " must not contain control characters (tabs, newlines)");
            return std::nullopt;
        }
        if ((c & 0xc0) != 0x80) ++chars;
    }
    if (chars > max_chars) {
        diag_.error(node->source(), name + " is " + std::to_string(chars) +
                                        " characters long; the limit is " +
                                        std::to_string(max_chars));
        return std::nullopt;
    }
    return value;
}

std::optional<std::string> TableReader::choice(std::string_view key,
                                               std::span<const std::string_view> values) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    const std::string name = "'" + std::string(key) + "'";
    const auto* s = node->as_string();
    if (!s) {
        diag_.error(node->source(),
                    name + " must be a string, not " + std::string(type_name(*node)));
        return std::nullopt;
    }
    for (const auto v : values) {
        if (v == s->get()) return s->get();
    }
    std::string list;
    for (const auto v : values) list += (list.empty() ? "" : ", ") + std::string(v);
    diag_.error(node->source(), "unknown " + std::string(key) + " " + quote(s->get()) +
                                    did_you_mean(s->get(), values) + " (one of: " + list + ")");
    return std::nullopt;
}

std::optional<glm::dvec3> TableReader::vec3(std::string_view key,
                                            const std::array<Range, 3>& ranges) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    const std::string name = "'" + std::string(key) + "'";
    const auto* a = node->as_array();
    if (!a || a->size() != 3) {
        diag_.error(node->source(), name + " must be an array of 3 numbers [x, y, z], not " +
                                        (a ? "an array of " + std::to_string(a->size())
                                           : std::string(type_name(*node))));
        return std::nullopt;
    }
    constexpr std::array<std::string_view, 3> kAxes = {"x", "y", "z"};
    glm::dvec3 out{0.0};
    bool ok = true;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto v =
            read_number(*a->get(i), name + " " + std::string(kAxes[i]), ranges[i], diag_);
        if (v) out[static_cast<glm::length_t>(i)] = *v;
        ok = ok && v.has_value();
    }
    if (!ok) return std::nullopt;
    return out;
}

namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

float srgb_to_linear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

std::optional<glm::vec3> TableReader::color(std::string_view key) {
    const toml::node* node = get(key);
    if (!node) return std::nullopt;
    const std::string name = "'" + std::string(key) + "'";
    if (const auto* s = node->as_string()) {
        const std::string& v = s->get();
        bool ok = v.size() == 7 && v[0] == '#';
        for (std::size_t i = 1; ok && i < 7; ++i) ok = hex_digit(v[i]) >= 0;
        if (!ok) {
            diag_.error(node->source(),
                        name + " must look like \"#33ff66\" (six hex digits), not " + quote(v));
            return std::nullopt;
        }
        glm::vec3 out;
        for (int c = 0; c < 3; ++c) {
            const int byte = hex_digit(v[static_cast<std::size_t>(1 + 2 * c)]) * 16 +
                             hex_digit(v[static_cast<std::size_t>(2 + 2 * c)]);
            out[c] = srgb_to_linear(static_cast<float>(byte) / 255.0f);
        }
        return out;
    }
    const auto* a = node->as_array();
    if (!a || a->size() != 3) {
        diag_.error(
            node->source(),
            name + " must be \"#rrggbb\" or an array of 3 numbers [r, g, b], not " +
                (a ? "an array of " + std::to_string(a->size()) : std::string(type_name(*node))));
        return std::nullopt;
    }
    constexpr std::array<std::string_view, 3> kChannels = {"red", "green", "blue"};
    glm::vec3 out{0.0f};
    bool ok = true;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto v =
            read_number(*a->get(i), name + " " + std::string(kChannels[i]), {0.0, 1.0}, diag_);
        if (v) out[static_cast<glm::length_t>(i)] = static_cast<float>(*v);
        ok = ok && v.has_value();
    }
    if (!ok) return std::nullopt;
    return out;
}

}  // namespace bz::level
