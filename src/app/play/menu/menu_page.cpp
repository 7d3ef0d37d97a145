#include "app/play/menu/menu_page.h"

#include <algorithm>

#include "game/hud/hud_layout.h"

namespace bz::app::menu {

namespace {

namespace hud = game::hud;
using scene::TextAlign;

const glm::vec3 kTitleColor = hud::kRed;
const glm::vec3 kRowColor = hud::kGreen;
const glm::vec3 kSelectedColor = hud::kWhite;
const glm::vec3 kWarnColor = hud::kRed;
const glm::vec3 kHintColor{0.55f, 0.85f, 0.6f};

constexpr float kHintHeight = 0.036f;
constexpr float kLineHeight = 0.04f;

Layout layout_for(const Page& page) {
    Layout l;
    // The title's rows sit low on the dark ground, below the band around the horizon where the
    // attract demo's obstacles, tanks and wreckage stand: from -0.06 down, the first rows were
    // drawn across them (the pyramid through START).
    if (page.big_title) {
        l.rows_top = -0.32f;
        l.row_step = 0.09f;
        l.rows_bottom = -0.78f;
    }
    if (page.under_band) {  // under the reticle too, on the ground
        l.title_y = -0.32f;
        l.rows_top = -0.46f;
        l.row_step = 0.09f;
        l.rows_bottom = -0.8f;
    }
    if (page.columns) {
        l.row_height = 0.042f;
        l.row_step = 0.072f;
    }
    if (!page.lines.empty()) l.rows_bottom = -0.5f;
    return l;
}

}  // namespace

Window scroll_window(std::size_t rows, std::size_t selected, std::size_t visible) {
    Window w;
    w.count = std::min(rows, std::max<std::size_t>(visible, 1));
    if (rows <= w.count) return w;
    // Keep the selection in the middle of the window where the list allows it.
    const std::size_t half = w.count / 2;
    const std::size_t first = selected > half ? selected - half : 0;
    w.first = std::min(first, rows - w.count);
    return w;
}

void draw(std::vector<scene::HudLine>& out, const scene::VectorFont& font, const Page& page,
          std::size_t selected, double aspect, std::uint64_t tick) {
    const float a = static_cast<float>(aspect);
    const Layout l = layout_for(page);
    if (page.big_title) {
        font.draw(out, page.title, {0.0f, 0.5f}, 0.2f, kTitleColor, TextAlign::center, 1.4f);
        font.draw(out, "A VECTOR TANK BATTLE", {0.0f, 0.34f}, 0.05f, kRowColor, TextAlign::center);
    } else {
        font.draw(out, page.title, {0.0f, l.title_y}, 0.09f, kTitleColor, TextAlign::center, 1.2f);
    }

    const auto visible = static_cast<std::size_t>((l.rows_top - l.rows_bottom) / l.row_step) + 1;
    const Window w = scroll_window(page.rows.size(), selected, visible);
    // Columns as wide as their widest entry, the table centred; a table wider than the
    // screen gets smaller text.
    float h = l.row_height;
    float label_w = 0.0f, value_w = 0.0f, note_w = 0.0f;
    for (const Row& r : page.rows) {
        label_w = std::max(label_w, font.width(r.label, h));
        value_w = std::max(value_w, font.width(r.choice ? "< " + r.value + " >" : r.value, h));
        note_w = std::max(note_w, font.width(r.note, h * 0.85f));
    }
    const float gap = 0.12f;
    float table_w = label_w + gap + value_w + (note_w > 0.0f ? gap + note_w : 0.0f);
    const float room = 2.0f * a - 0.3f;
    float shrink = 1.0f;
    if (page.columns && table_w > room) {
        shrink = room / table_w;
        h *= shrink;
        table_w = room;
    }
    const float label_x = -0.5f * table_w;
    const float value_x = label_x + (label_w + gap) * shrink;
    const float note_x = value_x + (value_w + gap) * shrink;
    float y = l.rows_top;
    const bool blink_on = (tick / 20) % 3 != 0;
    for (std::size_t i = w.first; i < w.first + w.count; ++i, y -= l.row_step) {
        const Row& r = page.rows[i];
        const bool sel = i == selected && r.selectable;
        const glm::vec3 color = sel ? kSelectedColor : kRowColor;
        const float glow = sel ? 1.5f : 0.9f;
        if (!page.columns) {
            std::string text = r.label;
            if (!r.value.empty())
                text += "   " + (sel && r.choice ? "< " + r.value + " >" : r.value);
            font.draw(out, text, {0.0f, y}, h, color, TextAlign::center, glow);
            if (sel && blink_on) {
                const float half = font.width(text, h) * 0.5f + 0.08f;
                font.draw(out, ">", {-half, y}, h, kSelectedColor, TextAlign::right, 1.5f);
                font.draw(out, "<", {half, y}, h, kSelectedColor, TextAlign::left, 1.5f);
            }
            continue;
        }
        if (sel && blink_on) {
            font.draw(out, ">", {label_x - 0.05f, y}, h, kSelectedColor, TextAlign::right, 1.5f);
        }
        font.draw(out, r.label, {label_x, y}, h, color, TextAlign::left, glow);
        const glm::vec3 vcolor = r.warn ? kWarnColor : color;
        std::string value = r.value;
        if (sel && r.choice) value = "< " + value + " >";
        font.draw(out, value, {value_x, y}, h, vcolor, TextAlign::left, glow);
        if (!r.note.empty()) {
            font.draw(out, r.note, {note_x, y}, h * 0.85f, r.warn ? kWarnColor : kHintColor,
                      TextAlign::left, glow);
        }
    }
    if (w.first > 0) {
        font.draw(out, "MORE ABOVE", {label_x, l.rows_top + l.row_step * 0.7f}, 0.03f, kHintColor);
    }
    if (w.first + w.count < page.rows.size()) {
        font.draw(out, "MORE BELOW", {label_x, y + l.row_step * 0.3f}, 0.03f, kHintColor);
    }

    float ly = std::min(y, l.rows_bottom) - 0.04f;
    for (const std::string& line : page.lines) {
        font.draw(out, line, {0.0f, ly}, kLineHeight, kWarnColor, TextAlign::center, 1.2f);
        ly -= kLineHeight * 1.6f;
    }

    if (!page.hint.empty()) {
        const hud::Box f = hud::footer_box(a);
        // Long hints shrink to the footer's width rather than run off the screen.
        float hint_h = kHintHeight;
        const float wdt = font.width(page.hint, hint_h);
        if (wdt > f.width()) hint_h *= f.width() / wdt;
        font.draw(out, page.hint, {0.0f, f.min.y + 0.4f * hint_h}, hint_h, kHintColor,
                  TextAlign::center);
    }
}

}  // namespace bz::app::menu
