#pragma once
// Stroke text for the HUD, from the public-domain Hershey fonts (data/fonts/*.jhf), turned
// into HudLines so text glows with the same beam shading and bloom as everything else.
#include <filesystem>
#include <string_view>
#include <vector>

#include "scene/frame_list.h"

namespace bz::scene {

enum class TextAlign { left, center, right };

class VectorFont {
  public:
    // Loads a Hershey .jhf file; throws UserError naming file:line on a malformed glyph.
    explicit VectorFont(const std::filesystem::path& jhf_file);
    // The font shipped in data/fonts (Hershey "futural").
    static VectorFont load_default();

    // Appends the strokes of `text` with its baseline at `origin` (HUD units), cap height
    // `height`. Unknown characters draw as a space.
    void draw(std::vector<HudLine>& out, std::string_view text, glm::vec2 origin, float height,
              glm::vec3 color, TextAlign align = TextAlign::left, float intensity = 1.0f) const;
    float width(std::string_view text, float height) const;
    std::size_t glyph_count() const { return glyphs_.size(); }

  private:
    struct Glyph {
        float left = 0.0f, right = 0.0f;              // advance = right - left
        std::vector<std::vector<glm::vec2>> strokes;  // font units, y down as in the file
    };
    const Glyph* glyph(unsigned char c) const;  // nullptr when the font has no such glyph
    float advance(unsigned char c) const;       // in font units
    float scale(float height) const { return height / (baseline_ - cap_top_); }

    std::vector<Glyph> glyphs_;  // index = character - 32
    // Font units of the top and bottom of 'H' (Hershey Roman: 21 units of cap height).
    float cap_top_ = -12.0f;
    float baseline_ = 9.0f;
};

}  // namespace bz::scene
