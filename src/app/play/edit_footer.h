#pragma once
// The --edit screen's footer: the status line (where the camera is, what the reticle names)
// over the key hints, both at the player's text size (the Comfort page's ui_scale). A line too
// wide for the screen breaks at its "   " gaps onto more lines, and only a single piece that
// still does not fit gets smaller. The footer grows upwards as tall as its lines need, and
// returns its top so the frame-rate readout and the notices stack above it (hud_layout.h).
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "game/hud/hud_layout.h"
#include "scene/frame_list.h"
#include "scene/vector_font.h"

namespace bz::app {

struct EditFooterLine {
    std::string text;
    glm::vec2 origin{0.0f};  // left end of the baseline, HUD units
    float height = 0.0f;
    bool status = false;  // the status line's (green), else the key hints' (white)
};

struct EditFooter {
    std::vector<EditFooterLine> lines;  // bottom-up: key hints first, the status above them
    game::hud::Box box;                 // holds every line; box.max.y is the footer's top
};

// The key hints of the --edit screen.
inline constexpr const char* kEditKeyHints =
    "W A S D MOVE   R / F UP, DOWN   ARROWS OR RIGHT MOUSE LOOK   SHIFT FAST   F5 SHADERS   "
    "ESCAPE LEAVE";

// The text heights at size 1, HUD units.
inline constexpr float kEditStatusHeight = 0.036f;
inline constexpr float kEditKeysHeight = 0.03f;

EditFooter layout_edit_footer(const scene::VectorFont& font, const std::string& status,
                              const std::string& keys, double aspect, float text_scale);

// Appends the footer's lines.
void draw_edit_footer(const scene::VectorFont& font, const EditFooter& footer,
                      std::vector<scene::HudLine>& out);

}  // namespace bz::app
