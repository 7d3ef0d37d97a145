#include "cli/cli_args.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

#include "core/budgets.h"
#include "core/text/printable.h"

namespace bz::app {

bool looks_like_option(std::string_view word) {
    if (word.size() < 2 || word[0] != '-') return false;
    const char c = word[1];
    return !((c >= '0' && c <= '9') || c == '.');
}

std::string_view ArgCursor::value(std::string_view option) {
    if (done()) throw UsageError(std::string(option) + " needs a value");
    const std::string_view v = args_[index_];
    if (v.empty()) throw UsageError(std::string(option) + " needs a value, not an empty string");
    if (looks_like_option(v)) {
        throw UsageError(std::string(option) + " needs a value, but the next word is the option " +
                         printable(v) + " (write ./" + printable(v) + " for a file of that name)");
    }
    ++index_;
    return v;
}

std::string choice_list(std::span<const std::string_view> names) {
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
        out += names[i];
    }
    return out;
}

render::ColourClears parse_colour_clears(std::string_view option, std::string_view text) {
    using enum render::ColourClears;
    return parse_choice<render::ColourClears>(
        option, text, {{"auto", automatic}, {"pipeline", pipeline}, {"compute", compute}});
}

render::BloomChain parse_bloom_chain(std::string_view option, std::string_view text) {
    using enum render::BloomChain;
    return parse_choice<render::BloomChain>(
        option, text, {{"auto", automatic}, {"pipeline", pipeline}, {"compute", compute}});
}

render::PrepassRaster parse_prepass_raster(std::string_view option, std::string_view text) {
    using enum render::PrepassRaster;
    return parse_choice<render::PrepassRaster>(
        option, text, {{"auto", automatic}, {"pipeline", pipeline}, {"compute", compute}});
}

render::EdgePrefilter parse_edge_prefilter(std::string_view option, std::string_view text) {
    using enum render::EdgePrefilter;
    return parse_choice<render::EdgePrefilter>(option, text,
                                               {{"auto", automatic}, {"gpu", gpu}, {"cpu", cpu}});
}

double parse_number(std::string_view option, std::string_view text) {
    double v = 0.0;
    const auto* end = text.data() + text.size();
    const auto r = std::from_chars(text.data(), end, v);
    if (r.ec != std::errc{} || r.ptr != end || !std::isfinite(v)) {
        throw UsageError(std::string(option) + ": '" + printable(text) +
                         "' is not a finite number");
    }
    return v;
}

int parse_int(std::string_view option, std::string_view text, int min_value, int max_value) {
    int v = 0;
    const auto* end = text.data() + text.size();
    const auto r = std::from_chars(text.data(), end, v);
    if (r.ec != std::errc{} || r.ptr != end || v < min_value || v > max_value) {
        throw UsageError(std::string(option) + ": '" + printable(text) +
                         "' is not an integer in [" + std::to_string(min_value) + ", " +
                         std::to_string(max_value) + "]");
    }
    return v;
}

scene::Style parse_style(std::string_view option, std::string_view text) {
    if (const auto s = scene::style_from_name(text)) return *s;
    throw UsageError(std::string(option) + ": expected " + scene::style_name_list() + ", not '" +
                     printable(text) + "'");
}

glm::dvec3 parse_vec3(std::string_view option, std::string_view text) {
    glm::dvec3 v(0.0);
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = text.find(',', start);
        const bool last = i == 2;
        if (last != (comma == std::string_view::npos)) {
            throw UsageError(std::string(option) + ": expected x,y,z but got '" + printable(text) +
                             "'");
        }
        const std::string_view part =
            text.substr(start, last ? std::string_view::npos : comma - start);
        v[i] = parse_number(option, part);
        start = comma + 1;
    }
    return v;
}

glm::ivec2 parse_size(std::string_view option, std::string_view text) {
    const std::size_t x = text.find('x');
    if (x == std::string_view::npos) {
        throw UsageError(std::string(option) + ": expected WxH but got '" + printable(text) + "'");
    }
    // Refused here, before any work: a picture larger than the budget would take gigabytes
    // and end in an incomplete framebuffer on most drivers.
    const glm::ivec2 size{parse_int(option, text.substr(0, x), 1, budget::kImageSide),
                          parse_int(option, text.substr(x + 1), 1, budget::kImageSide)};
    if (static_cast<std::int64_t>(size.x) * size.y > budget::kImagePixels) {
        throw UsageError(std::string(option) + ": " + printable(text) + " is more than " +
                         std::to_string(budget::kImagePixels) + " pixels");
    }
    return size;
}

}  // namespace bz::app
