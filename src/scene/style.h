#pragma once
// The looks a frame can be drawn in, by name. Plain data: the level loader, the settings file
// and the command line name a style, the renderer (render/styles/) says what each one draws.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bz::scene {

enum class Style : std::uint8_t {
    vector,       // glowing vector-monitor lines, hidden lines removed (Bernardoni 2018)
    vector_xray,  // the same without hidden-line removal: the 1980 machine hid nothing
    toon,         // cel-shaded fill with outlines (Castro & Macedo)
    sketch,       // pencil strokes on paper (Olejnik & Litchmore, after Jezek et al. 2018)
    pop_art,      // flat colour, Ben-Day dots and a fine outline (Olejnik & Litchmore)
    halo,         // haloed silhouette strokes, smoothed from coarse meshes (Loviscach)
    technical,    // ink on white; in vector output, hidden lines dashed by occlusion level
    // The names the first styles had; kept so old levels, settings and scripts still work.
    occluded = vector,
    arcade = vector_xray,
};

// Every style, in the order the play key cycles through them.
const std::vector<Style>& all_styles();
// The canonical name ("vector", "vector-xray", "toon", "sketch", "pop-art", "halo",
// "technical").
std::string_view style_name(Style s);
// A canonical name, or an old one ("occluded", "arcade"); nullopt for anything else.
std::optional<Style> style_from_name(std::string_view name);
// "vector, vector-xray, toon, sketch, pop-art, halo or technical", for messages.
std::string style_name_list();
// Every accepted name, canonical first, then the old aliases.
const std::vector<std::string_view>& accepted_style_names();
// The style after `s` in all_styles(), wrapping around.
Style next_style(Style s);

}  // namespace bz::scene
