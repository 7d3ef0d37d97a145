#pragma once
// Text the play loop lays over the game's own HUD: level errors while a hot reload is broken,
// and short notices (screenshot saved, volume). Drawn with the vector font
// so it glows like everything else.
#include <string>
#include <vector>

#include "scene/frame_list.h"
#include "scene/vector_font.h"

namespace bz::app {

class PlayOverlay {
  public:
    explicit PlayOverlay(const scene::VectorFont& font) : font_(font) {}

    // Shown until replaced; an empty list clears it.
    void set_errors(std::vector<std::string> lines) { errors_ = std::move(lines); }
    const std::vector<std::string>& errors() const { return errors_; }
    // Shown for `seconds`, newest at the bottom.
    void notify(std::string text, double seconds = 2.5);
    void advance(double seconds);  // ages the notices

    // Appends the overlay's lines (HUD units: y up, x in -aspect..aspect).
    void draw(std::vector<scene::HudLine>& out, double aspect) const;
    std::size_t notice_count() const { return notices_.size(); }

  private:
    struct Notice {
        std::string text;
        double seconds_left;
    };
    // Splits `text` into lines no wider than `max_width` at `height`, breaking at spaces when
    // it can and inside words when it must.
    std::vector<std::string> wrap(const std::string& text, float height, float max_width) const;

    const scene::VectorFont& font_;
    std::vector<std::string> errors_;
    std::vector<Notice> notices_;
};

}  // namespace bz::app
