#pragma once
// One menu screen as plain data (a title, rows, a hint line) and how it is drawn as vector
// text. The rows scroll when there are more than fit; the selected one is marked.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "game/hud/hud_layout.h"
#include "scene/frame_list.h"
#include "scene/vector_font.h"

namespace bz::app::menu {

struct Row {
    std::string label;
    std::string value;  // right column (a setting's value, an action's keys); may be empty
    std::string note;   // third column (a conflict, the gamepad button); may be empty
    bool warn = false;  // value and note drawn as a warning (a key bound twice)
    bool selectable = true;
    bool choice = false;  // LEFT / RIGHT change the value: drawn with arrows when selected
};

// A row that can be chosen; one whose value LEFT / RIGHT change; one only to read.
inline Row item(std::string label, std::string value = {}, std::string note = {}) {
    Row r;
    r.label = std::move(label);
    r.value = std::move(value);
    r.note = std::move(note);
    return r;
}
inline Row choice(std::string label, std::string value, std::string note = {}) {
    Row r = item(std::move(label), std::move(value), std::move(note));
    r.choice = true;
    return r;
}
inline Row info(std::string label, std::string value = {}) {
    Row r = item(std::move(label), std::move(value));
    r.selectable = false;
    return r;
}

struct Page {
    std::string title;
    std::vector<Row> rows;
    std::vector<std::string> lines;  // text under the rows (a question, a status)
    std::string hint;                // the key hint line at the bottom
    bool big_title = false;          // the game's name on the title menu
    bool columns = false;            // label left, value and note in columns (else centred)
    bool under_band = false;         // over the play HUD: kept below its radar band
};

struct Layout {
    float title_y = 0.62f;
    float rows_top = 0.42f;      // baseline of the first row
    float rows_bottom = -0.62f;  // no row baseline below this
    float row_height = 0.055f;
    float row_step = 0.1f;
};

// The rows shown for `selected`: a window of at most `visible` rows that keeps it in view.
struct Window {
    std::size_t first = 0;
    std::size_t count = 0;
};
Window scroll_window(std::size_t rows, std::size_t selected, std::size_t visible);

// Where a page's rows go (HUD units) at a text scale (the UI scale setting, 1 to 2): drawing
// and the mouse use the same placement, so a row is hit where it is drawn.
struct PlacedRow {
    std::size_t row = 0;       // index into Page::rows
    float y = 0.0f;            // text baseline
    game::hud::Box box;        // where the pointer picks it
    float text_height = 0.0f;  // a centred row too wide for the screen is drawn smaller
};
struct Placement {
    Layout layout;
    Window window;
    std::vector<PlacedRow> rows;  // the rows shown, top down
    float text_height = 0.0f;
    float label_x = 0.0f, value_x = 0.0f, note_x = 0.0f;
    float after_rows_y = 0.0f;  // the baseline after the last row shown
};
Placement place(const scene::VectorFont& font, const Page& page, std::size_t selected,
                double aspect, float scale = 1.0f);
// The selectable row under `at` (HUD units), if any.
std::optional<std::size_t> row_at(const Placement& placement, const Page& page, glm::vec2 at);

// Who draws the footer line: the page's key hints, or the play overlay (a notice, which
// takes the hints' place while it shows).
enum class FooterLine : std::uint8_t { hints, overlay };

// Appends the page's lines (HUD units). `tick` blinks the selection marker; `scale` is the
// player's text size.
void draw(std::vector<scene::HudLine>& out, const scene::VectorFont& font, const Page& page,
          std::size_t selected, double aspect, std::uint64_t tick, float scale = 1.0f,
          FooterLine footer = FooterLine::hints);

}  // namespace bz::app::menu
