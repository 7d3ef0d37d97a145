#include "scene/style.h"

#include <algorithm>

#include "scene/style_table.h"

namespace bz::scene {

const std::vector<Style>& all_styles() {
    static const std::vector<Style> styles = [] {
        std::vector<Style> s;
        for (int i = 0; i <= static_cast<int>(kLastStyle); ++i) s.push_back(static_cast<Style>(i));
        return s;
    }();
    return styles;
}

std::string_view style_name(Style s) {
    return style_entry(s).name;
}

std::optional<Style> style_from_name(std::string_view name) {
    if (name.empty()) return std::nullopt;
    for (const Style s : all_styles()) {
        const StyleEntry e = style_entry(s);
        if (e.name == name) return s;
        if (std::find(e.aliases.begin(), e.aliases.end(), name) != e.aliases.end()) return s;
    }
    return std::nullopt;
}

std::string style_name_list() {
    std::string out;
    const auto& all = all_styles();
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (i > 0) out += i + 1 == all.size() ? " or " : ", ";
        out += style_name(all[i]);
    }
    return out;
}

const std::vector<std::string_view>& accepted_style_names() {
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> v;
        for (const Style s : all_styles()) v.push_back(style_entry(s).name);
        for (const Style s : all_styles()) {
            for (const std::string_view a : style_entry(s).aliases)
                if (!a.empty()) v.push_back(a);
        }
        return v;
    }();
    return names;
}

const std::vector<std::string>& accepted_style_name_strings() {
    static const std::vector<std::string> names(accepted_style_names().begin(),
                                                accepted_style_names().end());
    return names;
}

std::string style_help() {
    std::string out;
    for (const Style s : all_styles()) {
        const StyleEntry e = style_entry(s);
        std::string line = "  " + std::string(e.name);
        line.resize(std::max<std::size_t>(line.size() + 1, 15), ' ');
        out += line + std::string(e.help);
        if (!e.aliases[0].empty()) out += " (old name: " + std::string(e.aliases[0]) + ")";
        out += "\n";
    }
    return out;
}

Style next_style(Style s) {
    const auto& all = all_styles();
    const auto it = std::find(all.begin(), all.end(), s);
    if (it == all.end() || it + 1 == all.end()) return all.front();
    return *(it + 1);
}

}  // namespace bz::scene
