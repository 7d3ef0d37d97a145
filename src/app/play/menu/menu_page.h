#pragma once
// One menu screen as plain data (a title, rows, a hint line) and how it is drawn as vector
// text. The rows scroll when there are more than fit; the selected one is marked.
#include <cstdint>
#include <string>
#include <vector>

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

// Appends the page's lines (HUD units). `tick` blinks the selection marker.
void draw(std::vector<scene::HudLine>& out, const scene::VectorFont& font, const Page& page,
          std::size_t selected, double aspect, std::uint64_t tick);

}  // namespace bz::app::menu
