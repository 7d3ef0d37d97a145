#include "scene/style.h"

#include <algorithm>
#include <array>

namespace bz::scene {

namespace {

struct Named {
    std::string_view name;
    Style style;
};

// Canonical names first; the old ones after, so style_name() finds the canonical one.
constexpr std::array<Named, 8> kNames = {{{"vector", Style::vector},
                                          {"vector-xray", Style::vector_xray},
                                          {"toon", Style::toon},
                                          {"sketch", Style::sketch},
                                          {"pop-art", Style::pop_art},
                                          {"halo", Style::halo},
                                          {"occluded", Style::vector},
                                          {"arcade", Style::vector_xray}}};
constexpr std::size_t kCanonical = 6;

}  // namespace

const std::vector<Style>& all_styles() {
    static const std::vector<Style> styles = [] {
        std::vector<Style> s;
        for (std::size_t i = 0; i < kCanonical; ++i) s.push_back(kNames[i].style);
        return s;
    }();
    return styles;
}

std::string_view style_name(Style s) {
    for (const Named& n : kNames) {
        if (n.style == s) return n.name;
    }
    return "vector";
}

std::optional<Style> style_from_name(std::string_view name) {
    for (const Named& n : kNames) {
        if (n.name == name) return n.style;
    }
    return std::nullopt;
}

std::string style_name_list() {
    std::string out;
    for (std::size_t i = 0; i < kCanonical; ++i) {
        if (i > 0) out += i + 1 == kCanonical ? " or " : ", ";
        out += kNames[i].name;
    }
    return out;
}

const std::vector<std::string_view>& accepted_style_names() {
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> v;
        for (const Named& n : kNames) v.push_back(n.name);
        return v;
    }();
    return names;
}

Style next_style(Style s) {
    const auto& all = all_styles();
    const auto it = std::find(all.begin(), all.end(), s);
    if (it == all.end() || it + 1 == all.end()) return all.front();
    return *(it + 1);
}

}  // namespace bz::scene
