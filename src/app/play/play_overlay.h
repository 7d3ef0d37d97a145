#pragma once
// Text the play loop lays over the game's own HUD, each kind in the region the HUD layout
// (game/hud/hud_layout.h) reserves for it: errors (level, model, shader, settings) in the error
// box under the radar band, short notices (screenshot saved, volume) along the bottom, and the
// footer's frame-rate readout. Drawn with the vector font so it glows like everything else.
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "scene/frame_list.h"
#include "scene/vector_font.h"

namespace bz::app {

// What an error is about, so the player knows what to fix; each kind has its own slot.
enum class ErrorKind : std::uint8_t { level, model, shader, settings, count };
std::string_view error_title(ErrorKind kind);  // "LEVEL ERROR"

class PlayOverlay {
  public:
    explicit PlayOverlay(const scene::VectorFont& font) : font_(font) {}

    // Shown until replaced (or for `seconds` when given); an empty list clears that kind.
    void set_errors(ErrorKind kind, std::vector<std::string> lines,
                    std::optional<double> seconds = std::nullopt);
    // Every kind's lines, level errors first.
    std::vector<std::string> errors() const;
    const std::vector<std::string>& errors(ErrorKind kind) const;
    // Shown for `seconds`, newest at the bottom.
    void notify(std::string text, double seconds = 2.5);
    void advance(double seconds);  // ages the notices and timed errors
    // The footer's right end (the frame-rate readout); empty hides it.
    void set_footer(std::string text) { footer_ = std::move(text); }
    // The top of the screen's footer (HUD units): the readout and the notices stack above it.
    // The --edit footer is taller than the one-line footer of the other screens.
    void set_footer_top(float top) { footer_top_ = top; }
    // Where notices go. A menu's rows reach down to the readout's strip at a large text size,
    // so the notice strip would cross its last rows: while a menu is open the newest notice
    // takes the footer line instead, in place of the page's key hints, for as long as it shows.
    enum class NoticePlace : std::uint8_t { strip, footer };
    void set_notice_place(NoticePlace place) { notice_place_ = place; }
    // Whether the footer line is the newest notice's this frame (the menu then leaves out its
    // key hints).
    bool notice_in_footer() const {
        return notice_place_ == NoticePlace::footer && !notices_.empty();
    }

    // The player's text size (the Comfort page's ui_scale, 1 to 2): every line is this much
    // taller, wrapped and clipped to the same regions, so larger text never leaves them.
    void set_text_scale(float scale) { scale_ = std::clamp(scale, 1.0f, 2.0f); }

    // Appends the overlay's lines (HUD units: y up, x in -aspect..aspect).
    void draw(std::vector<scene::HudLine>& out, double aspect) const;
    std::size_t notice_count() const { return notices_.size(); }

    // The lines the error box shows for `errors` (already split per kind, titles included):
    // wrapped to the box's width, the first lines kept and the rest counted in a last line.
    struct BoxLine {
        std::string text;
        bool title = false;
    };
    std::vector<BoxLine> error_box_lines(double aspect) const;

  private:
    struct Notice {
        std::string text;
        double seconds_left;
    };
    struct Errors {
        std::vector<std::string> lines;
        std::optional<double> seconds_left;
    };
    // Splits `text` into lines no wider than `max_width` at `height`, breaking at spaces when
    // it can and inside words when it must.
    std::vector<std::string> wrap(const std::string& text, float height, float max_width) const;

    const scene::VectorFont& font_;
    std::array<Errors, static_cast<std::size_t>(ErrorKind::count)> errors_;
    std::vector<Notice> notices_;
    std::string footer_;
    float scale_ = 1.0f;
    float footer_top_ = -0.88f;  // game::hud::kFooterTop
    NoticePlace notice_place_ = NoticePlace::strip;
};

}  // namespace bz::app
